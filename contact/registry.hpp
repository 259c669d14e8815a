// Registry of tangential (creep-force) models, chosen by name from YAML or the
// command line, and of the saturation laws of the model "coefficients".
// Adding a model is adding one file (which defines its factory) and one line in
// registry.cpp.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "contact/tangential_model.hpp"

namespace railsim::contact {

// Extrapolation of a grid model's forces to zero element size.
enum class GridExtrapolation {
  Default,     // the model's own choice (mim: Richardson)
  None,        // the grid's own result (mim: CONTACT's discretisation, equal grid = equal forces)
  Richardson,  // first-order Richardson extrapolation from the grid and the half grid
};

// Options common to all tangential models; a model ignores what it does not use.
struct TangentialModelOptions {
  int grid = 0;             // discretisation (elements across the minor axis); 0 = model default
  double tolerance = 0.0;   // solver tolerance; 0 = model default
  std::string cache_dir;    // table cache folder (tabulated models); empty = default
  std::string saturation = "none";  // model "coefficients": its saturation law (saturation_laws())
  GridExtrapolation extrapolation = GridExtrapolation::Default;  // model "mim"
};

using TangentialFactory = std::unique_ptr<TangentialModel> (*)(const TangentialModelOptions&);

// The options of TangentialModelOptions a model reads (bit flags).
enum TangentialOption : unsigned {
  kOptionGrid = 1u,
  kOptionTolerance = 2u,
  kOptionExtrapolation = 4u,
  kOptionCacheDir = 8u,
  kOptionSaturation = 16u,
};

struct TangentialModelEntry {
  const char* name;
  const char* description;
  TangentialFactory make;
  // Built from a table that is computed once and cached on disk (mim_table:
  // 56,277 MIM solves at grid 28, extrapolated from 28 and 14, the first
  // time: about 3.5 min on two cores, the normal problem solved once per
  // patch shape). Commands that run every model by
  // default (demo, compare-contact, benchmarks) leave these out unless asked.
  bool tabulated = false;
  // What the model does with spin and where that fails, measured against
  // railsim's exact reference set (tests/data/contact/spin_reference); shown
  // by `railsim contact` and in README.md. The exact |Fy| under pure spin
  // peaks near phi = 0.75 1/m on these patches (psi' = G c^3 C23 phi/(mu Fz)
  // about 1) and then falls (0.20 mu Fz at 5 1/m, circular patch).
  const char* spin = "";
  // Takes its creep coefficients from the contact geometry
  // (ContactInput::coefficients; model "coefficients"). On a bare patch it is
  // the linear theory or SHE again, so comparisons of models leave it out.
  bool geometry_coefficients = false;
  // The options it reads (TangentialOption flags); the others it ignores.
  unsigned options = 0;

  // Run by commands and audits that compare every model by default: neither
  // tabulated (the table would be built) nor taking the geometry's coefficients.
  bool compared_by_default() const { return !tabulated && !geometry_coefficients; }
};

// Every registered model, in the order they are listed to users.
const std::vector<TangentialModelEntry>& tangential_models();

// The entry of a model by name, without building it (mim_table's table is not
// loaded or built); unknown names throw InputError listing the known ones.
const TangentialModelEntry& find_tangential_model(std::string_view name);

// Build a model by name; unknown names throw InputError listing the known ones.
std::unique_ptr<TangentialModel> make_tangential_model(std::string_view name,
                                                       const TangentialModelOptions& options = {});

// The options set in `o` (away from their defaults) that `model` does not
// read: commands and bindings that run one model refuse them rather than
// ignore them silently.
std::vector<TangentialOption> unused_model_options(const TangentialModelEntry& model, const TangentialModelOptions& o);
// The option's field name in TangentialModelOptions ("grid", "tolerance",
// "extrapolation", "cache_dir", "saturation").
const char* option_field_name(TangentialOption option);
// "fastsim, fastrip, mim" : the models that read an option (one flag).
std::string models_reading(TangentialOption option);

// "linear, linear_sat, ..." for help texts and error messages.
std::string tangential_model_names();
// GridExtrapolation from its name ("default", "none", "richardson"); InputError
// naming `what` (the option or key) and the allowed names otherwise.
GridExtrapolation grid_extrapolation_from_name(const std::string& name, const char* what);

struct LinearCoefficients;  // contact/linear_theory.hpp

// A saturation law of the model "coefficients": the forces for the linear
// coefficients f_ij and the creepages of `in`, with the law's validity flag.
struct SaturationLawEntry {
  const char* name;
  const char* description;
  ContactForces (*forces)(const LinearCoefficients& f, const ContactInput& in);
  bool coulomb_bounded;  // false for "none" (the unsaturated linear theory)
};

// Every saturation law, in the order they are listed to users.
const std::vector<SaturationLawEntry>& saturation_laws();

// A law by name; unknown names throw InputError listing the known ones.
const SaturationLawEntry& find_saturation_law(std::string_view name);

// "none, she" for help texts and error messages.
std::string saturation_law_names();

}  // namespace railsim::contact
