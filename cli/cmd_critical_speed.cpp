// `railsim critical-speed SCENARIO.yaml --method bifurcation|ramping --out DIR`:
// the critical speed of the scenario's vehicle (engine/analysis/critical_speed.hpp).
//
// Writes DIR/summary.json (critical_speed_kmh, linear_critical_speed_kmh,
// method, contact_model, reduction, wall time, and with --reduction the change
// against the unreduced contact), DIR/bifurcation.csv + bifurcation.png
// (amplitude against speed, both branches, the linear critical speed marked) or
// DIR/ramping.csv + ramping.png. Every finished sweep point is on disk at once;
// a sweep started again in the same DIR skips the finished points. Under
// `mpirun -np N` the speeds are spread over the ranks.
// --compare-models runs the analysis once per contact model and tabulates
// critical speed and wall time per model (DIR/compare_models.csv + .png).
#include <spdlog/spdlog.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "cli/commands.hpp"
#include "cli/support_speed_range.hpp"
#include "contact/reduction.hpp"
#include "contact/registry.hpp"
#include "core/errors.hpp"
#include "engine/analysis/critical_speed.hpp"
#include "engine/analysis/sweep_runner.hpp"
#include "results/chart.hpp"
#include "results/csv_writer.hpp"
#include "results/json_writer.hpp"

namespace railsim::cli {

namespace {

namespace fs = std::filesystem;
using results::Json;

struct CriticalSpeedArgs {
  std::string scenario;
  std::string method = "bifurcation";
  std::string out = "critical_speed";
  std::string model;
  std::string reduction;
  bool compare_models = false;
  std::string models = "coefficients,linear_sat,she,chopaya,polach";
  bool baseline = true;
  // Sweep settings: NaN = not given on the command line, take the scenario's
  // `critical_speed` section (engine::CriticalSpeedSettings) or its defaults.
  double v_min_kmh = NAN, v_max_kmh = NAN, v_step_kmh = NAN;
  double duration = NAN;
  double large = NAN, small = NAN, threshold = NAN;  // mm
  double deceleration = NAN;                          // m/s^2
  bool up_branch = true;
  bool continuation_on = false, continuation_off = false;  // neither: the scenario's setting
  int continuation = -1;  // resolved: 0 off, 1 on
  int threads = 0;
  double ramp_start_kmh = 0.0, ramp_disturbance = 0.0;  // from the scenario only
};

// Command-line values where given, else the scenario's settings.
CriticalSpeedArgs resolve_settings(CriticalSpeedArgs a, const engine::CriticalSpeedSettings& s) {
  auto pick = [](double& cli, double scen) {
    if (std::isnan(cli)) cli = scen;
  };
  const bool range_given = !std::isnan(a.v_max_kmh);
  pick(a.v_min_kmh, s.v_min_kmh);
  pick(a.v_max_kmh, s.v_max_kmh);
  pick(a.v_step_kmh, s.v_step_kmh);
  pick(a.duration, s.duration);
  const bool disturbance_given = !std::isnan(a.large);
  pick(a.large, s.disturbance_mm);
  pick(a.small, s.small_disturbance_mm);
  pick(a.threshold, s.threshold_mm);
  pick(a.deceleration, s.deceleration);
  a.continuation = a.continuation_on ? 1 : a.continuation_off ? 0 : (s.continuation ? 1 : 0);
  a.ramp_start_kmh = range_given || s.ramp_start_kmh <= 0 ? a.v_max_kmh : s.ramp_start_kmh;
  a.ramp_disturbance = disturbance_given || s.ramp_disturbance_mm <= 0 ? a.large : s.ramp_disturbance_mm;
  return a;
}

struct Outcome {
  double critical = NAN, linear = NAN, wall = 0.0;
  std::vector<engine::BifurcationPoint> points;  // bifurcation sweeps only
};

std::string kmh(double v) {
  if (std::isnan(v)) return "none found";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f km/h", v * 3.6);
  return buf;
}

Outcome analyse(const engine::Scenario& sc, const CriticalSpeedArgs& a, const std::string& dir,
                const engine::MpiContext& mpi, Json& summary) {
  fs::create_directories(dir);
  Outcome out;
  const auto t0 = std::chrono::steady_clock::now();
  const double v_lo = a.v_min_kmh / 3.6, v_hi = a.v_max_kmh / 3.6;
  out.linear = engine::linear_critical_speed(sc, std::max(1.0, 0.25 * v_lo), 1.5 * v_hi);
  if (a.method == "bifurcation") {
    engine::BifurcationOptions o;
    o.v_min = v_lo;
    o.v_max = v_hi;
    o.v_step = a.v_step_kmh / 3.6;
    o.duration = a.duration;
    o.large_disturbance = a.large * 1e-3;
    o.small_disturbance = a.small * 1e-3;
    o.threshold = a.threshold * 1e-3;
    o.up_branch = a.up_branch;
    o.continuation = a.continuation == 1;
    o.threads = a.threads;
    o.use_mpi = true;
    const auto r = engine::bifurcation_sweep(sc, o, dir + "/bifurcation.csv");
    out.critical = r.nonlinear_critical_speed;
    out.points = r.points;
    summary.set("speed_resolution_kmh", a.v_step_kmh);
    if (mpi.rank == 0) {
      results::Chart c;
      c.title = "Bifurcation diagram: " + sc.name;
      c.xlabel = "speed [km/h]";
      c.ylabel = "settled lateral amplitude [mm]";
      for (const char* branch : {"down", "up"}) {
        results::ChartSeries s;
        s.label = std::string(branch) == "down" ? "from large disturbance (down)" : "from small disturbance (up)";
        s.style = "line+markers";
        for (const auto& p : r.points)
          if (p.branch == branch) s.x.push_back(p.speed * 3.6), s.y.push_back(p.amplitude * 1e3);
        if (!s.x.empty()) c.series.push_back(s);
      }
      // Runs that stopped (a wheel unloaded or left the contact table): their
      // amplitude is the one reached before the stop, not a settled one.
      results::ChartSeries stopped{"run stopped (wheel unloaded): counted as hunting", {}, {}, "markers", "k"};
      for (const auto& p : r.points)
        if (p.failed) stopped.x.push_back(p.speed * 3.6), stopped.y.push_back(p.amplitude * 1e3);
      if (!stopped.x.empty()) c.series.push_back(stopped);
      if (!std::isnan(out.linear)) c.lines.push_back({out.linear * 3.6, "linear critical speed", "r", true});
      if (!std::isnan(out.critical)) c.lines.push_back({out.critical * 3.6, "nonlinear critical speed", "g", true});
      c.lines.push_back({a.threshold, "hunting threshold", "0.5", false});
      results::draw(c, dir + "/bifurcation.png");
    }
  } else {
    engine::RampingOptions o;
    o.v_start = a.ramp_start_kmh / 3.6;
    o.v_end = v_lo;
    o.deceleration = a.deceleration;
    o.disturbance = a.ramp_disturbance * 1e-3;
    o.threshold = a.threshold * 1e-3;
    const auto r = engine::ramping(sc, o);
    out.critical = r.critical_speed;
    summary.set("deceleration_m_s2", a.deceleration);
    summary.set("hunting_at_start", r.hunting_at_start);
    summary.set("hunting_at_end", r.hunting_at_end);
    if (mpi.rank == 0) {
      results::CsvWriter csv(dir + "/ramping.csv", {"time_s", "speed_kmh", "max_lateral_mm"}, false, 1000);
      results::ChartSeries s{"max |lateral shift| of the wheelsets", {}, {}, "line", ""};
      for (std::size_t i = 0; i < r.time.size(); ++i) {
        csv.row({r.time[i], r.speed[i] * 3.6, r.max_lateral[i] * 1e3});
        s.x.push_back(r.speed[i] * 3.6);
        s.y.push_back(r.max_lateral[i] * 1e3);
      }
      results::Chart c;
      c.title = "Ramping: " + sc.name;
      c.xlabel = "speed [km/h]";
      c.ylabel = "max |lateral shift| [mm]";
      c.series.push_back(s);
      if (!std::isnan(out.critical)) c.lines.push_back({out.critical * 3.6, "critical speed (ramping)", "g", true});
      if (!std::isnan(out.linear)) c.lines.push_back({out.linear * 3.6, "linear critical speed", "r", true});
      results::draw(c, dir + "/ramping.png");
    }
  }
  out.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

void fill_summary(Json& s, const engine::Scenario& sc, const CriticalSpeedArgs& a, const Outcome& o) {
  s.set("scenario", sc.name);
  s.set("vehicle", sc.model.vehicle_name);
  s.set("method", a.method);
  s.set("geometry", sc.geometry_description);
  s.set("equivalent_conicity_3mm", sc.equivalent_conicity_3mm);
  s.set("contact_model", sc.model.coupling.options().tangential);
  s.set("contact_description", sc.model.coupling.describe());
  s.set("reduction", contact::describe_reduction(sc.model.coupling.options().reduction));
  s.set("critical_speed_kmh", std::isnan(o.critical) ? Json(nullptr) : Json(o.critical * 3.6));
  s.set("linear_critical_speed_kmh", std::isnan(o.linear) ? Json(nullptr) : Json(o.linear * 3.6));
  s.set("speed_range_kmh", results::Json::array().push(a.v_min_kmh).push(a.v_max_kmh));
  Json set = Json::object();
  if (a.method == "bifurcation") {
    set.set("v_step_kmh", a.v_step_kmh);
    set.set("duration_s", a.duration);
    set.set("large_disturbance_mm", a.large);
    set.set("small_disturbance_mm", a.small);
    set.set("up_branch", a.up_branch);
    set.set("continuation", a.continuation == 1);
  } else {
    set.set("start_speed_kmh", a.ramp_start_kmh);
    set.set("disturbance_mm", a.ramp_disturbance);
    set.set("deceleration_m_s2", a.deceleration);
  }
  set.set("threshold_mm", a.threshold);
  s.set("settings", set);
  s.set("wall_time_s", o.wall);
}

int run_critical_speed(const CriticalSpeedArgs& args) {
  const engine::MpiContext mpi = engine::mpi_context();
  engine::Scenario base = engine::load_scenario(args.scenario);
  const CriticalSpeedArgs a = resolve_settings(args, base.critical_speed);
  check_speed_range(a.v_min_kmh, a.v_max_kmh, a.v_step_kmh);
  contact::ReductionFactors k;
  const contact::ReductionFactors* kp = nullptr;
  if (!a.reduction.empty()) {
    k = contact::parse_reduction(a.reduction, "--reduction");
    kp = &k;
  }
  if (!a.model.empty()) contact::make_tangential_model(a.model == "coefficients" ? "linear" : a.model);  // validates the name
  std::error_code ec;
  fs::create_directories(a.out, ec);
  if (ec) throw InputError("--out " + a.out + ": cannot create the folder (" + ec.message() + ")");

  if (a.compare_models) {
    std::vector<std::string> names;
    std::stringstream ss(a.models);
    for (std::string n; std::getline(ss, n, ',');)
      if (!n.empty()) names.push_back(n);
    for (const auto& n : names)
      if (n != "coefficients") contact::make_tangential_model(n);
    results::CsvWriter csv(a.out + "/compare_models.csv",
                           {"contact_model", "critical_speed_kmh", "linear_critical_speed_kmh", "wall_time_s"});
    Json table = Json::array();
    results::ChartSeries pts{"critical speed", {}, {}, "markers", ""};
    results::Chart chart;
    for (std::size_t i = 0; i < names.size(); ++i) {
      const engine::Scenario sc = engine::with_contact(base, names[i], kp);
      spdlog::info("compare-models: {} ({}/{})", names[i], i + 1, names.size());
      Json s = Json::object();
      const Outcome o = analyse(sc, a, a.out + "/" + names[i], mpi, s);
      fill_summary(s, sc, a, o);
      if (mpi.rank == 0) {
        s.write_file(a.out + "/" + names[i] + "/summary.json");
        csv.cell(names[i]).cell(o.critical * 3.6).cell(o.linear * 3.6).cell(o.wall).end_row();
      }
      table.push(s);
      pts.x.push_back(o.wall);
      pts.y.push_back(o.critical * 3.6);
      chart.annotations.push_back({names[i], {o.wall, o.critical * 3.6}});
    }
    if (mpi.rank == 0) {
      chart.title = "Critical speed and cost per contact model (" + a.method + ")";
      chart.xlabel = "wall time of the analysis [s]";
      chart.ylabel = "critical speed [km/h]";
      chart.logx = true;
      chart.series.push_back(pts);
      results::draw(chart, a.out + "/compare_models.png");
      Json summary = Json::object();
      summary.set("method", a.method);
      summary.set("models", table);
      summary.write_file(a.out + "/summary.json");
      std::printf("%-16s %22s %22s %12s\n", "contact model", "critical speed", "linear crit. speed", "wall time");
      for (std::size_t i = 0; i < names.size(); ++i)
        std::printf("%-16s %22s %22s %10.1f s\n", names[i].c_str(), kmh(pts.y[i] / 3.6).c_str(), "", pts.x[i]);
    }
    return kExitSuccess;
  }

  const engine::Scenario sc = engine::with_contact(base, a.model, kp);
  Json summary = Json::object();
  const Outcome o = analyse(sc, a, a.out, mpi, summary);
  fill_summary(summary, sc, a, o);
  // With reduced creep coefficients, also the unreduced contact for comparison.
  Outcome ref;
  const bool with_baseline = kp && a.baseline && contact::describe_reduction(k) != "none";
  if (with_baseline) {
    const contact::ReductionFactors none;
    const engine::Scenario sc0 = engine::with_contact(base, a.model, &none);
    Json s0 = Json::object();
    ref = analyse(sc0, a, a.out + "/unreduced", mpi, s0);
    Json b = Json::object();
    b.set("critical_speed_kmh", std::isnan(ref.critical) ? Json(nullptr) : Json(ref.critical * 3.6));
    b.set("linear_critical_speed_kmh", std::isnan(ref.linear) ? Json(nullptr) : Json(ref.linear * 3.6));
    if (!std::isnan(ref.critical) && !std::isnan(o.critical))
      b.set("critical_speed_change_percent", 100.0 * (o.critical - ref.critical) / ref.critical);
    if (!std::isnan(ref.linear) && !std::isnan(o.linear))
      b.set("linear_critical_speed_change_percent", 100.0 * (o.linear - ref.linear) / ref.linear);
    summary.set("unreduced", b);
    if (mpi.rank == 0 && a.method == "bifurcation") {
      // Both down branches on one chart: how far the reduction moves the hunting onset.
      results::Chart c;
      c.title = "Effect of the creep-coefficient reduction: " + sc.name;
      c.xlabel = "speed [km/h]";
      c.ylabel = "settled lateral amplitude, down branch [mm]";
      const std::pair<const Outcome*, std::string> cases[] = {
          {&ref, "unreduced (k = 1)"}, {&o, "reduction " + contact::describe_reduction(k)}};
      const char* colours[] = {"tab:blue", "tab:red"};
      for (int i = 0; i < 2; ++i) {
        results::ChartSeries s{cases[i].second, {}, {}, "line+markers", colours[i]};
        for (const auto& p : cases[i].first->points)
          if (p.branch == "down") s.x.push_back(p.speed * 3.6), s.y.push_back(p.amplitude * 1e3);
        c.series.push_back(s);
        if (!std::isnan(cases[i].first->critical))
          c.lines.push_back({cases[i].first->critical * 3.6, "critical speed, " + cases[i].second, colours[i], true});
      }
      results::draw(c, a.out + "/bifurcation_reduction.png");
    }
  }
  if (mpi.rank == 0) {
    summary.write_file(a.out + "/summary.json");
    std::printf("\nrailsim critical speed: %s\n", sc.name.c_str());
    std::printf("  vehicle            %s\n", sc.model.vehicle_name.c_str());
    std::printf("  contact            %s\n", sc.model.coupling.describe().c_str());
    std::printf("  method             %s over %.0f..%.0f km/h\n", a.method.c_str(), a.v_min_kmh, a.v_max_kmh);
    std::printf("  critical speed     %s\n", kmh(o.critical).c_str());
    std::printf("  linear crit. speed %s (eigenvalues)\n", kmh(o.linear).c_str());
    if (with_baseline) {
      std::printf("  without reduction  %s (linear %s)\n", kmh(ref.critical).c_str(), kmh(ref.linear).c_str());
      if (!std::isnan(ref.critical) && !std::isnan(o.critical))
        std::printf("  change             %+.1f %% from the reduction factors\n",
                    100.0 * (o.critical - ref.critical) / ref.critical);
    }
    std::printf("  wall time          %.1f s\n  results            %s/summary.json\n\n", o.wall + ref.wall,
                a.out.c_str());
  }
  return kExitSuccess;
}

}  // namespace

void register_critical_speed(CLI::App& app, CommandRunner& run) {
  auto a = std::make_shared<CriticalSpeedArgs>();
  auto* cmd = app.add_subcommand("critical-speed", "Critical speed by bifurcation sweep or ramping");
  cmd->add_option("scenario", a->scenario, "Scenario YAML file")->required();
  cmd->add_option("--method", a->method, "bifurcation or ramping")
      ->check(CLI::IsMember({"bifurcation", "ramping"}))
      ->capture_default_str();
  cmd->add_option("--out", a->out, "Output folder")->capture_default_str();
  cmd->add_option("--model", a->model,
                  "Tangential contact model overriding the scenario (coefficients or a registry name: " +
                      contact::tangential_model_names() + ")");
  cmd->add_option("--reduction", a->reduction,
                  "Reduction factors: none, elastic_fe, elastoplastic_fe, third_body, one number k, or k11,k22,k23");
  cmd->add_flag("--compare-models", a->compare_models, "Run once per contact model (see --models) and tabulate");
  cmd->add_option("--models", a->models, "Models for --compare-models, comma-separated")->capture_default_str();
  cmd->add_flag("!--no-baseline", a->baseline, "With --reduction, skip the unreduced comparison run");
  // Defaults of the sweep settings: the scenario's `critical_speed` section, else
  // engine::CriticalSpeedSettings (80..300 km/h in 20 km/h steps, 6 s, 8 / 0.5 mm, 0.5 mm, 0.5 m/s^2).
  cmd->add_option("--v-min", a->v_min_kmh, "Lowest speed [km/h] (default: scenario, else 80)");
  cmd->add_option("--v-max", a->v_max_kmh, "Highest speed, also the ramping start speed [km/h] (default: scenario, else 300)");
  cmd->add_option("--v-step", a->v_step_kmh, "Speed step of the bifurcation sweep [km/h] (default: scenario, else 20)");
  cmd->add_option("--duration", a->duration, "Simulated time per sweep point [s] (default: scenario, else 6)")
      ->check(CLI::Range(0.5, 600.0));
  cmd->add_option("--disturbance", a->large,
                  "Large initial lateral shift (down branch, ramping) [mm] (default: scenario, else 8)")
      ->check(CLI::Range(0.01, 20.0));
  cmd->add_option("--small-disturbance", a->small, "Small initial lateral shift (up branch) [mm] (default: scenario, else 0.5)")
      ->check(CLI::Range(0.001, 20.0));
  cmd->add_option("--threshold", a->threshold, "Settled amplitude that counts as hunting [mm] (default: scenario, else 0.5)")
      ->check(CLI::Range(0.001, 20.0));
  cmd->add_option("--deceleration", a->deceleration, "Ramping deceleration [m/s^2] (default: scenario, else 0.5)")
      ->check(CLI::Range(0.001, 10.0));
  cmd->add_flag("!--no-up-branch", a->up_branch, "Sweep only the strongly disturbed (down) branch");
  auto* on = cmd->add_flag("--continuation", a->continuation_on,
                           "Path following on the down branch: below its lowest hunting speed, each speed starts "
                           "from the limit cycle of the one above, down to the fold (default: the scenario's "
                           "setting, else off)");
  cmd->add_flag("--no-continuation", a->continuation_off, "Every down-branch speed from the large disturbance")
      ->excludes(on);
  cmd->add_option("--threads", a->threads, "Worker threads per process (0: all cores)")
      ->check(CLI::Range(0, 256))
      ->capture_default_str();
  cmd->callback([a, &run] { run = [a] { return run_critical_speed(*a); }; });
}

}  // namespace railsim::cli
