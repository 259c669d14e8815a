// Critical-speed studies of one scenario; see critical_speed_study.hpp.
#include "engine/analysis/critical_speed_study.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "contact/reduction.hpp"
#include "core/errors.hpp"
#include "engine/analysis/bifurcation_chart.hpp"
#include "engine/analysis/scenario_record.hpp"

namespace railsim::engine {

namespace {

using results::Json;


Json number_or_null(double v, double factor = 1.0) { return std::isnan(v) ? Json(nullptr) : Json(v * factor); }

double change_percent(double v, double v0) {
  return std::isnan(v) || std::isnan(v0) ? std::nan("") : 100.0 * (v - v0) / v0;
}

}  // namespace

double as_given(double si, double factor) {
  if (!std::isfinite(si)) return si * factor;
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.12g", si * factor);
  return std::strtod(buf, nullptr);
}

CriticalSpeedMethod parse_critical_speed_method(const std::string& name, const std::string& where) {
  if (name == "bifurcation") return CriticalSpeedMethod::bifurcation;
  if (name == "ramping") return CriticalSpeedMethod::ramping;
  throw InputError(where + ": unknown method '" + name + "' (bifurcation or ramping)");
}

const char* critical_speed_method_name(CriticalSpeedMethod m) {
  return m == CriticalSpeedMethod::ramping ? "ramping" : "bifurcation";
}

CriticalSpeedStudySettings study_settings(const CriticalSpeedSettings& sc) {
  CriticalSpeedStudySettings s;
  s.v_min = sc.v_min;
  s.v_max = sc.v_max;
  s.v_step = sc.v_step;
  s.duration = sc.duration;
  s.large_disturbance = sc.disturbance;
  s.small_disturbance = sc.small_disturbance;
  s.threshold = sc.threshold;
  s.deceleration = sc.deceleration;
  s.continuation = sc.continuation;
  s.ramp_start = sc.ramp_start > 0 ? sc.ramp_start : sc.v_max;
  s.ramp_start_source = sc.ramp_start > 0 ? "the scenario's critical_speed.ramping.v_start_kmh"
                                          : "v_max_kmh of the scenario's critical_speed section (or the default)";
  s.ramp_disturbance = sc.ramp_disturbance > 0 ? sc.ramp_disturbance : sc.disturbance;
  return s;
}

void apply_overrides(CriticalSpeedStudySettings& s, const CriticalSpeedOverrides& g) {
  auto kmh = [](double& to, double given) { if (!std::isnan(given)) to = given / 3.6; };
  auto mm = [](double& to, double given) { if (!std::isnan(given)) to = given * 1e-3; };
  auto si = [](double& to, double given) { if (!std::isnan(given)) to = given; };
  kmh(s.v_min, g.v_min_kmh);
  kmh(s.v_max, g.v_max_kmh);
  kmh(s.v_step, g.v_step_kmh);
  si(s.duration, g.duration);
  mm(s.large_disturbance, g.large_disturbance_mm);
  mm(s.small_disturbance, g.small_disturbance_mm);
  mm(s.threshold, g.threshold_mm);
  si(s.deceleration, g.deceleration);
  if (g.continuation) s.continuation = *g.continuation;
  if (!std::isnan(g.v_max_kmh)) {  // the given v_max is also the ramp's start
    s.ramp_start = s.v_max;
    s.ramp_start_source = g.v_max_name;
  }
  if (!std::isnan(g.large_disturbance_mm)) s.ramp_disturbance = s.large_disturbance;
}

BifurcationOptions bifurcation_options(const CriticalSpeedStudySettings& s) {
  BifurcationOptions o;
  o.v_min = s.v_min;
  o.v_max = s.v_max;
  o.v_step = s.v_step;
  o.duration = s.duration;
  o.large_disturbance = s.large_disturbance;
  o.small_disturbance = s.small_disturbance;
  o.threshold = s.threshold;
  o.up_branch = s.up_branch;
  o.continuation = s.continuation;
  o.threads = s.threads;
  o.use_mpi = true;
  o.stop = s.stop;
  return o;
}

RampingOptions ramping_options(const CriticalSpeedStudySettings& s) {
  RampingOptions o;
  o.v_start = s.ramp_start;
  o.v_end = s.v_min;
  o.deceleration = s.deceleration;
  o.disturbance = s.ramp_disturbance;
  o.threshold = s.threshold;
  o.stop = s.stop;
  return o;
}

double linear_bracket_low(const CriticalSpeedStudySettings& s) { return std::max(1.0, 0.25 * s.v_min); }
double linear_bracket_high(const CriticalSpeedStudySettings& s) { return 1.5 * s.v_max; }

CriticalSpeedOutcome analyse_critical_speed(const Scenario& sc, const CriticalSpeedStudySettings& s,
                                            const std::string& dir) {
  std::filesystem::create_directories(dir);
  CriticalSpeedOutcome out;
  const auto t0 = std::chrono::steady_clock::now();
  out.linear = linear_critical_speed(sc, linear_bracket_low(s), linear_bracket_high(s));
  out.fold_frequency = std::nan("");
  if (s.method == CriticalSpeedMethod::bifurcation) {
    out.bifurcation = bifurcation_sweep(sc, bifurcation_options(s), dir + "/bifurcation.csv");
    out.critical = out.bifurcation.nonlinear_critical_speed;
    out.fold_amplitude = out.bifurcation.fold_amplitude;
    out.fold_frequency = out.bifurcation.fold_frequency;
  } else {
    try {
      out.ramping = ramping(sc, ramping_options(s));
    } catch (const InterruptedError& e) {
      throw InterruptedError(std::string("ramping: ") + e.what() +
                             "; a ramp is one run, nothing of it is kept: start it again");
    }
    out.critical = out.ramping.critical_speed;
    out.fold_amplitude = out.ramping.critical_amplitude;
  }
  out.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

Json critical_speed_summary(const Scenario& sc, const CriticalSpeedStudySettings& st, const CriticalSpeedOutcome& o) {
  Json s = Json::object();
  const bool bifurcation = st.method == CriticalSpeedMethod::bifurcation;
  if (bifurcation) {
    const BifurcationOptions bo = bifurcation_options(st);
    const BifurcationResult& r = o.bifurcation;
    s.set("speed_resolution_kmh", given_kmh(st.v_step));
    s.set("rule", critical_speed_rule(bo));
    Json counts = Json::object();
    int n[kPointStates] = {};
    for (const auto& p : r.points) ++n[static_cast<int>(point_state(p, bo))];
    for (int q = 0; q < kPointStates; ++q) counts.set(point_state_name(static_cast<PointState>(q)), n[q]);
    s.set("points_by_state", counts);
    s.set("limit_cycle_amplitude_at_fold_mm", number_or_null(r.fold_amplitude, 1e3));
    s.set("limit_cycle_frequency_at_fold_hz", number_or_null(r.fold_frequency));
    if (!r.undetermined.empty()) s.set("undetermined", r.undetermined);
  } else {
    const RampingResult& r = o.ramping;
    s.set("deceleration_m_s2", st.deceleration);
    s.set("hunting_at_start", r.hunting_at_start);
    s.set("hunting_at_end", r.hunting_at_end);
    s.set("start_speed_kmh", r.start_speed * 3.6);
    s.set("start_speed_source", st.ramp_start_source);
    s.set("critical_speed_read_at_time_s", number_or_null(r.critical_time));
    s.set("envelope_at_critical_speed_mm", number_or_null(r.critical_amplitude, 1e3));
    if (!r.derailment.empty()) s.set("derailment", r.derailment);
    if (!r.range_stop.empty()) s.set("left_model_range", r.range_stop);
  }
  s.set("scenario", sc.name);
  s.set("vehicle", sc.model.vehicle_name);
  s.set("method", critical_speed_method_name(st.method));
  s.set("geometry", sc.geometry_description);
  s.set("equivalent_conicity_3mm", sc.equivalent_conicity_3mm);
  s.set("contact_model", sc.model.coupling.options().tangential);
  s.set("contact_description", sc.model.coupling.describe());
  s.set("reduction", contact::reduction_label(sc.reduction));
  s.set("mu", sc.model.coupling.options().material.mu);
  s.set("wheelset_model", wheelset_model_name(sc.model.wheelset_model));
  s.set("saturation_law", saturation_law(sc));
  s.set("record", scenario_record(sc));
  s.set("critical_speed_kmh", number_or_null(given_kmh(o.critical)));  // a speed of the sweep
  s.set("linear_critical_speed_kmh", number_or_null(o.linear, 3.6));
  s.set("speed_range_kmh", Json::array().push(given_kmh(st.v_min)).push(given_kmh(st.v_max)));
  Json set = Json::object();
  if (bifurcation) {
    set.set("v_step_kmh", given_kmh(st.v_step));
    set.set("duration_s", st.duration);
    set.set("duration_per_point_s", st.duration);
    set.set("large_disturbance_mm", given_mm(st.large_disturbance));
    set.set("small_disturbance_mm", given_mm(st.small_disturbance));
    set.set("up_branch", st.up_branch);
    set.set("continuation", st.continuation);
  } else {
    set.set("start_speed_kmh", given_kmh(st.ramp_start));
    set.set("disturbance_mm", given_mm(st.ramp_disturbance));
    set.set("deceleration_m_s2", st.deceleration);
  }
  set.set("threshold_mm", given_mm(st.threshold));
  s.set("settings", set);
  s.set("wall_time_s", o.wall);
  return s;
}

CriticalSpeedWithBaseline critical_speed_with_baseline(const Scenario& base, const std::string& tangential_model,
                                                       const CriticalSpeedStudySettings& settings, bool reduction_given,
                                                       bool baseline, const std::string& out_dir) {
  CriticalSpeedWithBaseline r;
  r.scenario = with_contact(base, tangential_model, nullptr);
  r.outcome = analyse_critical_speed(r.scenario, settings, out_dir);
  r.summary = critical_speed_summary(r.scenario, settings, r.outcome);
  const contact::ReductionFactors& k = base.reduction.k;
  r.with_baseline = reduction_given && baseline && !(k.k11 == 1.0 && k.k22 == 1.0 && k.k23 == 1.0);
  r.change_percent = r.linear_change_percent = std::nan("");
  if (!r.with_baseline) return r;
  const contact::ReductionFactors none;
  r.unreduced_scenario = with_contact(base, tangential_model, &none);
  r.unreduced = analyse_critical_speed(r.unreduced_scenario, settings, out_dir + "/unreduced");
  r.change_percent = change_percent(r.outcome.critical, r.unreduced.critical);
  r.linear_change_percent = change_percent(r.outcome.linear, r.unreduced.linear);
  Json b = Json::object();
  b.set("critical_speed_kmh", number_or_null(given_kmh(r.unreduced.critical)));
  b.set("linear_critical_speed_kmh", number_or_null(r.unreduced.linear, 3.6));
  if (!std::isnan(r.change_percent)) b.set("critical_speed_change_percent", r.change_percent);
  if (!std::isnan(r.linear_change_percent)) b.set("linear_critical_speed_change_percent", r.linear_change_percent);
  r.summary.set("unreduced", b);
  return r;
}

std::vector<ModelCriticalSpeed> critical_speed_per_model(
    const Scenario& base, const std::vector<std::string>& models, const CriticalSpeedStudySettings& settings,
    const std::string& out_dir, const std::function<void(const ModelCriticalSpeed&)>& finished) {
  std::vector<ModelCriticalSpeed> out;
  for (std::size_t i = 0; i < models.size(); ++i) {
    ModelCriticalSpeed m;
    m.model = models[i];
    m.scenario = with_contact(base, models[i], nullptr);
    spdlog::info("compare-models: {} ({}/{})", models[i], i + 1, models.size());
    m.outcome = analyse_critical_speed(m.scenario, settings, out_dir + "/" + models[i]);
    m.summary = critical_speed_summary(m.scenario, settings, m.outcome);
    if (finished) finished(m);
    out.push_back(std::move(m));
  }
  return out;
}

}  // namespace railsim::engine
