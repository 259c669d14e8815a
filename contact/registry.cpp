// Registry of tangential models; see registry.hpp.
// To add a model: define its factory in the model's own file, declare it below
// and add one line to the table.
#include "contact/registry.hpp"

#include "contact/linear_theory.hpp"
#include "contact/she.hpp"
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
std::unique_ptr<TangentialModel> make_coefficients(const TangentialModelOptions&);

const std::vector<TangentialModelEntry>& tangential_models() {
  static const std::vector<TangentialModelEntry> table = {
      // {"name", "one-line description", &factory, tabulated, "spin", geometry_coefficients, options read},
      {"linear", "Kalker's linear theory (no saturation; valid for small creepage)", &make_linear_theory, false,
       "linear C23 term only, no saturation: valid while |F| < 0.3 mu Fz (flagged beyond)"},
      {"linear_sat", "Kalker's linear theory with Coulomb cut-off at mu Fz", &make_linear_sat, false,
       "linear C23 term cut at mu Fz: |Fy| rises to mu Fz and stays, while the exact |Fy| falls past "
       "phi ~ 0.75 1/m (61 - 94 % of mu Fz wrong at 5 1/m, a/b 5 - 0.2); flagged when psi' > 0.3"},
      {"vermeulen_johnson", "Vermeulen-Johnson cubic saturation of Kalker's forces, no spin", &make_vermeulen_johnson,
       false, "spin ignored (Fy = 0 under pure spin, up to 89 % of mu Fz wrong); flagged when psi' > 0.05"},
      {"she", "Shen-Hedrick-Elkins cubic saturation incl. linear spin term", &make_she, false,
       "linear C23 term saturated with the creepage: |Fy| rises to mu Fz with spin, no fall past the peak "
       "(61 - 94 % of mu Fz wrong at 5 1/m, a/b 5 - 0.2); flagged when psi' > 0.3"},
      {"chopaya", "exponential saturation with spin via reduced creepage (reconstruction of CHOPAYA)", &make_chopaya,
       false,
       "spin through the reduced lateral creepage, saturated: |Fy| rises to mu Fz, no fall past the peak "
       "(61 - 94 % of mu Fz wrong at 5 1/m, a/b 5 - 0.2); flagged when psi' > 0.3"},
      {"polach", "Polach (1999/2005) with spin; kA = kS = 1, constant friction by default", &make_polach, false,
       "Polach's own spin term (K_M, 1999): |Fy| peaks and falls as the exact theory, but too fast at large spin "
       "(24 % of mu Fz low at 5 1/m, a/b 5) and superposed on the creep force (formula up to 1.46 mu Fz, limited "
       "to mu Fz and flagged)"},
      {"fastsim", "FASTSIM as CONTACT distributes it: Kalker's flexibilities blended towards one at large "
                  "creepage (Vollebregt & Voltr 2023), elliptic bound, grid N x N (default 20)", &make_fastsim, false,
       "Winkler spin flexibility L3: peak and fall reproduced, 9 % of mu Fz low at the peak on long patches "
       "(a/b 5); lateral creepage against spin on wide/long patches up to 21 %", false, kOptionGrid},
      {"fastsim_kalker", "FASTSIM with Kalker's three flexibilities L1, L2, L3 (no blending), elliptic bound, "
                         "grid N x N (default 20)", &make_fastsim_kalker, false,
       "as fastsim; with creepage + spin the saturated traction is skewed by L1 != L2 != L3: up to 24 % of mu Fz",
       false, kOptionGrid},
      {"fastsim_parabolic", "Kalker's original FASTSIM (1982): three flexibilities, parabolic bound, grid N x N "
                            "(default 20)", &make_fastsim_parabolic, false,
       "as fastsim_kalker with the parabolic bound: up to 22 % of mu Fz", false, kOptionGrid},
      {"fastrip", "FaStrip-type: strip theory per strip + FASTSIM-like spin, grid N x N (default 20)", &make_fastrip,
       false,
       "strip theory for creepage, Winkler spin, sliding strips follow the rigid slip: every sign combination "
       "within 10.4 % of mu Fz (pure spin: 9 % low at the peak, a/b 5)", false, kOptionGrid},
      {"mim", "exact boundary-element steady rolling (Kalker's MIM, FFT), grid N across minor axis (default 40)",
       &make_mim, false, "exact (the reference); spin discretised as CONTACT's, forces Richardson-extrapolated from grid N and N/2 "
       "(grid 60 within 0.23 % of mu Fz of grid 120; without extrapolation 0.49 %)", false,
       kOptionGrid | kOptionTolerance | kOptionExtrapolation},
      {"mim_table", "exact MIM results tabulated over a/b and normalised creepages/spin (USETAB-like), cubic "
                    "interpolation; the table is built once (56,277 solves) and cached",
       &make_mim_table, true, "exact values interpolated over (xi', eta' + psi'/3, psi'): within 0.6 % of mu Fz",
       false, kOptionGrid | kOptionTolerance | kOptionCacheDir},
      {"coefficients", "Kalker's linear theory on the contact geometry's creep coefficients (RSGEO table C_ij or "
                       "prescribed f_ij), saturated by the law `saturation` (none | she)", &make_coefficients, false,
       "as linear (saturation none) or she (saturation she) with the geometry's C23; flagged alike", true,
       kOptionSaturation},
  };
  return table;
}

const std::vector<SaturationLawEntry>& saturation_laws() {
  static const std::vector<SaturationLawEntry> table = {
      // {"name", "description", &forces, coulomb_bounded},
      {"none", "none (linear creep forces, coefficients mode)", &linear_theory_forces, false},
      {"she", "Shen-Hedrick-Elkins cubic on the resultant (coefficients mode)", &she_forces, true},
  };
  return table;
}

namespace {

// "a, b, c" of a table's names.
template <class Entry>
std::string names_of(const std::vector<Entry>& table) {
  std::string s;
  for (const auto& e : table) s += (s.empty() ? "" : ", ") + std::string(e.name);
  return s;
}

// The entry called `name`; InputError "unknown <what> 'name' (known <plural>: ...)" otherwise.
template <class Entry>
const Entry& find_in(const std::vector<Entry>& table, std::string_view name, const char* what, const char* plural) {
  for (const auto& e : table)
    if (name == e.name) return e;
  throw InputError("unknown " + std::string(what) + " '" + std::string(name) + "' (known " + plural + ": " +
                   names_of(table) + ")");
}

}  // namespace

std::string saturation_law_names() { return names_of(saturation_laws()); }

const SaturationLawEntry& find_saturation_law(std::string_view name) {
  return find_in(saturation_laws(), name, "saturation law", "laws");
}

std::string tangential_model_names() { return names_of(tangential_models()); }

std::vector<TangentialOption> unused_model_options(const TangentialModelEntry& model, const TangentialModelOptions& o) {
  const TangentialModelOptions d;
  const std::pair<TangentialOption, bool> given[] = {
      {kOptionGrid, o.grid != d.grid},
      {kOptionTolerance, o.tolerance != d.tolerance},
      {kOptionExtrapolation, o.extrapolation != d.extrapolation},
      {kOptionCacheDir, o.cache_dir != d.cache_dir},
      {kOptionSaturation, o.saturation != d.saturation},
  };
  std::vector<TangentialOption> unused;
  for (const auto& [flag, set] : given)
    if (set && !(model.options & flag)) unused.push_back(flag);
  return unused;
}

const char* option_field_name(TangentialOption option) {
  switch (option) {
    case kOptionGrid: return "grid";
    case kOptionTolerance: return "tolerance";
    case kOptionExtrapolation: return "extrapolation";
    case kOptionCacheDir: return "cache_dir";
    case kOptionSaturation: return "saturation";
  }
  return "?";
}

std::string models_reading(TangentialOption option) {
  std::string s;
  for (const auto& e : tangential_models())
    if (e.options & option) s += (s.empty() ? "" : ", ") + std::string(e.name);
  return s.empty() ? "none" : s;
}

GridExtrapolation grid_extrapolation_from_name(const std::string& name, const char* what) {
  if (name == "default") return GridExtrapolation::Default;
  if (name == "none") return GridExtrapolation::None;
  if (name == "richardson") return GridExtrapolation::Richardson;
  throw InputError(std::string(what) + ": extrapolation must be 'default', 'none' or 'richardson' (got '" + name +
                   "')");
}

const TangentialModelEntry& find_tangential_model(std::string_view name) {
  return find_in(tangential_models(), name, "contact model", "models");
}

std::unique_ptr<TangentialModel> make_tangential_model(std::string_view name,
                                                       const TangentialModelOptions& options) {
  return find_tangential_model(name).make(options);
}

}  // namespace railsim::contact
