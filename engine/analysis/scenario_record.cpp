// Scenario record for summaries; see scenario_record.hpp.
#include "engine/analysis/scenario_record.hpp"

#include <cmath>

#include "contact/registry.hpp"
#include "engine/analysis/equivalent_conicity.hpp"

namespace railsim::engine {

namespace {

results::Json number_or_null(double v) { return std::isfinite(v) ? results::Json(v) : results::Json(nullptr); }

}  // namespace

std::string saturation_law(const Scenario& sc) {
  const CouplingOptions& o = sc.model.coupling.options();
  const contact::TangentialModelEntry& e = contact::find_tangential_model(o.tangential);
  if (e.geometry_coefficients) return contact::find_saturation_law(o.saturation).description;
  return std::string(e.name) + ": " + e.description;
}

results::Json reduction_record(const Scenario& sc) {
  using results::Json;
  const contact::ReductionSpec& r = sc.reduction;
  const contact::ReductionFactors& k = sc.model.coupling.options().reduction;
  Json j = Json::object();
  j.set("given", r.form == contact::ReductionForm::unset ? Json(nullptr) : Json(r.text));
  j.set("form", contact::reduction_form_name(r.form));
  j.set("label", contact::reduction_label(r));
  j.set("k11", k.k11);
  j.set("k22", k.k22);
  j.set("k23", k.k23);
  if (r.form == contact::ReductionForm::layer) {
    Json l = Json::object();
    l.set("h_m", r.layer.h);
    l.set("G3_Pa", r.layer.G3);
    l.set("tau_c_Pa", r.layer.tau_limit > 0 ? Json(r.layer.tau_limit) : Json(nullptr));
    l.set("method", "exact solver (MIM) with the interfacial layer: initial creep slopes with / without it");
    l.set("grid_elements_minor_axis", sc.layer.grid);
    Json p = Json::object();
    p.set("a_m", sc.layer.patch.a);
    p.set("b_m", sc.layer.patch.b);
    p.set("A_1_m", sc.layer.patch.A);
    p.set("B_1_m", sc.layer.patch.B);
    p.set("Fz_N", sc.layer.patch.Fz);
    p.set("where", "nominal patch: centred wheelset, static load of the first wheel");
    l.set("patch", p);
    l.set("mu_limit", sc.layer.mu_limit > 0 ? Json(sc.layer.mu_limit) : Json(nullptr));
    l.set("from_cache", sc.layer.from_cache);
    l.set("cache_file", sc.layer.cache_file);
    j.set("layer", l);
  }
  return j;
}

results::Json scenario_record(const Scenario& sc) {
  using results::Json;
  const Model& m = sc.model;
  const CouplingOptions& o = m.coupling.options();
  Json j = Json::object();
  j.set("scenario", sc.name);
  j.set("scenario_file", sc.file);
  j.set("vehicle", m.vehicle_name);
  j.set("wheelset_model", wheelset_model_name(m.wheelset_model));
  j.set("geometry", sc.geometry_description);
  Json con = Json::array();
  if (!m.wheelsets.empty() && m.wheelsets.front().geometry)
    for (const auto& p : conicity_curve(*m.wheelsets.front().geometry)) {
      Json c = Json::object();
      c.set("amplitude_mm", p.amplitude * 1e3);
      c.set("conicity", number_or_null(p.conicity));
      con.push(c);
    }
  j.set("equivalent_conicity", con);
  j.set("contact_model", o.tangential);
  j.set("contact_description", m.coupling.describe());
  j.set("saturation_law", saturation_law(sc));
  Json mat = Json::object();
  mat.set("mu", o.material.mu);
  mat.set("mu_scenario", sc.creep_material.mu);
  mat.set("E_Pa", sc.creep_material.E);
  mat.set("nu", sc.creep_material.nu);
  mat.set("G_Pa", sc.creep_material.shear_modulus());
  j.set("material", mat);
  j.set("reduction", reduction_record(sc));
  return j;
}

}  // namespace railsim::engine
