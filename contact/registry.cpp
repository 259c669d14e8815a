// Registry of tangential models; see registry.hpp.
// To add a model: define its factory in the model's own file, declare it below
// and add one line to the table.
#include "contact/registry.hpp"

#include "core/errors.hpp"

namespace railsim::contact {

// Factories, defined in the models' own files.
std::unique_ptr<TangentialModel> make_linear_theory(const TangentialModelOptions&);
std::unique_ptr<TangentialModel> make_linear_sat(const TangentialModelOptions&);
std::unique_ptr<TangentialModel> make_vermeulen_johnson(const TangentialModelOptions&);
std::unique_ptr<TangentialModel> make_she(const TangentialModelOptions&);
std::unique_ptr<TangentialModel> make_chopaya(const TangentialModelOptions&);
std::unique_ptr<TangentialModel> make_polach(const TangentialModelOptions&);
std::unique_ptr<TangentialModel> make_fastsim(const TangentialModelOptions&);
std::unique_ptr<TangentialModel> make_fastsim_kalker(const TangentialModelOptions&);
std::unique_ptr<TangentialModel> make_fastsim_parabolic(const TangentialModelOptions&);
std::unique_ptr<TangentialModel> make_fastrip(const TangentialModelOptions&);
std::unique_ptr<TangentialModel> make_mim(const TangentialModelOptions&);
std::unique_ptr<TangentialModel> make_mim_table(const TangentialModelOptions&);

const std::vector<TangentialModelEntry>& tangential_models() {
  static const std::vector<TangentialModelEntry> table = {
      // {"name", "one-line description", &factory},
      {"linear", "Kalker's linear theory (no saturation; valid for small creepage)", &make_linear_theory},
      {"linear_sat", "Kalker's linear theory with Coulomb cut-off at mu Fz", &make_linear_sat},
      {"vermeulen_johnson", "Vermeulen-Johnson cubic saturation of Kalker's forces, no spin", &make_vermeulen_johnson},
      {"she", "Shen-Hedrick-Elkins cubic saturation incl. linear spin term", &make_she},
      {"chopaya", "exponential saturation with spin via reduced creepage (reconstruction of CHOPAYA)", &make_chopaya},
      {"polach", "Polach (1999/2005) with spin; kA = kS = 1, constant friction by default", &make_polach},
      {"fastsim", "FASTSIM as CONTACT distributes it: Kalker's flexibilities blended towards one at large "
                  "creepage (Vollebregt & Voltr 2023), elliptic bound, grid N x N (default 20)", &make_fastsim},
      {"fastsim_kalker", "FASTSIM with Kalker's three flexibilities L1, L2, L3 (no blending), elliptic bound, "
                         "grid N x N (default 20)", &make_fastsim_kalker},
      {"fastsim_parabolic", "Kalker's original FASTSIM (1982): three flexibilities, parabolic bound, grid N x N "
                            "(default 20)", &make_fastsim_parabolic},
      {"fastrip", "FaStrip-type: strip theory per strip + FASTSIM-like spin, grid N x N (default 20)", &make_fastrip},
      {"mim", "exact boundary-element steady rolling (Kalker's MIM, FFT), grid N across minor axis (default 40)", &make_mim},
      {"mim_table", "exact MIM results tabulated over a/b and normalised creepages/spin (USETAB-like), cubic "
                    "interpolation; the table is built once (56,277 solves) and cached",
       &make_mim_table, true},
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
