// Registry of tangential (creep-force) models, chosen by name from YAML or the
// command line. Adding a model is adding one file (which defines its factory)
// and one line in registry.cpp.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "contact/tangential_model.hpp"

namespace railsim::contact {

// Options common to all tangential models; a model ignores what it does not use.
struct TangentialModelOptions {
  int grid = 0;             // discretisation (elements across the minor axis); 0 = model default
  double tolerance = 0.0;   // solver tolerance; 0 = model default
  std::string cache_dir;    // table cache folder (tabulated models); empty = default
};

using TangentialFactory = std::unique_ptr<TangentialModel> (*)(const TangentialModelOptions&);

struct TangentialModelEntry {
  const char* name;
  const char* description;
  TangentialFactory make;
  // Built from a table that is computed once and cached on disk (mim_table:
  // 56,277 MIM solves at grid 28 the first time, about 15 - 30 min on two
  // cores; measured once: 29 min while another solver run shared the machine). Commands that run every model by
  // default (demo, compare-contact, benchmarks) leave these out unless asked.
  bool tabulated = false;
  // What the model does with spin and where that fails, measured against
  // railsim's exact reference set (tests/data/contact/spin_reference); shown
  // by `railsim contact` and in README.md. The exact |Fy| under pure spin
  // peaks near phi = 0.75 1/m on these patches (psi' = G c^3 C23 phi/(mu Fz)
  // about 1) and then falls (0.20 mu Fz at 5 1/m, circular patch).
  const char* spin = "";
};

// Every registered model, in the order they are listed to users.
const std::vector<TangentialModelEntry>& tangential_models();

// Build a model by name; unknown names throw InputError listing the known ones.
std::unique_ptr<TangentialModel> make_tangential_model(std::string_view name,
                                                       const TangentialModelOptions& options = {});

// "linear, linear_sat, ..." for help texts and error messages.
std::string tangential_model_names();

}  // namespace railsim::contact
