// One run of a scenario with its report; see scenario_run.hpp. (Moved from
// cli/cmd_run.cpp so that the program and the Python module share it.)
#include "engine/analysis/scenario_run.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>

#include "core/errors.hpp"
#include "engine/analysis/curving.hpp"
#include "engine/analysis/run_history.hpp"
#include "engine/analysis/run_safety.hpp"
#include "results/chart.hpp"
#include "results/csv_writer.hpp"
#include "results/sliding_window.hpp"

namespace railsim::engine {

namespace {
constexpr double kDeg = 180.0 / 3.14159265358979323846;

results::Json peak_json(double value, double distance, double time) {
  results::Json j = results::Json::object();
  j.set("max", value);
  j.set("distance", distance);
  j.set("time", time);
  return j;
}

results::Json windowed_json(const WindowedMaximum& w, double time) {
  results::Json j = peak_json(w.max_abs, w.at_distance, time);
  j.set("percentile_99_85", w.percentile);
  j.set("limit", w.limit);
  j.set("pass", w.pass);
  return j;
}

results::Json safety_json(const RunSafety& rs, const FlangeAngle& fa) {
  results::Json j = results::Json::object();
  j.set("pass", rs.pass);
  j.set("flange_angle_deg", rs.flange_angle * kDeg);
  j.set("flange_angle_source", fa.source);
  j.set("flange_angle_fallback", fa.fallback);
  j.set("mu", rs.mu);
  j.set("nadal_limit", rs.nadal);
  results::Json lim = results::Json::object();
  lim.set("yq_2m", rs.limits.yq_limit);
  lim.set("wheel_unloading", rs.limits.wheel_unloading);
  lim.set("prudhomme_alpha", rs.limits.prudhomme_alpha);
  lim.set("window_m", rs.limits.window);
  lim.set("step_m", rs.limits.step);
  lim.set("percentile", rs.limits.percentile);
  j.set("limits", lim);
  j.set("en14363_evaluated", rs.en14363_evaluated);
  j.set("distances", "track distance of the wheelset [m]; forces in N");
  results::Json notes = results::Json::array();
  for (const auto& n : rs.notes) notes.push(n);
  j.set("notes", notes);
  results::Json arr = results::Json::array();
  for (const auto& w : rs.wheelsets) {
    results::Json a = results::Json::object();
    a.set("name", w.name);
    a.set("pass", w.pass);
    a.set("static_wheel_load", w.static_wheel_load);
    results::Json wheels = results::Json::object();
    for (int side = 0; side < 2; ++side) {
      const auto& ws = w.wheel[side];
      results::Json wj = results::Json::object();
      results::Json inst = peak_json(ws.max_abs_yq.value, ws.max_abs_yq.distance, ws.max_abs_yq.time);
      inst.set("nadal_limit", rs.nadal);
      inst.set("pass", ws.nadal_pass);
      wj.set("yq_instantaneous", inst);
      if (rs.en14363_evaluated)
        wj.set("yq_2m", windowed_json(side == 0 ? w.en14363.yq_left : w.en14363.yq_right, ws.yq_2m_time));
      wheels.set(side == 0 ? "left" : "right", wj);
    }
    a.set("wheels", wheels);
    if (rs.en14363_evaluated) {
      a.set("sum_y_2m", windowed_json(w.en14363.sum_y, w.sum_y_time));
      results::Json u = peak_json(w.en14363.max_unloading, w.en14363.unloading_at, w.unloading_time);
      u.set("limit", rs.limits.wheel_unloading);
      u.set("pass", w.en14363.unloading_pass);
      a.set("wheel_unloading", u);
      a.set("en14363_pass", w.en14363.pass);
    }
    arr.push(a);
  }
  j.set("wheelsets", arr);
  return j;
}

results::Json stat_json(const Stat& s, double scale = 1.0) {
  results::Json j = results::Json::object();
  j.set("mean", s.mean * scale);
  j.set("min", s.min * scale);
  j.set("max", s.max * scale);
  return j;
}

results::Json curving_json(const std::vector<CurveResult>& curves, const CurvingOptions& opt) {
  results::Json j = results::Json::object();
  j.set("settle_distance_m", opt.settle_distance);
  j.set("angle_of_attack_sign", "wheelset yaw relative to the track, > 0 heading toward the outer rail");
  j.set("lateral_shift_sign", "relative to the track, > 0 toward the outer rail");
  j.set("tgamma_definition", "-(Fx xi + Fy eta + Mz spin) [N], spin term included");
  results::Json arr = results::Json::array();
  for (const auto& c : curves) {
    results::Json cj = results::Json::object();
    cj.set("radius_m", 1.0 / std::fabs(c.curvature));
    cj.set("direction", c.curvature > 0 ? "left" : "right");
    cj.set("cant_angle_rad", c.cant);
    cj.set("start_distance", c.start);
    cj.set("end_distance", c.end);
    cj.set("samples", static_cast<long>(c.samples));
    cj.set("mean_speed", c.mean_speed);
    cj.set("unbalanced_lateral_acceleration", c.unbalanced_acceleration);
    cj.set("sum_Y_mean", c.sum_Y);
    cj.set("sum_Y_expected_M_a_nc", c.expected_sum_Y);
    results::Json ws = results::Json::array();
    for (const auto& w : c.wheelsets) {
      results::Json wj = results::Json::object();
      wj.set("name", w.name);
      wj.set("angle_of_attack_mrad", stat_json(w.angle_of_attack, 1e3));
      wj.set("lateral_shift_mm", stat_json(w.lateral_shift, 1e3));
      results::Json wheels = results::Json::object();
      for (int s = 0; s < 2; ++s) {
        const auto& wc = w.wheel[s];
        results::Json x = results::Json::object();
        x.set("outer", wc.outer);
        x.set("YQ", stat_json(wc.yq));
        x.set("Y", stat_json(wc.Y));
        x.set("Q", stat_json(wc.Q));
        x.set("Tgamma", stat_json(wc.Tgamma));
        wheels.set(s == 0 ? "left" : "right", x);
      }
      wj.set("wheels", wheels);
      ws.push(wj);
    }
    cj.set("wheelsets", ws);
    arr.push(cj);
  }
  j.set("curves", arr);
  return j;
}

// Y/Q of the leading wheelset's wheels (largest offset) against its track
// distance, instantaneous and as 2 m sliding means, with the limits.
void draw_yq(const RunHistory& h, const RunSafety& rs, const std::string& path) {
  if (h.wheelsets.empty() || h.size() < 2) return;
  std::size_t lead = 0;
  for (std::size_t w = 1; w < h.wheelsets.size(); ++w)
    if (h.wheelsets[w].offset > h.wheelsets[lead].offset) lead = w;
  const auto& wh = h.wheelsets[lead];
  results::Chart c;
  c.title = "Y/Q, leading wheelset " + wh.name;
  c.xlabel = "distance of " + wh.name + " along the track [m]";
  c.ylabel = "Y/Q [-]";
  std::vector<double> x(h.size());
  for (std::size_t i = 0; i < h.size(); ++i) x[i] = h.wheelset_distance(lead, i);
  const char* names[2] = {"left", "right"};
  const char* colors[2] = {"tab:blue", "tab:red"};
  const char* mean_colors[2] = {"navy", "darkred"};
  for (int s = 0; s < 2; ++s) {
    results::ChartSeries ser;
    ser.label = wh.name + " " + names[s] + " wheel";
    ser.x = x;
    ser.color = colors[s];
    for (std::size_t i = 0; i < h.size(); ++i)
      ser.y.push_back(wh.wheel[s].Q[i] > 0.0 ? wh.wheel[s].Y[i] / wh.wheel[s].Q[i] : 0.0);
    if (rs.en14363_evaluated) {
      const auto m = results::sliding_mean(x, ser.y, rs.limits.window, rs.limits.step);
      c.series.push_back({wh.name + " " + names[s] + ", 2 m mean", m.centre, m.value, "line", mean_colors[s]});
    }
    c.series.push_back(std::move(ser));
  }
  char buf[96];
  std::snprintf(buf, sizeof buf, "Nadal limit %.3g (%.1f deg, mu %.2g)", rs.nadal, rs.flange_angle * kDeg, rs.mu);
  c.lines.push_back({rs.nadal, buf, "k", false});
  c.lines.push_back({-rs.nadal, "", "k", false});
  std::snprintf(buf, sizeof buf, "(Y/Q)_2m limit %.2g", rs.limits.yq_limit);
  c.lines.push_back({rs.limits.yq_limit, buf, "tab:orange", false});
  c.lines.push_back({-rs.limits.yq_limit, "", "tab:orange", false});
  results::draw(c, path);
}

// Running safety and curving of the recorded history into the summary, and yq.png.
void evaluate_history(const Model& m, const RunHistory& history, results::Json& summary,
                      const std::string& out) {
  if (m.wheelsets.empty() || history.size() == 0) return;
  // Nadal's flange angle from the contact geometry of the first wheelset.
  const FlangeAngle fa = flange_angle(*m.wheelsets.front().geometry);
  const RunSafety safety = evaluate_run_safety(history, fa.angle, m.coupling.options().material.mu);
  summary.set("running_safety", safety_json(safety, fa));
  const CurvingOptions copt;
  const auto curves = evaluate_curving(history, copt);
  summary.set("curving", curving_json(curves, copt));
  if (!out.empty()) draw_yq(history, safety, out + "/yq.png");
  spdlog::info("running safety: {} (Nadal limit {:.3g} at {:.1f} deg, mu {:.2g}{})", safety.pass ? "pass" : "FAIL",
               safety.nadal, safety.flange_angle * kDeg, safety.mu, fa.fallback ? ", fallback flange angle" : "");
  for (const auto& c : curves)
    for (const auto& w : c.wheelsets) {
      const int o = w.wheel[0].outer ? 0 : 1;
      const auto peak = [](const Stat& s) { return std::max(std::fabs(s.min), std::fabs(s.max)); };
      spdlog::info("curve R {:.0f} m: {} angle of attack {:.2f} mrad, |Y/Q| max outer {:.3f} inner {:.3f}, "
                   "mean T-gamma outer {:.1f} N inner {:.1f} N", 1.0 / std::fabs(c.curvature), w.name,
                   w.angle_of_attack.mean * 1e3, peak(w.wheel[o].yq), peak(w.wheel[1 - o].yq),
                   w.wheel[o].Tgamma.mean, w.wheel[1 - o].Tgamma.mean);
    }
}

}  // namespace

ScenarioRunResult run_scenario(const Scenario& sc, const ScenarioRunOptions& o) {
  namespace fs = std::filesystem;
  const bool files = !o.out_dir.empty();
  if (files) {
    std::error_code ec;
    fs::create_directories(o.out_dir, ec);
    if (ec) throw InputError(o.out_dir + ": cannot create the output folder (" + ec.message() + ")");
  }
  const auto& m = sc.model;
  spdlog::info("scenario '{}': vehicle '{}', {} states, {} wheelset model, {}", sc.name, m.vehicle_name,
               m.n_states, wheelset_model_name(m.wheelset_model), sc.integrator.method);

  ScenarioRunResult out;
  out.channel_names = channel_names(m);
  std::unique_ptr<results::CsvWriter> csv;
  if (files) csv = std::make_unique<results::CsvWriter>(o.out_dir + "/channels.csv", out.channel_names, false, 50);
  std::vector<double> row;
  RunHistory history(m);
  const auto expected_rows = static_cast<std::size_t>(std::max(1L, std::lround(sc.duration / sc.output_interval))) + 1;
  history.reserve(expected_rows);
  if (o.keep_channels) out.channels.reserve(expected_rows * out.channel_names.size());
  results::Json& summary = out.summary;
  summary = results::Json::object();
  summary.set("scenario", sc.name);
  summary.set("scenario_file", sc.file);
  summary.set("vehicle", m.vehicle_name);
  results::Json choices = results::Json::object();
  choices.set("wheelset_model", wheelset_model_name(m.wheelset_model));
  choices.set("geometry", sc.geometry_description);
  choices.set("tangential", m.coupling.describe());
  choices.set("track", m.track->describe());
  choices.set("integrator", sc.integrator.method);
  choices.set("rtol", sc.integrator.rtol);
  choices.set("atol", sc.integrator.atol);
  choices.set("max_step", sc.integrator.max_step);
  choices.set("jacobian", sc.integrator.jacobian);
  choices.set("linear_solver", sc.integrator.linear_solver);
  summary.set("model_choices", choices);
  summary.set("speed_initial", m.speed.v0);
  summary.set("duration", sc.duration);
  summary.set("output_interval", sc.output_interval);
  summary.set("states", m.n_states);

  RunSummary& rs = out.run;
  try {
    rs = simulate(m, sc.integrator, sc.x0, sc.duration, sc.output_interval,
                  [&](double t, const Eigen::VectorXd& x, const Data& d) {
                    channel_row(m, t, x, d, row);
                    if (csv) csv->row(row);
                    if (o.keep_channels) out.channels.insert(out.channels.end(), row.begin(), row.end());
                    ++out.rows;
                    history.record(m, t, x, d);
                  });
  } catch (const NumericalError& e) {
    if (csv) csv->flush();
    summary.set("status", "failed");
    summary.set("error", e.what());
    evaluate_history(m, history, summary, o.out_dir);  // up to the failure (e.g. derailment)
    if (files) summary.write_file(o.out_dir + "/summary.json");
    throw;
  }
  if (csv) csv->flush();
  summary.set("status", "ok");
  summary.set("integrator", rs.integrator);
  results::Json st = results::Json::object();
  st.set("steps", rs.stats.steps);
  st.set("rhs_calls", rs.stats.rhs_calls);
  st.set("failed_steps", rs.stats.failed_steps);
  st.set("jacobian_evaluations", rs.stats.jacobian_evals);
  st.set("last_step", rs.stats.last_step);
  summary.set("integrator_statistics", st);
  summary.set("wall_time", rs.wall_time);
  summary.set("real_time_factor", rs.real_time_factor);
  summary.set("cpu_time", rs.cpu_time);
  summary.set("real_time_factor_cpu", rs.real_time_factor_cpu);
  results::Json maxy = results::Json::object();
  double overall = 0;
  for (std::size_t w = 0; w < m.wheelsets.size(); ++w) {
    maxy.set(m.wheelsets[w].name, rs.max_abs_lateral[w]);
    overall = std::max(overall, rs.max_abs_lateral[w]);
  }
  summary.set("max_lateral_shift", overall);
  summary.set("max_lateral_shift_per_wheelset", maxy);
  results::Json warn = results::Json::array();
  if (rs.invalid_contact_calls > 0)
    warn.push("contact model used outside its validity domain in " + std::to_string(rs.invalid_contact_calls) +
              " evaluations (first: " + rs.first_invalid_reason + ")");
  if (m.wheelset_model == WheelsetModel::lateral && overall > 0.006)
    warn.push("lateral wheelset model with lateral shifts above 6 mm: flange contact with quasi-static loads");
  evaluate_history(m, history, summary, o.out_dir);
  summary.set("warnings", warn);
  if (files) summary.write_file(o.out_dir + "/summary.json");
  spdlog::info("done: {:.3g} s simulated in {:.3g} s wall ({:.3g}x real time; {:.3g}x on CPU time), {} steps, {} rhs calls, max |y| {:.3g} mm",
               sc.duration, rs.wall_time, rs.real_time_factor, rs.real_time_factor_cpu, rs.stats.steps, rs.stats.rhs_calls, overall * 1e3);
  return out;
}

}  // namespace railsim::engine
