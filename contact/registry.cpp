// Registry of tangential models; see registry.hpp.
// To add a model: define its factory in the model's own file, declare it below
// and add one line to the table.
#include "contact/registry.hpp"

#include "core/errors.hpp"

namespace railsim::contact {

// Factories, defined in the models' own files.
// (none yet)

const std::vector<TangentialModelEntry>& tangential_models() {
  static const std::vector<TangentialModelEntry> table = {
      // {"name", "one-line description", &factory},
  };
  return table;
}

std::string tangential_model_names() {
  std::string s;
  for (const auto& e : tangential_models()) s += (s.empty() ? "" : ", ") + std::string(e.name);
  return s;
}

std::unique_ptr<TangentialModel> make_tangential_model(std::string_view name,
                                                       const TangentialModelOptions& options) {
  for (const auto& e : tangential_models())
    if (name == e.name) return e.make(options);
  throw InputError("unknown contact model '" + std::string(name) + "' (known models: " +
                   tangential_model_names() + ")");
}

}  // namespace railsim::contact
