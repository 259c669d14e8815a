// Y/Q of the leading wheels of several runs; see yq_comparison.hpp.
#include "engine/analysis/yq_comparison.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>

#include "config/yaml_input.hpp"
#include "core/errors.hpp"
#include "engine/analysis/run_history.hpp"
#include "engine/analysis/run_safety.hpp"
#include "engine/analysis/safety_limits.hpp"
#include "results/csv_writer.hpp"

namespace railsim::engine {

namespace {

constexpr double kDeg = 180.0 / 3.14159265358979323846;

YqWheelResult evaluate(const std::vector<double>& t, const std::vector<double>& s, const std::vector<double>& yq,
                       double limit) {
  YqWheelResult r;
  for (std::size_t i = 0; i < yq.size(); ++i)
    if (std::fabs(yq[i]) > r.peak) {
      r.peak = std::fabs(yq[i]);
      r.peak_signed = yq[i];
      r.peak_distance = s[i];
      r.peak_time = t[i];
    }
  // Length and duration above the limit; crossings interpolated inside each sample interval.
  for (std::size_t i = 0; i + 1 < yq.size(); ++i) {
    const double a = std::fabs(yq[i]) - limit, b = std::fabs(yq[i + 1]) - limit;
    if (a <= 0.0 && b <= 0.0) continue;
    double f0 = 0.0, f1 = 1.0;  // part of the interval above the limit
    if (a <= 0.0) f0 = a / (a - b);
    if (b <= 0.0) f1 = a / (a - b);
    const double ds = s[i + 1] - s[i], dt = t[i + 1] - t[i];
    r.exceed_length += (f1 - f0) * std::fabs(ds);
    r.exceed_time += (f1 - f0) * dt;
    const double at0 = s[i] + f0 * ds, at1 = s[i] + f1 * ds;
    if (!r.exceeded) r.first_exceed = at0;
    r.last_exceed = at1;
    r.exceeded = true;
  }
  return r;
}

results::Json wheel_json(const YqWheelResult& w) {
  results::Json j = results::Json::object();
  j.set("max_abs_yq", w.peak);
  j.set("yq_at_max", w.peak_signed);
  j.set("distance_m", w.peak_distance);
  j.set("time_s", w.peak_time);
  j.set("exceeds_nadal", w.exceeded);
  j.set("exceed_length_m", w.exceed_length);
  j.set("exceed_time_s", w.exceed_time);
  j.set("first_exceed_m", w.exceeded ? results::Json(w.first_exceed) : results::Json(nullptr));
  j.set("last_exceed_m", w.exceeded ? results::Json(w.last_exceed) : results::Json(nullptr));
  return j;
}

// The run's summary.json (written by `railsim run`): a run that failed
// numerically has no verdict; one of another scenario is compared with a warning.
void read_run_status(const std::string& file, const Scenario& sc, YqRun& run, double& duration, double& interval) {
  if (!std::filesystem::exists(file))
    throw InputError(file + ": not found: `railsim run` writes it whatever the run's end (ok, derailed, failed, interrupted), "
                     "so the run did not finish (killed?) and its Y/Q has no verdict; run it again");
  std::ifstream in(file);
  nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (j.is_discarded() || !j.is_object()) throw InputError(file + ": not a JSON object (a run's summary.json)");
  if (j.contains("status") && j["status"].is_string()) run.status = j["status"].get<std::string>();
  duration = j.contains("duration") && j["duration"].is_number() ? j["duration"].get<double>() : NAN;
  interval = j.contains("output_interval") && j["output_interval"].is_number() ? j["output_interval"].get<double>() : NAN;
  if (run.status == "failed") {
    const std::string why = j.contains("error") && j["error"].is_string() ? j["error"].get<std::string>() : "";
    throw InputError(file + ": status 'failed': the run stopped on a numerical failure" +
                     (why.empty() ? std::string() : " (" + why + ")") +
                     "; its Y/Q has no verdict (run it again, e.g. with a tighter integrator tolerance)");
  }
  if (run.status == "interrupted")
    throw InputError(file + ": status '" + run.status + "': the run was stopped before its end" +
                     (j.contains("interrupted") && j["interrupted"].is_string()
                          ? " (" + j["interrupted"].get<std::string>() + ")"
                          : std::string()) +
                     "; its Y/Q has no verdict (run it to its end)");
  if (j.contains("scenario") && j["scenario"].is_string() && j["scenario"].get<std::string>() != sc.name) {
    run.warning = "a run of scenario '" + j["scenario"].get<std::string>() + "', compared against '" + sc.name +
                  "' (its wheelsets, flange angle and friction)";
    spdlog::warn("compare-yq: {}: {}", run.dir, run.warning);
  }
}

}  // namespace

namespace {

// Default labels: each folder's name, with as many parent folders as it takes
// to tell the runs apart (a/out and b/out: "a/out", "b/out"; "out" alone
// when the names differ). The same folder given twice is refused.
std::vector<std::string> folder_labels(const std::vector<std::string>& dirs) {
  namespace fs = std::filesystem;
  const std::size_t n = dirs.size();
  std::vector<std::vector<fs::path>> parts(n);  // components, last first
  for (std::size_t i = 0; i < n; ++i) {
    fs::path p = fs::path(dirs[i]).lexically_normal();
    if (p.filename().empty()) p = p.parent_path();  // "a/out/" -> "a/out"
    for (const fs::path& c : p) parts[i].insert(parts[i].begin(), c);
    if (parts[i].empty()) parts[i].push_back(dirs[i]);
  }
  std::vector<std::size_t> depth(n, 1);
  auto label = [&](std::size_t i) {
    fs::path l;
    for (std::size_t k = depth[i]; k-- > 0;) l /= parts[i][k];
    return l.generic_string();
  };
  std::vector<std::string> out(n);
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t i = 0; i < n; ++i) out[i] = label(i);
    // Every run whose label another shares takes one parent more.
    std::vector<std::size_t> grow;
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t k = 0; k < n; ++k)
        if (k != i && out[k] == out[i]) {
          if (depth[i] == parts[i].size() && depth[k] == parts[k].size())
            throw InputError("compare-yq: run folders " + std::to_string(std::min(i, k) + 1) + " and " +
                             std::to_string(std::max(i, k) + 1) + " (" + dirs[std::min(i, k)] + ", " +
                             dirs[std::max(i, k)] + ") are the same folder: compare different runs");
          grow.push_back(i);
          break;
        }
    for (std::size_t i : grow)
      if (depth[i] < parts[i].size()) ++depth[i], changed = true;
  }
  return out;
}

}  // namespace

YqComparison compare_yq(const Scenario& sc, const std::vector<std::string>& dirs, const std::vector<std::string>& labels,
                        const std::string& wheelset) {
  if (dirs.empty()) throw InputError("compare-yq: no run folders given");
  if (!labels.empty() && labels.size() != dirs.size())
    throw InputError("--labels: " + std::to_string(labels.size()) + " labels for " + std::to_string(dirs.size()) +
                     " run folders");
  for (std::size_t i = 0; i < labels.size(); ++i) {
    if (labels[i].find_first_not_of(' ') == std::string::npos)
      throw InputError("--labels: label " + std::to_string(i + 1) + " is empty (give one per run folder)");
    for (std::size_t k = 0; k < i; ++k)
      if (labels[k] == labels[i])
        throw InputError("--labels: '" + labels[i] + "' is given twice (labels " + std::to_string(k + 1) + " and " +
                         std::to_string(i + 1) + "): the rows could not be told apart");
  }
  const RunHistory layout(sc.model);
  if (layout.wheelsets.empty()) throw InputError(sc.file + ": the scenario has no wheelsets");
  std::size_t w = 0;
  if (wheelset.empty()) {
    for (std::size_t i = 1; i < layout.wheelsets.size(); ++i)
      if (layout.wheelsets[i].offset > layout.wheelsets[w].offset) w = i;
  } else {
    bool found = false;
    std::string known;
    for (std::size_t i = 0; i < layout.wheelsets.size(); ++i) {
      known += (i ? ", " : "") + layout.wheelsets[i].name;
      if (layout.wheelsets[i].name == wheelset) w = i, found = true;
    }
    if (!found) throw InputError("--wheelset: no wheelset '" + wheelset + "' in the scenario (known: " + known + ")");
  }
  YqComparison c;
  c.scenario = sc.name;
  c.wheelset = layout.wheelsets[w].name;
  c.offset = layout.wheelsets[w].offset;
  const FlangeAngle fa = flange_angle(*sc.model.wheelsets[w].geometry);
  c.flange_angle = fa.angle;
  c.mu = sc.model.coupling.options().material.mu;
  c.nadal = nadal_limit(c.flange_angle, c.mu);
  const std::vector<std::string> names = labels.empty() ? folder_labels(dirs) : labels;
  for (std::size_t r = 0; r < dirs.size(); ++r) {
    YqRun run;
    run.dir = dirs[r];
    run.label = names[r];
    const std::string file = dirs[r] + "/channels.csv";
    if (!std::filesystem::exists(file))
      throw InputError(file + ": not found (give folders written by `railsim run SCENARIO --out DIR`)");
    double duration = NAN, interval = NAN;
    read_run_status(dirs[r] + "/summary.json", sc, run, duration, interval);
    const results::CsvTable t = results::read_csv(file);
    const std::string cols[4] = {"time", "distance", c.wheelset + ".L.YQ", c.wheelset + ".R.YQ"};
    for (const std::string& col : cols) t.column(col);  // throws naming the file and the column
    const auto finite = [&](std::size_t i, const std::string& col) {
      const double v = t.number(i, col);
      if (!std::isfinite(v))
        throw InputError(file + ": line " + std::to_string(i + 2) + ", column '" + col + "': '" +
                         t.rows[i][t.column(col)] + "' is not a finite number (a run's channels hold finite values)");
      return v;
    };
    for (std::size_t i = 0; i < t.rows.size(); ++i) {
      run.time.push_back(finite(i, cols[0]));
      run.distance.push_back(finite(i, cols[1]) + c.offset);
      run.yq[0].push_back(finite(i, cols[2]));
      run.yq[1].push_back(finite(i, cols[3]));
    }
    if (run.time.size() < 2) throw InputError(file + ": fewer than two samples");
    for (std::size_t i = 1; i < run.time.size(); ++i)
      if (!(run.time[i] > run.time[i - 1]))
        throw InputError(file + ": line " + std::to_string(i + 2) + ": time " + config::format_number(run.time[i]) +
                         " s does not follow " + config::format_number(run.time[i - 1]) +
                         " s (a run's channels are in increasing time)");
    // A run that ended normally wrote samples up to its duration: fewer is a truncated file.
    if (run.status == "ok" && std::isfinite(duration) && std::isfinite(interval) &&
        run.time.back() < duration - interval * 1.001)
      throw InputError(file + ": ends at t = " + config::format_number(run.time.back()) + " s, but its run lasted " +
                       config::format_number(duration) + " s (summary.json: status ok, output every " +
                       config::format_number(interval) + " s): the file is truncated; its Y/Q has no verdict");
    for (int s = 0; s < 2; ++s) run.wheel[s] = evaluate(run.time, run.distance, run.yq[s], c.nadal);
    c.runs.push_back(std::move(run));
  }
  return c;
}

results::Chart yq_comparison_chart(const YqComparison& c) {
  results::Chart ch;
  ch.title = "Y/Q of the leading wheelset " + c.wheelset + ": " + c.scenario;
  ch.xlabel = "track distance of " + c.wheelset + " [m]";
  ch.ylabel = "Y/Q [-]";
  ch.width = 10.0;
  ch.height = 6.0;
  static const char* colors[] = {"tab:blue", "tab:red", "tab:green", "tab:purple", "tab:orange", "tab:brown"};
  char buf[200];
  for (std::size_t r = 0; r < c.runs.size(); ++r) {
    const YqRun& run = c.runs[r];
    const std::string color = colors[r % 6];
    for (int s = 0; s < 2; ++s) {
      results::ChartSeries ser;
      const YqWheelResult& w = run.wheel[s];
      std::snprintf(buf, sizeof buf, "%s, %s wheel: peak %.3g at %.1f m%s", run.label.c_str(), s == 0 ? "left" : "right",
                    w.peak, w.peak_distance, w.exceeded ? "" : ", below the limit");
      ser.label = buf;
      if (w.exceeded) {
        std::snprintf(buf, sizeof buf, ", above the limit over %.2f m (%.3f s)", w.exceed_length, w.exceed_time);
        ser.label += buf;
      }
      ser.color = color;
      ser.style = results::custom_style("", s == 0 ? ":" : "-");
      ser.x = run.distance;
      ser.y = run.yq[s];
      ch.series.push_back(ser);
      results::ChartSeries peak;
      peak.color = color;
      peak.style = results::custom_style("o", "", true, 8);
      peak.x = {w.peak_distance};
      peak.y = {w.peak_signed};
      ch.series.push_back(peak);
    }
  }
  std::snprintf(buf, sizeof buf, "Nadal limit %.3g (flange angle %.1f deg, mu %.2g)", c.nadal, c.flange_angle * kDeg,
                c.mu);
  ch.lines.push_back({c.nadal, buf, "k", false});
  ch.lines.push_back({-c.nadal, "", "k", false});
  ch.note = "Y/Q = lateral over vertical force of the rail on the wheel, signed (track y to the left); the limit "
            "applies to |Y/Q|. Dotted: left wheel, solid: right wheel; circles: each wheel's peak.";
  return ch;
}

results::Json yq_comparison_summary(const YqComparison& c) {
  results::Json s = results::Json::object();
  s.set("scenario", c.scenario);
  s.set("wheelset", c.wheelset);
  s.set("wheelset_offset_m", c.offset);
  s.set("nadal_limit", c.nadal);
  s.set("flange_angle_deg", c.flange_angle * kDeg);
  s.set("mu", c.mu);
  s.set("distances", "track distance of the compared wheelset [m]");
  results::Json arr = results::Json::array();
  for (const auto& r : c.runs) {
    results::Json j = results::Json::object();
    j.set("label", r.label);
    j.set("dir", r.dir);
    j.set("status", r.status.empty() ? results::Json(nullptr) : results::Json(r.status));
    if (!r.warning.empty()) j.set("warning", r.warning);
    results::Json wheels = results::Json::object();
    wheels.set("left", wheel_json(r.wheel[0]));
    wheels.set("right", wheel_json(r.wheel[1]));
    j.set("wheels", wheels);
    const int p = r.wheel[1].peak > r.wheel[0].peak ? 1 : 0;
    results::Json peak = wheel_json(r.wheel[p]);
    peak.set("wheel", p == 0 ? "left" : "right");
    j.set("peak", peak);
    arr.push(j);
  }
  s.set("runs", arr);
  return s;
}

}  // namespace railsim::engine
