// Critical speed against the reduction factors; see reduction_study.hpp.
#include "engine/analysis/reduction_study.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <limits>
#include <mutex>
#include <sstream>
#include <thread>

#include "core/atomic_file.hpp"
#include "core/errors.hpp"
#include "engine/analysis/bifurcation_chart.hpp"
#include "engine/analysis/scenario_record.hpp"
#include "engine/analysis/sweep_runner.hpp"
#include "results/csv_writer.hpp"

namespace railsim::engine {

namespace {

namespace fs = std::filesystem;
using results::Json;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kKmh = 3.6;

Json num(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }

bool is_unreduced(const contact::ReductionFactors& k) { return k.k11 == 1.0 && k.k22 == 1.0 && k.k23 == 1.0; }

std::string slug(const std::string& s) {
  std::string out;
  for (char c : s) {
    const bool ok = std::isalnum(static_cast<unsigned char>(c)) || c == '.';
    if (ok) out += c;
    else if (!out.empty() && out.back() != '_') out += '_';
  }
  while (!out.empty() && out.back() == '_') out.pop_back();
  if (out.size() > 48) out.resize(48);
  return out.empty() ? "entry" : out;
}

// Entry label with its numbers when the label is a name (preset, layer).
std::string display_label(const ReductionStudyEntry& e) {
  const auto& spec = e.scenario.reduction;
  const std::string numbers = contact::describe_reduction(spec.k);
  if (spec.form == contact::ReductionForm::preset || spec.form == contact::ReductionForm::layer) {
    char buf[96];
    std::snprintf(buf, sizeof buf, " (%.3g,%.3g,%.3g)", spec.k.k11, spec.k.k22, spec.k.k23);
    return e.label + buf;
  }
  if (spec.form == contact::ReductionForm::uniform) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "k = %g", spec.k.k11);
    return buf;
  }
  return "k = " + numbers;
}

// The settings a study's files depend on; a folder holding another study is refused.
Json settings_json(const Scenario& sc, const ReductionStudyOptions& o) {
  Json s = Json::object();
  s.set("method", o.method);
  s.set("scenario_file", sc.file);
  s.set("scenario", sc.name);
  s.set("contact_model", o.tangential_model.empty() ? sc.model.coupling.options().tangential : o.tangential_model);
  if (o.method == "bifurcation") {
    const BifurcationOptions& b = o.bifurcation;
    s.set("v_min_kmh", b.v_min * kKmh);
    s.set("v_max_kmh", b.v_max * kKmh);
    s.set("v_step_kmh", b.v_step * kKmh);
    s.set("duration_per_point_s", b.duration);
    s.set("large_disturbance_mm", b.large_disturbance * 1e3);
    s.set("small_disturbance_mm", b.small_disturbance * 1e3);
    s.set("threshold_mm", b.threshold * 1e3);
    s.set("tail_fraction", b.tail_fraction);
    s.set("decay_tolerance", b.decay_tolerance);
    s.set("up_branch", b.up_branch);
    s.set("continuation", b.continuation);
  } else {
    const RampingOptions& r = o.ramping;
    s.set("start_speed_kmh", r.v_start * kKmh);
    s.set("end_speed_kmh", r.v_end * kKmh);
    s.set("deceleration_m_s2", r.deceleration);
    s.set("disturbance_mm", r.disturbance * 1e3);
    s.set("threshold_mm", r.threshold * 1e3);
    s.set("collapse_rate_1_s", r.collapse_rate);
    s.set("settle_time_s", r.settle_time);
    s.set("output_interval_s", r.output_interval);
  }
  s.set("linear_bracket_kmh", Json::array().push(o.linear_v_lo * kKmh).push(o.linear_v_hi * kKmh));
  return s;
}

void check_folder(const std::string& dir, const std::string& fingerprint, bool write) {
  const std::string path = dir + "/study_settings.json";
  std::ifstream in(path, std::ios::binary);
  if (in) {
    std::stringstream ss;
    ss << in.rdbuf();
    if (ss.str() != fingerprint)
      throw InputError("--out " + dir + ": the folder holds a reductions study with other settings (" + path +
                       "); its finished points would not match. Use another folder, or remove it to start again");
    return;
  }
  if (write) {
    write_file_atomically(path, fingerprint);
  }
}

// Run fn(i) for i in [0, n) on `workers` threads; the first exception is rethrown after all finished.
template <class Fn>
void parallel_for(std::size_t n, int workers, Fn fn) {
  std::atomic<std::size_t> next{0};
  std::exception_ptr error;
  std::mutex m;
  auto work = [&] {
    for (std::size_t i = next++; i < n; i = next++) {
      {
        std::lock_guard<std::mutex> lock(m);
        if (error) return;
      }
      try {
        fn(i);
      } catch (...) {
        std::lock_guard<std::mutex> lock(m);
        if (!error) error = std::current_exception();
      }
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < workers; ++t) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

void write_ramp_record(const std::string& path, const RampingResult& r) {
  // The CSV text CsvWriter writes (12 significant digits), atomically and checked.
  write_file_atomically(path, [&](std::ostream& f) {
    f << "time_s,speed_kmh,max_lateral_mm\n";
    char buf[96];
    for (std::size_t i = 0; i < r.time.size(); ++i) {
      std::snprintf(buf, sizeof buf, "%.12g,%.12g,%.12g\n", r.time[i], r.speed[i] * kKmh, r.max_lateral[i] * 1e3);
      f << buf;
    }
  });
}

void read_ramp_record(const std::string& path, RampingResult& r) {
  if (!fs::exists(path)) return;
  const auto t = results::read_csv(path);
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    r.time.push_back(t.number(i, "time_s"));
    r.speed.push_back(t.number(i, "speed_kmh") / kKmh);
    r.max_lateral.push_back(t.number(i, "max_lateral_mm") * 1e-3);
  }
}

}  // namespace

std::string reduction_entry_color(std::size_t i) {
  static const char* colors[] = {"tab:blue",  "tab:orange", "tab:green", "tab:red",   "tab:purple", "tab:brown",
                                 "tab:pink",  "tab:olive",  "tab:cyan",  "navy",      "darkred",    "darkgreen",
                                 "goldenrod", "teal",       "indigo",    "chocolate"};
  return colors[i % (sizeof colors / sizeof colors[0])];
}

ReductionStudyResult reduction_study(const Scenario& base, const ReductionStudyOptions& o) {
  if (o.entries.empty()) throw InputError("--reductions: no entries (expected a list such as 1,0.8,0.6,elastic_fe)");
  if (o.method != "bifurcation" && o.method != "ramping")
    throw InputError("--method: expected bifurcation or ramping (got '" + o.method + "')");
  const auto t0 = std::chrono::steady_clock::now();
  const MpiContext mpi = o.use_mpi ? mpi_context() : MpiContext{};
  fs::create_directories(o.out_dir);
  const std::string fingerprint = settings_json(base, o).dump() + "\n";
  check_folder(o.out_dir, fingerprint, mpi.rank == 0);

  ReductionStudyResult res;
  res.method = o.method;
  for (std::size_t i = 0; i < o.entries.size(); ++i) {
    ReductionStudyEntry e;
    e.scenario = with_reduction(base, o.entries[i], "--reductions entry " + std::to_string(i + 1), o.cache_dir,
                                o.tangential_model);
    e.label = contact::reduction_label(e.scenario.reduction);
    if (e.scenario.reduction.form == contact::ReductionForm::layer)
      spdlog::info("reductions: {} -> k11 {:.4g}, k22 {:.4g}, k23 {:.4g} (exact solver{}, patch a {:.2f} mm, b {:.2f} mm)",
                   e.label, e.scenario.reduction.k.k11, e.scenario.reduction.k.k22, e.scenario.reduction.k.k23,
                   e.scenario.layer.from_cache ? ", from the cache" : "", e.scenario.layer.patch.a * 1e3,
                   e.scenario.layer.patch.b * 1e3);
    res.entries.push_back(std::move(e));
  }
  for (std::size_t i = 0; i < res.entries.size() && res.reference < 0; ++i)
    if (is_unreduced(res.entries[i].scenario.reduction.k)) res.reference = static_cast<int>(i);
  if (res.reference < 0) {
    contact::ReductionSpec one = contact::parse_reduction_spec("1", "reference");
    ReductionStudyEntry e;
    e.scenario = with_reduction(base, one, "reference", o.cache_dir, o.tangential_model);
    e.label = contact::reduction_label(e.scenario.reduction);
    e.added_reference = true;
    res.entries.push_back(std::move(e));
    res.reference = static_cast<int>(res.entries.size()) - 1;
  }
  for (std::size_t i = 0; i < res.entries.size(); ++i) {
    char buf[80];
    std::snprintf(buf, sizeof buf, "e%02zu_", i);
    res.entries[i].folder = buf + slug(res.entries[i].label);
    fs::create_directories(o.out_dir + "/" + res.entries[i].folder);
  }
  const std::size_t n = res.entries.size();
  int threads = o.threads > 0 ? o.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  if (mpi.size > 1 && o.threads <= 0) threads = 1;

  // Linear critical speeds (eigenvalues): one point per entry.
  {
    std::vector<SweepPoint> pts;
    for (std::size_t i = 0; i < n; ++i) pts.push_back({static_cast<long>(i), res.entries[i].folder, {}});
    SweepOptions so;
    so.output = o.out_dir + "/linear_critical_speeds.csv";
    so.result_columns = {"linear_critical_speed_m_s"};
    so.threads = threads;
    so.use_mpi = o.use_mpi;
    so.label = "reductions: linear critical speeds";
    const auto rows = run_sweep(pts, [&](const SweepPoint& p) {
      return std::vector<double>{linear_critical_speed(res.entries[static_cast<std::size_t>(p.index)].scenario,
                                                       o.linear_v_lo, o.linear_v_hi)};
    }, so);
    for (const auto& r : rows) res.entries[static_cast<std::size_t>(r.index)].linear = r.values[0];
  }

  if (o.method == "bifurcation") {
    // Entries in parallel (one thread each) when there are enough of them; under
    // mpirun one after the other, each over the ranks.
    const int concurrent = mpi.size > 1 ? 1 : std::max(1, std::min<int>(threads, static_cast<int>(n)));
    const int per_entry = mpi.size > 1 ? threads : std::max(1, threads / concurrent);
    parallel_for(n, concurrent, [&](std::size_t i) {
      ReductionStudyEntry& e = res.entries[i];
      const auto te = std::chrono::steady_clock::now();
      BifurcationOptions b = o.bifurcation;
      b.threads = per_entry;
      b.use_mpi = o.use_mpi;
      b.label = "reductions: " + e.label;
      spdlog::info("reductions: {} ({}/{}) ...", e.label, i + 1, n);
      e.bifurcation = bifurcation_sweep(e.scenario, b, o.out_dir + "/" + e.folder + "/bifurcation.csv");
      e.critical = e.bifurcation.nonlinear_critical_speed;
      e.fold_amplitude = e.bifurcation.fold_amplitude;
      e.fold_frequency = e.bifurcation.fold_frequency;
      e.below_state.clear();
      if (std::isfinite(e.critical))
        for (const auto& p : e.bifurcation.points)
          if (p.branch == Branch::down && std::fabs(p.speed - (e.critical - b.v_step)) < 1e-6 * b.v_step)
            e.below_state = point_state_name(point_state(p, b));
      e.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - te).count();
      spdlog::info("reductions: {}: critical speed {:.1f} km/h ({:.0f} s)", e.label, e.critical * kKmh, e.wall_time);
    });
  } else {
    std::vector<SweepPoint> pts;
    for (std::size_t i = 0; i < n; ++i) pts.push_back({static_cast<long>(i), res.entries[i].folder, {}});
    SweepOptions so;
    so.output = o.out_dir + "/ramping.csv";
    so.result_columns = {"critical_speed_m_s", "hunting_at_start", "hunting_at_end", "critical_time_s",
                         "critical_amplitude_m", "start_speed_m_s", "stopped"};
    so.threads = threads;
    so.use_mpi = o.use_mpi;
    so.label = "reductions: ramps";
    std::vector<double> wall(n, 0.0);
    const auto rows = run_sweep(pts, [&](const SweepPoint& p) {
      const std::size_t i = static_cast<std::size_t>(p.index);
      const auto te = std::chrono::steady_clock::now();
      RampingResult r;
      double stopped = 0.0;  // 0 ran to the end, 1 numerical failure, 2 derailed, 3 left the model's range
      try {
        r = ramping(res.entries[i].scenario, o.ramping);
        if (r.stopped()) stopped = r.derailment.empty() ? 3.0 : 2.0;
      } catch (const NumericalError& err) {
        spdlog::error("reductions: {}: ramp stopped on a numerical failure ({}); no verdict", res.entries[i].label,
                      err.what());
        r.critical_speed = r.critical_time = r.critical_amplitude = kNaN;
        r.start_speed = o.ramping.v_start;
        stopped = 1.0;
      }
      write_ramp_record(o.out_dir + "/" + res.entries[i].folder + "/ramping_record.csv", r);
      wall[i] = std::chrono::duration<double>(std::chrono::steady_clock::now() - te).count();
      return std::vector<double>{r.critical_speed, r.hunting_at_start ? 1.0 : 0.0, r.hunting_at_end ? 1.0 : 0.0,
                                 r.critical_time, r.critical_amplitude, r.start_speed, stopped};
    }, so);
    for (const auto& row : rows) {
      ReductionStudyEntry& e = res.entries[static_cast<std::size_t>(row.index)];
      RampingResult& r = e.ramping;
      r.critical_speed = row.values[0];
      r.hunting_at_start = row.values[1] > 0.5;
      r.hunting_at_end = row.values[2] > 0.5;
      r.critical_time = row.values[3];
      r.critical_amplitude = row.values[4];
      r.start_speed = row.values[5];
      e.ramp_failed = row.values[6] > 0.5 && row.values[6] < 1.5;
      e.ramp_stop = e.ramp_failed           ? "the ramp stopped on a numerical failure (see the log): no verdict"
                    : row.values[6] > 2.5 ? "the ramp's grown motion left the model's range (e.g. a wheel lifting "
                                            "in the lateral model; see the log): no critical speed"
                    : row.values[6] > 1.5 ? "the vehicle derailed during the ramp: no critical speed"
                                          : "";
      read_ramp_record(o.out_dir + "/" + e.folder + "/ramping_record.csv", r);
      e.critical = r.critical_speed;
      e.fold_amplitude = r.critical_amplitude;
      e.fold_frequency = kNaN;
      e.wall_time = wall[static_cast<std::size_t>(row.index)];
    }
  }

  const ReductionStudyEntry& ref = res.entries[static_cast<std::size_t>(res.reference)];
  for (auto& e : res.entries) {
    e.change_percent = (std::isfinite(e.critical) && std::isfinite(ref.critical))
                           ? 100.0 * (e.critical - ref.critical) / ref.critical
                           : kNaN;
    e.linear_change_percent = (std::isfinite(e.linear) && std::isfinite(ref.linear))
                                  ? 100.0 * (e.linear - ref.linear) / ref.linear
                                  : kNaN;
  }
  res.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return res;
}

results::Json reduction_study_summary(const Scenario& sc, const ReductionStudyOptions& o,
                                      const ReductionStudyResult& r) {
  Json s = Json::object();
  s.set("study", "critical speed against the reduction factors on Kalker's creep coefficients");
  s.set("method", r.method);
  Json rec = scenario_record(sc);
  s.set("scenario", rec);
  Json set = settings_json(sc, o);
  s.set("settings", set);
  if (r.method == "bifurcation") s.set("rule", critical_speed_rule(o.bifurcation));
  else
    s.set("rule", "ramping: the speed where the envelope of the lateral motion starts its final collapse");
  s.set("reference_entry", r.reference >= 0 ? Json(r.entries[static_cast<std::size_t>(r.reference)].label) : Json());
  Json arr = Json::array();
  for (const auto& e : r.entries) {
    Json j = Json::object();
    j.set("label", e.label);
    j.set("folder", e.folder);
    j.set("added_as_reference", e.added_reference);
    j.set("reduction", reduction_record(e.scenario));
    const auto& k = e.scenario.reduction.k;
    j.set("k11", k.k11);
    j.set("k22", k.k22);
    j.set("k23", k.k23);
    j.set("mu", e.scenario.model.coupling.options().material.mu);
    j.set("critical_speed_kmh", num(e.critical * kKmh));
    j.set("linear_critical_speed_kmh", num(e.linear * kKmh));
    j.set("critical_speed_change_percent", num(e.change_percent));
    j.set("linear_critical_speed_change_percent", num(e.linear_change_percent));
    j.set("limit_cycle_amplitude_at_fold_mm", num(e.fold_amplitude * 1e3));
    j.set("limit_cycle_frequency_at_fold_hz", num(e.fold_frequency));
    if (r.method == "bifurcation") {
      int counts[kPointStates] = {};
      for (const auto& p : e.bifurcation.points) ++counts[static_cast<int>(point_state(p, o.bifurcation))];
      Json c = Json::object();
      for (int q = 0; q < kPointStates; ++q) c.set(point_state_name(static_cast<PointState>(q)), counts[q]);
      j.set("points_by_state", c);
      j.set("state_one_step_below_critical_speed", e.below_state.empty() ? Json(nullptr) : Json(e.below_state));
      j.set("critical_speed_is_upper_bound", e.below_state == "decaying" || e.below_state == "growing");
      j.set("points", static_cast<long>(e.bifurcation.points.size()));
      if (!e.bifurcation.undetermined.empty()) j.set("undetermined", e.bifurcation.undetermined);
    } else {
      if (!e.ramp_stop.empty()) j.set("stopped", e.ramp_stop);
      j.set("hunting_at_start", e.ramping.hunting_at_start);
      j.set("hunting_at_end", e.ramping.hunting_at_end);
      j.set("start_speed_kmh", num(e.ramping.start_speed * kKmh));
      j.set("critical_speed_read_at_time_s", num(e.ramping.critical_time));
    }
    arr.push(j);
  }
  s.set("entries", arr);
  return s;
}

results::Json reduction_study_timing(const ReductionStudyResult& r) {
  Json t = Json::object();
  t.set("wall_time_s", r.wall_time);
  t.set("note", "wall time of this call; entries finished by an earlier call show 0");
  Json arr = Json::array();
  for (const auto& e : r.entries) {
    Json j = Json::object();
    j.set("label", e.label);
    j.set("wall_time_s", e.wall_time);
    arr.push(j);
  }
  t.set("entries", arr);
  return t;
}

results::Chart reductions_chart(const Scenario& sc, const ReductionStudyOptions& o, const ReductionStudyResult& r) {
  if (r.method == "bifurcation") {
    std::vector<BifurcationCurve> curves;
    for (std::size_t i = 0; i < r.entries.size(); ++i)
      curves.push_back({display_label(r.entries[i]), reduction_entry_color(i), &r.entries[i].bifurcation,
                        r.entries[i].linear});
    results::Chart c = bifurcation_chart(curves, o.bifurcation,
                                         "Down branches against the reduction factors: " + sc.name, false);
    c.ylabel = "lateral amplitude over the tail of each run, down branch [mm]";
    return c;
  }
  results::Chart c;
  c.title = "Ramping against the reduction factors: " + sc.name;
  c.xlabel = "speed [km/h]";
  c.ylabel = "max |lateral shift| of the wheelsets over 0.5 s [mm]";
  c.y_from_zero = true;
  c.width = 11.0;
  c.height = 6.5;
  char buf[160];
  for (std::size_t i = 0; i < r.entries.size(); ++i) {
    const auto& e = r.entries[i];
    results::ChartSeries s;
    std::snprintf(buf, sizeof buf, ": critical speed %.1f km/h", e.critical * kKmh);
    s.label = display_label(e) + (std::isfinite(e.critical) ? std::string(buf) : ": none found");
    s.color = reduction_entry_color(i);
    s.style = results::custom_style("", "-");
    ramping_envelope(e.ramping, s.x, s.y);
    c.series.push_back(s);
    if (std::isfinite(e.critical) && std::isfinite(e.fold_amplitude)) {
      results::ChartSeries at;
      at.color = s.color;
      at.style = results::custom_style("*", "", false, 12);
      at.x = {e.critical * kKmh};
      at.y = {e.fold_amplitude * 1e3};
      c.series.push_back(at);
    }
  }
  results::ChartSeries key;
  key.label = "star: where the critical speed was read (start of the final collapse)";
  key.color = "0.3";
  key.style = results::custom_style("*", "", false, 12);
  c.series.push_back(key);
  std::snprintf(buf, sizeof buf, "ramps from %.1f km/h at %.3g m/s^2 (speed falls from right to left)",
                o.ramping.v_start * kKmh, o.ramping.deceleration);
  c.note = buf;
  return c;
}

results::Chart critical_speed_vs_k_chart(const Scenario& sc, const ReductionStudyResult& r) {
  results::Chart c;
  c.title = "Critical speed against the reduction factor: " + sc.name;
  c.xlabel = "reduction factor k (uniform entries); k22 for the others (labelled)";
  c.ylabel = "critical speed [km/h]";
  c.width = 9.0;
  c.height = 6.0;
  std::vector<const ReductionStudyEntry*> uniform, other;
  for (const auto& e : r.entries) {
    const auto& k = e.scenario.reduction.k;
    (k.k11 == k.k22 && k.k22 == k.k23 && e.scenario.reduction.form != contact::ReductionForm::layer ? uniform : other)
        .push_back(&e);
  }
  std::sort(uniform.begin(), uniform.end(),
            [](auto* a, auto* b) { return a->scenario.reduction.k.k11 < b->scenario.reduction.k.k11; });
  results::ChartSeries nl, lin, nl_o, lin_o;
  nl.label = std::string("nonlinear critical speed (") + r.method + "), uniform k";
  nl.color = "tab:green";
  nl.style = results::custom_style("o", "-");
  lin.label = "linear critical speed (eigenvalues), uniform k";
  lin.color = "tab:red";
  lin.style = results::custom_style("s", "--");
  for (auto* e : uniform) {
    nl.x.push_back(e->scenario.reduction.k.k11), nl.y.push_back(e->critical * kKmh);
    lin.x.push_back(e->scenario.reduction.k.k11), lin.y.push_back(e->linear * kKmh);
  }
  nl_o.label = "nonlinear critical speed, other entries";
  nl_o.color = "tab:green";
  nl_o.style = results::custom_style("D", "", false, 7);
  lin_o.label = "linear critical speed, other entries";
  lin_o.color = "tab:red";
  lin_o.style = results::custom_style("D", "", true, 7);
  for (auto* e : other) {
    const double x = e->scenario.reduction.k.k22;
    nl_o.x.push_back(x), nl_o.y.push_back(e->critical * kKmh);
    lin_o.x.push_back(x), lin_o.y.push_back(e->linear * kKmh);
    c.annotations.push_back({display_label(*e), {x, std::isfinite(e->critical) ? e->critical * kKmh : e->linear * kKmh}});
  }
  c.series.push_back(nl);
  c.series.push_back(lin);
  if (!other.empty()) {
    c.series.push_back(nl_o);
    c.series.push_back(lin_o);
  }
  // Critical speeds read above a run that was still decaying at its end: upper bounds.
  results::ChartSeries bound;
  bound.label = "upper bound: the run one step below was still decaying at its end";
  bound.color = "k";
  bound.style = results::custom_style("o", "", true, 13);
  for (const auto& e : r.entries)
    if ((e.below_state == "decaying" || e.below_state == "growing") && std::isfinite(e.critical)) {
      const auto& k = e.scenario.reduction.k;
      const bool uni = k.k11 == k.k22 && k.k22 == k.k23 && e.scenario.reduction.form != contact::ReductionForm::layer;
      bound.x.push_back(uni ? k.k11 : k.k22);
      bound.y.push_back(e.critical * kKmh);
    }
  if (!bound.x.empty()) c.series.push_back(bound);
  c.note = "Points without a value (none found in the speed range) are left out.";
  return c;
}

}  // namespace railsim::engine
