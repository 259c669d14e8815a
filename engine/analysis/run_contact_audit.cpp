// Contact audit of a vehicle run; see run_contact_audit.hpp.
#include "engine/analysis/run_contact_audit.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "contact/hertz.hpp"
#include "contact/registry.hpp"
#include "core/errors.hpp"
#include "config/yaml_input.hpp"
#include "results/csv_writer.hpp"

namespace railsim::engine {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kDeg = 180.0 / 3.14159265358979323846;

double reference_median_us(const contact::ContactAuditResult& r) {
  std::vector<double> c;
  for (std::size_t s = 0; s < r.audited.size(); ++s)
    if (r.audited[s]) c.push_back(r.reference_cost_ns[s]);
  if (c.empty()) return kNaN;
  std::sort(c.begin(), c.end());
  const std::size_t h = c.size() / 2;
  return 1e-3 * (c.size() % 2 ? c[h] : 0.5 * (c[h - 1] + c[h]));
}
}  // namespace

RunContactAudit run_contact_audit(const ContactStateRecorder& rec, const CouplingOptions& run,
                                  const RunContactAuditOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  if (!(o.tolerance > 0.0 && o.tolerance <= 1.0))
    throw InputError("contact audit: tolerance must lie in (0, 1] of mu N");
  const ContactStateSample sample = sample_contact_states(rec, o.samples);
  RunContactAudit a;
  a.recorded_states = rec.states().size();
  a.recorded_rows = rec.rows();
  a.why = sample.why;
  std::vector<contact::ContactInput> inputs;
  std::vector<contact::ContactForces> run_forces;
  for (const std::size_t i : sample.index) {
    a.states.push_back(rec.states()[i]);
    auto& in = a.states.back().input;
    if (!(in.patch.A > 0.0 && in.patch.B > 0.0) && in.patch.a > 0.0 && in.patch.b > 0.0 && in.patch.Fz > 0.0) {
      // Semi-axes without curvatures (a contact table's patch): the Hertzian curvatures that give them.
      const contact::HertzPatch h = contact::hertz_from_semi_axes(in.patch.a, in.patch.b, in.patch.Fz, in.material);
      in.patch.A = h.A;
      in.patch.B = h.B;
      ++a.completed_patches;
    }
    inputs.push_back(in);
    run_forces.push_back(a.states.back().forces);
  }
  contact::ContactAuditOptions co;
  co.mim_grid = o.mim_grid;
  co.mim_tolerance = o.mim_tolerance;
  co.tolerance = o.tolerance;
  co.threads = o.threads;
  co.cache_dir = o.cache_dir;
  co.stop = o.stop;
  co.saturation = run.saturation;
  const std::string run_model = contact::find_tangential_model(run.tangential).name;
  for (const auto& e : contact::tangential_models())
    if (e.compared_by_default() || run_model == e.name) co.models.emplace_back(e.name);
  a.result = contact::audit_contacts(inputs, co);
  if (std::none_of(a.result.audited.begin(), a.result.audited.end(), [](bool b) { return b; }))
    throw InputError("contact audit: none of the " + std::to_string(inputs.size()) +
                     " sampled contact states has a patch (semi-axes a, b > 0) to solve: the run's contact gives "
                     "creep coefficients without a patch shape (conical wheels without patch_a, patch_b)");
  a.run_model = run_model;
  const auto m = static_cast<std::size_t>(a.result.find(run_model));
  a.reproduction = 0.0;
  for (std::size_t s = 0; s < inputs.size(); ++s) {
    if (!a.result.audited[s]) continue;
    const auto& f = a.result.forces[m][s];
    a.reproduction = std::max(a.reproduction, std::hypot(f.Fx - run_forces[s].Fx, f.Fy - run_forces[s].Fy) /
                                                  (inputs[s].material.mu * inputs[s].patch.Fz));
  }
  a.verdict = contact::audit_verdict(a.result, a.run_model);
  a.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return a;
}

results::Json contact_audit_json(const RunContactAudit& a, const Model& /*model*/) {
  using results::Json;
  const auto& r = a.result;
  Json j = Json::object();
  j.set("samples", static_cast<long>(a.states.size()));
  j.set("recorded_states", static_cast<long>(a.recorded_states));
  j.set("recorded_output_rows", static_cast<long>(a.recorded_rows));
  j.set("sampling", "the run's loaded patches at every output (the evaluation the channels come from); chosen: the "
                    "extremes (largest normal load, |phi|, |(xi, eta)|, contact angle, |F|/(mu N) of the run's model, "
                    "largest and smallest a/b, largest |xi|, |eta|), the rest evenly in time walking through the wheels");
  long audited = 0;
  for (const bool b : r.audited) audited += b ? 1 : 0;
  j.set("audited_states", audited);
  j.set("patches_completed", static_cast<long>(a.completed_patches));
  if (a.completed_patches > 0)
    j.set("patches_completed_note", "states whose patch had semi-axes but no curvatures (a contact table's): the "
                                    "Hertzian curvatures A, B that give these semi-axes at this load were added");
  j.set("reference", "MIM (Kalker), grid " + std::to_string(r.mim_grid) + " elements across the minor axis");
  j.set("error_measure", "|(Fx, Fy) - (Fx, Fy)_MIM| / (mu Fz), per cent");
  j.set("tolerance_pct", 100.0 * r.tolerance);
  j.set("run_model", a.run_model);
  j.set("run_model_reproduction_pct", 100.0 * a.reproduction);
  const auto& v = a.verdict;
  j.set("run_model_meets_tolerance", v.run_meets);
  j.set("cheapest_meeting_tolerance", v.cheapest_meeting.empty() ? Json() : Json(v.cheapest_meeting));
  Json ch = Json::array();
  for (const auto& n : v.cheaper_meeting) ch.push(n);
  j.set("cheaper_than_run_model_meeting_tolerance", ch);
  j.set("most_accurate", v.most_accurate);
  Json ladder = Json::array();
  for (const double pct : {1.0, 2.0, 5.0, 10.0, 20.0}) {
    const std::string m = contact::cheapest_within(r, pct / 100.0);
    Json e = Json::object();
    e.set("tolerance_pct", pct);
    e.set("cheapest", m.empty() ? Json() : Json(m));
    ladder.push(e);
  }
  j.set("cheapest_by_tolerance", ladder);
  Json ok = Json::array();
  for (const auto& n : r.meeting_tolerance()) ok.push(n);
  j.set("meeting_tolerance_cheapest_first", ok);
  j.set("reference_median_cost_us", reference_median_us(r));
  Json models = Json::array();
  for (const auto& m : r.models) {
    Json e = Json::object();
    e.set("model", m.model);
    e.set("max_error_pct", 100.0 * m.max_error);
    e.set("p95_error_pct", 100.0 * m.p95_error);
    e.set("mean_error_pct", 100.0 * m.mean_error);
    e.set("worst_state", static_cast<long>(m.worst_state));
    e.set("worst_state_time", a.states[m.worst_state].t);
    e.set("mean_cost_us", m.mean_cost_ns * 1e-3);
    e.set("median_cost_us", m.median_cost_ns * 1e-3);
    e.set("flagged_invalid", m.flagged_invalid);
    e.set("failed", m.failed);
    e.set("meets_tolerance", m.meets_tolerance);
    models.push(e);
  }
  j.set("models", models);
  j.set("costs", "steady clock, per state the mean of repeated calls until 20 us (at most 64; the reference one call), "
                 "on the audit's worker threads; models are ranked by the median over the states: indicative only "
                 "(the benchmarks in bench/ measure costs)");
  j.set("wall_time", a.wall_seconds);
  return j;
}

results::Chart contact_audit_chart(const RunContactAudit& a, const std::string& title_tail) {
  constexpr double kFloorPct = 1e-2;  // errors below 0.01 % drawn at 0.01 % (log axis)
  const auto& r = a.result;
  results::Chart c;
  c.title = "contact audit, " + std::to_string(a.states.size()) + " states of the run: " + title_tail;
  c.xlabel = "cost per call, median over the states [us]";
  c.ylabel = "error vs MIM grid " + std::to_string(r.mim_grid) + " [% of mu Fz]";
  c.logx = c.logy = true;
  c.legend = "outside";
  results::ChartSeries mx{"max over the states", {}, {}, "markers", "tab:blue"};
  results::ChartSeries p95{"95th percentile", {}, {}, results::custom_style("o", "", true, 10), "tab:green"};
  results::ChartSeries run{"the run's model (" + a.run_model + ")", {}, {}, results::custom_style("*", "", false, 16),
                           "tab:red"};
  for (const auto& m : r.models) {
    const double y = std::max(100.0 * m.max_error, kFloorPct);
    if (!std::isfinite(m.median_cost_ns)) {  // forces given by the run: no cost measured
      c.lines.push_back({y, m.model + ": max " + config::format_number(std::round(y * 100) / 100) + " %",
                         "tab:red", false});
      continue;
    }
    const double x = m.median_cost_ns * 1e-3;
    mx.x.push_back(x);
    mx.y.push_back(std::isfinite(y) ? y : 1e3);
    p95.x.push_back(x);
    p95.y.push_back(std::max(100.0 * m.p95_error, kFloorPct));
    if (m.model == a.run_model) run.x.push_back(x), run.y.push_back(y);
    c.annotations.push_back({m.model == "mim" ? "mim (its default grid)" : m.model, {x, y}});
  }
  c.series = {mx, p95};
  if (!run.x.empty()) c.series.push_back(run);
  c.lines.push_back({100.0 * r.tolerance, "tolerance " + config::format_number(100.0 * r.tolerance) + " %", "k",
                     false});
  const double ref_us = reference_median_us(r);
  if (std::isfinite(ref_us))
    c.lines.push_back({ref_us, "MIM reference (grid " + std::to_string(r.mim_grid) + ")", "0.5", true});
  const auto& v = a.verdict;
  c.note = "run's model " + a.run_model + (v.run_meets ? " meets" : " misses") + " the tolerance; cheapest meeting it: " +
           (v.cheapest_meeting.empty() ? std::string("none") : v.cheapest_meeting);
  return c;
}

void write_contact_audit_csv(const RunContactAudit& a, const Model& model, const std::string& path) {
  const auto& r = a.result;
  results::CsvWriter w(path,
                       {"state", "why", "t", "distance", "wheelset", "side", "patch", "contact_angle_deg", "a", "b",
                        "A", "B", "p0", "Fz", "xi", "eta", "phi", "mu", "k11", "k22", "k23", "V", "model", "Fx", "Fy",
                        "Mz", "valid", "Fx_mim", "Fy_mim", "Mz_mim", "error_pct_mu_Fz", "time_us"},
                       false, 1000);
  for (std::size_t s = 0; s < a.states.size(); ++s) {
    if (!r.audited[s]) continue;
    const RunContactState& st = a.states[s];
    const auto& in = st.input;
    for (std::size_t m = 0; m < r.models.size(); ++m) {
      const auto& f = r.forces[m][s];
      w.cell(static_cast<long>(s)).cell(a.why[s]).cell(st.t).cell(st.distance);
      w.cell(model.wheelsets[static_cast<std::size_t>(st.wheelset)].name).cell(st.side == 0 ? "left" : "right");
      w.cell(st.point).cell(st.contact_angle * kDeg);
      w.cell(in.patch.a).cell(in.patch.b).cell(in.patch.A).cell(in.patch.B).cell(in.patch.p0).cell(in.patch.Fz);
      w.cell(in.creep.xi).cell(in.creep.eta).cell(in.creep.phi).cell(in.material.mu);
      w.cell(in.reduction.k11).cell(in.reduction.k22).cell(in.reduction.k23).cell(in.rolling_speed);
      w.cell(r.models[m].model).cell(f.Fx).cell(f.Fy).cell(f.Mz).cell(f.valid);
      w.cell(r.reference[s].Fx).cell(r.reference[s].Fy).cell(r.reference[s].Mz);
      w.cell(100.0 * r.errors[m][s]).cell(r.cost_ns[m][s] * 1e-3);
      w.end_row();
    }
  }
  w.close();
}

}  // namespace railsim::engine
