// `railsim critical-speed SCENARIO.yaml --method bifurcation|ramping --out DIR`:
// the critical speed of the scenario's vehicle (engine/analysis/critical_speed.hpp).
//
// Writes DIR/summary.json (critical_speed_kmh, linear_critical_speed_kmh,
// method, the scenario record: mu, geometry and its equivalent conicity,
// wheelset model, saturation law, reduction as given; the settings with the
// duration per point; wall time; with --reduction the change against the
// unreduced contact), DIR/bifurcation.csv + bifurcation.png (amplitude against
// speed, both branches, markers by what each run did by its end, the fold as a
// jump, the rule of the critical speed; engine/analysis/bifurcation_chart.hpp)
// or DIR/ramping.csv + ramping.png (the ramp's start speed named, the point
// where the critical speed was read marked). Every finished sweep point is on
// disk at once; a sweep started again in the same DIR skips the finished
// points. Under `mpirun -np N` the speeds are spread over the ranks.
// --compare-models runs the analysis once per contact model and tabulates
// critical speed and wall time per model (DIR/compare_models.csv + .png).
// --reductions LIST runs the analysis once per reduction-factor entry in one
// resumable job (engine/analysis/reduction_study.hpp) and writes
// DIR/reductions.csv, DIR/summary.json, DIR/timing.json (wall times),
// DIR/reductions.png (the down branches of every entry) and
// DIR/critical_speed_vs_k.png; each entry's sweep in its own sub-folder.
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/support_interrupt.hpp"
#include "cli/support_option_checks.hpp"
#include "engine/analysis/sweep_limits.hpp"
#include "config/yaml_input.hpp"
#include "contact/reduction.hpp"
#include "contact/registry.hpp"
#include "core/errors.hpp"
#include "core/output_lock.hpp"
#include "engine/analysis/bifurcation_chart.hpp"
#include "engine/analysis/critical_speed.hpp"
#include "engine/analysis/critical_speed_study.hpp"
#include "engine/analysis/reduction_study.hpp"
#include "engine/analysis/scenario_record.hpp"
#include "engine/analysis/sweep_runner.hpp"
#include "results/chart.hpp"
#include "results/csv_writer.hpp"
#include "results/json_writer.hpp"

namespace railsim::cli {

namespace {

namespace fs = std::filesystem;
using results::Json;

struct CriticalSpeedArgs {
  std::vector<std::string> given;  // options given on the command line (for those that do not apply)
  std::string scenario;
  std::string method = "bifurcation";
  std::string out = "critical_speed";
  std::string model;
  std::string reduction;
  std::string reductions;  // study: list of entries
  std::string cache_dir;   // layer factors
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
  int threads = 0;
};

// The settings in SI (the engine's units): command-line values (km/h, mm)
// where given, else the scenario's critical_speed section (already SI).
engine::CriticalSpeedStudySettings study_settings(const CriticalSpeedArgs& a, const engine::CriticalSpeedSettings& sc) {
  engine::CriticalSpeedStudySettings s = engine::study_settings(sc);
  s.method = engine::parse_critical_speed_method(a.method, "--method");
  engine::CriticalSpeedOverrides given;  // options not given are NaN
  given.v_min_kmh = a.v_min_kmh;
  given.v_max_kmh = a.v_max_kmh;
  given.v_step_kmh = a.v_step_kmh;
  given.duration = a.duration;
  given.large_disturbance_mm = a.large;
  given.small_disturbance_mm = a.small;
  given.threshold_mm = a.threshold;
  given.deceleration = a.deceleration;
  if (a.continuation_on || a.continuation_off) given.continuation = a.continuation_on;
  engine::apply_overrides(s, given);
  s.up_branch = a.up_branch;
  s.threads = a.threads;
  s.stop = interrupt_request();  // Ctrl-C: finished points stay for the resume
  return s;
}

std::string kmh(double v) {
  if (std::isnan(v)) return "none found";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f km/h", v * 3.6);
  return buf;
}

// The critical speed as printed: "undetermined" when a failure left no
// verdict, "none (derailed)" when a ramp derailed, else the speed or "none found".
std::string verdict_text(const engine::CriticalSpeedOutcome& o) {
  if (!o.bifurcation.undetermined.empty()) return "undetermined (see below)";
  if (!o.ramping.derailment.empty()) return "none (derailed, see below)";
  if (!o.ramping.range_stop.empty()) return "none (left the model's range, see below)";
  return kmh(o.critical);
}

// Exit code of analyses whose verdict may be missing: a bifurcation sweep
// whose hunting range could not be followed (engine BifurcationResult::
// undetermined) gives no critical speed; the reason goes to stderr, and the
// exit is 3 for a numerical failure, 2 for runs too short or a sweep whose
// lowest speed still hunts (a setting to change), never 0. `what` names the analysis (model, reduction entry).
int verdict_exit(const engine::BifurcationResult& b, const std::string& what, int so_far = kExitSuccess) {
  using U = engine::BifurcationResult::Undetermined;
  if (b.undetermined_kind == U::none) return so_far;
  std::fprintf(stderr, "railsim critical-speed: %sno critical speed: %s\n", what.empty() ? "" : (what + ": ").c_str(),
               b.undetermined.c_str());
  const int code = b.undetermined_kind == U::numerical_failure ? kExitNumericalFailure : kExitBadInput;
  return std::max(so_far, code);
}

// A ramp that derailed or whose grown motion left the model's range (the
// physics, a result: exit 0): its message, no critical speed.
void print_ramp_derailment(const engine::RampingResult& r, const std::string& what) {
  if (!r.stopped()) return;
  std::fprintf(stderr, "railsim critical-speed: %sno critical speed: %s\n", what.empty() ? "" : (what + ": ").c_str(),
               (r.derailment.empty() ? r.range_stop : r.derailment).c_str());
}

void print_ramp_start(const engine::CriticalSpeedStudySettings& s, const char* suffix) {
  std::printf("ramping from %.1f km/h (%s) down to %.1f km/h at %.3g m/s^2%s\n", s.ramp_start * 3.6,
              s.ramp_start_source.c_str(), s.v_min * 3.6, s.deceleration, suffix);
}

// The chart (and for ramping the record) of one analysis in `dir`.
void write_analysis_files(const engine::Scenario& sc, const engine::CriticalSpeedStudySettings& s,
                          const engine::CriticalSpeedOutcome& o, const std::string& dir) {
  if (s.method == engine::CriticalSpeedMethod::bifurcation) {
    const std::vector<engine::BifurcationCurve> curves = {
        {contact::reduction_label(sc.reduction), "tab:blue", &o.bifurcation, o.linear}};
    results::draw(engine::bifurcation_chart(curves, engine::bifurcation_options(s), "Bifurcation diagram: " + sc.name,
                                            s.up_branch),
                  dir + "/bifurcation.png");
    return;
  }
  const engine::RampingResult& r = o.ramping;
  results::CsvWriter csv(dir + "/ramping.csv", {"time_s", "speed_kmh", "max_lateral_mm"}, false, 1000);
  for (std::size_t i = 0; i < r.time.size(); ++i) csv.row({r.time[i], r.speed[i] * 3.6, r.max_lateral[i] * 1e3});
  csv.close();
  results::draw(engine::ramping_chart(r, o.linear, s.threshold, "Ramping: " + sc.name), dir + "/ramping.png");
}

std::string kmh_cell(double v) {
  if (!std::isfinite(v)) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f", v * 3.6);
  return buf;
}

std::string percent_cell(double v) {
  if (!std::isfinite(v)) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%+.1f %%", v);
  return buf;
}

// --reductions: the study (engine/analysis/reduction_study.hpp), its files and table.
int run_reduction_study(const engine::Scenario& base, const CriticalSpeedArgs& a,
                        const engine::CriticalSpeedStudySettings& s,
                        const std::vector<contact::ReductionSpec>& entries, const engine::MpiContext& mpi) {
  engine::ReductionStudyOptions o;
  o.entries = entries;
  o.method = a.method;
  o.bifurcation = engine::bifurcation_options(s);
  o.ramping = engine::ramping_options(s);
  o.linear_v_lo = std::max(1.0, 0.25 * s.v_min);
  o.linear_v_hi = engine::linear_bracket_high(s);
  o.out_dir = a.out;
  o.cache_dir = a.cache_dir;
  o.tangential_model = a.model;
  o.threads = a.threads;
  if (mpi.rank == 0 && a.method == "ramping") print_ramp_start(s, ", every entry");
  const engine::ReductionStudyResult r = engine::reduction_study(base, o);
  if (mpi.rank != 0) return kExitSuccess;

  // reductions.csv: one row per entry (no wall times: a resumed job writes the same file).
  {
    results::CsvWriter csv(a.out + "/reductions.csv",
                           {"entry", "label", "given", "form", "k11", "k22", "k23", "mu", "critical_speed_kmh",
                            "linear_critical_speed_kmh", "critical_speed_change_percent",
                            "linear_critical_speed_change_percent", "limit_cycle_amplitude_at_fold_mm",
                            "limit_cycle_frequency_at_fold_hz", "state_one_step_below", "folder"},
                           false, 1000);
    for (std::size_t i = 0; i < r.entries.size(); ++i) {
      const auto& e = r.entries[i];
      const auto& spec = e.scenario.reduction;
      csv.cell(static_cast<long>(i))
          .cell(e.label)
          .cell(spec.text)
          .cell(contact::reduction_form_name(spec.form))
          .cell(spec.k.k11)
          .cell(spec.k.k22)
          .cell(spec.k.k23)
          .cell(e.scenario.model.coupling.options().material.mu)
          .cell(e.critical * 3.6)
          .cell(e.linear * 3.6)
          .cell(e.change_percent)
          .cell(e.linear_change_percent)
          .cell(e.fold_amplitude * 1e3)
          .cell(e.fold_frequency)
          .cell(e.below_state)
          .cell(e.folder);
      csv.end_row();
    }
    csv.close();
  }
  engine::reduction_study_summary(base, o, r).write_file(a.out + "/summary.json");
  engine::reduction_study_timing(r).write_file(a.out + "/timing.json");
  results::draw(engine::reductions_chart(base, o, r), a.out + "/reductions.png");
  results::draw(engine::critical_speed_vs_k_chart(base, r), a.out + "/critical_speed_vs_k.png");
  for (std::size_t i = 0; i < r.entries.size(); ++i) {
    const auto& e = r.entries[i];
    const std::string dir = a.out + "/" + e.folder;
    if (a.method == "bifurcation") {
      const std::vector<engine::BifurcationCurve> curves = {{e.label, engine::reduction_entry_color(i), &e.bifurcation,
                                                             e.linear}};
      results::draw(engine::bifurcation_chart(curves, o.bifurcation, "Bifurcation diagram: " + base.name + ", " + e.label,
                                              a.up_branch),
                    dir + "/bifurcation.png");
    } else {
      results::draw(engine::ramping_chart(e.ramping, e.linear, o.ramping.threshold,
                                          "Ramping: " + base.name + ", " + e.label),
                    dir + "/ramping.png");
    }
  }

  std::printf("\nrailsim critical speed against the reduction factors: %s\n", base.name.c_str());
  std::printf("  vehicle %s, %s wheelset model, %s\n  contact %s, mu %.3g\n  method  %s", base.model.vehicle_name.c_str(),
              engine::wheelset_model_name(base.model.wheelset_model), base.geometry_description.c_str(),
              base.model.coupling.options().tangential.c_str(), base.model.coupling.options().material.mu,
              a.method.c_str());
  if (a.method == "bifurcation")
    std::printf(" over %.0f..%.0f km/h, step %.3g km/h, %.3g s per point%s\n", s.v_min * 3.6, s.v_max * 3.6,
                s.v_step * 3.6, s.duration, s.continuation ? ", with continuation" : "");
  else
    std::printf(" from %.1f km/h (%s) at %.3g m/s^2\n", s.ramp_start * 3.6, s.ramp_start_source.c_str(),
                s.deceleration);
  std::printf("\n  %-38s %6s %6s %6s %10s %8s %10s %8s %9s\n", "entry", "k11", "k22", "k23", "V_NL km/h", "change",
              "V_L km/h", "change", "fold mm");
  for (const auto& e : r.entries) {
    const auto& k = e.scenario.reduction.k;
    char fold[32] = "-";
    if (std::isfinite(e.fold_amplitude)) std::snprintf(fold, sizeof fold, "%.2f", e.fold_amplitude * 1e3);
    const bool bound = e.below_state == "decaying" || e.below_state == "growing";
    std::printf("  %-38s %6.3g %6.3g %6.3g %10s %8s %10s %8s %9s%s%s\n", e.label.substr(0, 38).c_str(), k.k11, k.k22,
                k.k23, (std::string(bound ? "<=" : "") + kmh_cell(e.critical)).c_str(),
                percent_cell(e.change_percent).c_str(), kmh_cell(e.linear).c_str(),
                percent_cell(e.linear_change_percent).c_str(), fold,
                e.added_reference ? "  (added as the k = 1 reference)" : "",
                bound ? "  (upper bound: the run one step below was still decaying)" : "");
  }
  std::printf("\n  wall time %.1f s\n  results   %s/reductions.csv, summary.json, reductions.png, "
              "critical_speed_vs_k.png\n\n",
              r.wall_time, a.out.c_str());
  int code = kExitSuccess;
  for (const auto& e : r.entries) {
    code = verdict_exit(e.bifurcation, e.label, code);
    if (!e.ramp_stop.empty())
      std::fprintf(stderr, "railsim critical-speed: %s: no critical speed: %s\n", e.label.c_str(), e.ramp_stop.c_str());
    if (e.ramp_failed) code = std::max(code, kExitNumericalFailure);
  }
  return code;
}

int run_critical_speed(const CriticalSpeedArgs& a) {
  const engine::MpiContext mpi = engine::mpi_context();
  // One job per output folder (the ranks of one MPI job share it: rank 0 holds the lock).
  std::optional<OutputLock> lock;
  if (mpi.rank == 0) lock.emplace(a.out, "critical-speed");
  engine::Scenario base = engine::load_scenario(a.scenario);
  const engine::CriticalSpeedStudySettings s = study_settings(a, base.critical_speed);
  engine::check_speed_range(s.v_min * 3.6, s.v_max * 3.6, s.v_step * 3.6);
  // Options that do not apply to this analysis were ignored silently.
  const auto given = [&](const char* opt) { return std::find(a.given.begin(), a.given.end(), opt) != a.given.end(); };
  const bool ramping = s.method == engine::CriticalSpeedMethod::ramping;
  for (const char* opt : {"--v-step", "--duration", "--small-disturbance", "--no-up-branch", "--continuation",
                          "--no-continuation"})
    if (ramping && given(opt))
      throw InputError(std::string(opt) + ": applies to the bifurcation sweep, not to ramping (which takes --v-min, "
                                          "--v-max, --disturbance, --threshold and --deceleration)");
  if (!ramping && given("--deceleration"))
    throw InputError("--deceleration: applies to ramping (--method ramping), not to the bifurcation sweep");
  if (given("--models") && !a.compare_models)
    throw InputError("--models: applies with --compare-models (to choose one model: --model)");
  if (given("--no-baseline") && a.reduction.empty())
    throw InputError("--no-baseline: applies with --reduction (it skips the unreduced comparison run)");
  if (!ramping && s.up_branch && !(s.large_disturbance > s.small_disturbance))
    throw InputError("--disturbance/--small-disturbance: the down branch's disturbance (" +
                     config::format_number(s.large_disturbance * 1e3) + " mm) must exceed the up branch's (" +
                     config::format_number(s.small_disturbance * 1e3) + " mm)");
  if (!a.reduction.empty() && !a.reductions.empty())
    throw InputError("--reduction and --reductions: give one of them (--reductions runs every entry of its list)");
  if (!a.reductions.empty() && a.compare_models)
    throw InputError("--reductions and --compare-models: give one of them");
  contact::ReductionSpec spec;
  const bool reduction_given = !a.reduction.empty();
  if (reduction_given) spec = contact::parse_reduction_spec(a.reduction, "--reduction");
  std::vector<contact::ReductionSpec> study_entries;
  if (!a.reductions.empty()) study_entries = contact::parse_reduction_list(a.reductions, "--reductions");
  if (!a.model.empty()) {
    tangential_model_option("--model", a.model);
    try {
      engine::check_model_has_patch(base, a.model);  // a model the scenario's contact can feed
    } catch (const InputError& e) {
      throw InputError("--model " + a.model + ": " + e.what());
    }
  }
  std::error_code ec;
  fs::create_directories(a.out, ec);
  if (ec) throw InputError("--out " + a.out + ": cannot create the folder (" + ec.message() + ")");
  if (!study_entries.empty()) return run_reduction_study(base, a, s, study_entries, mpi);
  // The reduction resolved once (a layer's factors for this scenario's patch).
  if (reduction_given) base = engine::with_reduction(base, spec, "--reduction", a.cache_dir);

  if (mpi.rank == 0 && s.method == engine::CriticalSpeedMethod::ramping) print_ramp_start(s, "");
  if (a.compare_models) {
    std::vector<std::string> names;
    std::stringstream ss(a.models);
    for (std::string n; std::getline(ss, n, ',');)
      if (!n.empty()) names.push_back(n);
    if (names.empty()) throw InputError("--models '" + a.models + "': no model named");
    for (std::size_t i = 0; i < names.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (names[i] == names[j])
          throw InputError("--models: model '" + names[i] + "' listed twice (each model's results go to its own "
                           "folder)");
    for (const auto& n : names) {
      tangential_model_option("--models", n);
      try {
        engine::check_model_has_patch(base, n);
      } catch (const InputError& e) {
        throw InputError("--models: " + std::string(e.what()));
      }
    }
    // Each model's files as soon as it is done (rank 0): a later model's failure keeps them.
    std::optional<results::CsvWriter> csv;
    if (mpi.rank == 0)
      csv.emplace(a.out + "/compare_models.csv",
                  std::vector<std::string>{"contact_model", "critical_speed_kmh", "linear_critical_speed_kmh",
                                           "wall_time_s"});
    Json table = Json::array();
    results::ChartSeries pts{"critical speed", {}, {}, "markers", ""};
    results::Chart chart;
    const auto finished = [&](const engine::ModelCriticalSpeed& m) {
      table.push(m.summary);
      pts.x.push_back(m.outcome.wall);
      pts.y.push_back(m.outcome.critical * 3.6);
      chart.annotations.push_back({m.model, {m.outcome.wall, m.outcome.critical * 3.6}});
      if (mpi.rank != 0) return;
      write_analysis_files(m.scenario, s, m.outcome, a.out + "/" + m.model);
      m.summary.write_file(a.out + "/" + m.model + "/summary.json");
      csv->cell(m.model).cell(m.outcome.critical * 3.6).cell(m.outcome.linear * 3.6).cell(m.outcome.wall).end_row();
    };
    const std::vector<engine::ModelCriticalSpeed> runs =
        engine::critical_speed_per_model(base, names, s, a.out, finished);
    if (mpi.rank != 0) return kExitSuccess;
    csv->close();
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
    for (std::size_t i = 0; i < runs.size(); ++i)
      std::printf("%-16s %22s %22s %10.1f s\n", runs[i].model.c_str(), verdict_text(runs[i].outcome).c_str(),
                  kmh(runs[i].outcome.linear).c_str(), pts.x[i]);
    int code = kExitSuccess;
    for (const auto& m : runs) code = verdict_exit(m.outcome.bifurcation, m.model, code);
    return code;
  }

  const engine::CriticalSpeedWithBaseline r =
      engine::critical_speed_with_baseline(base, a.model, s, reduction_given, a.baseline, a.out);
  if (mpi.rank != 0) return kExitSuccess;
  const engine::Scenario& sc = r.scenario;
  const engine::CriticalSpeedOutcome& o = r.outcome;
  const engine::CriticalSpeedOutcome& ref = r.unreduced;
  write_analysis_files(sc, s, o, a.out);
  if (r.with_baseline) {
    write_analysis_files(r.unreduced_scenario, s, ref, a.out + "/unreduced");
    if (s.method == engine::CriticalSpeedMethod::bifurcation) {
      // Both down branches on one chart: how far the reduction moves the hunting onset.
      const std::vector<engine::BifurcationCurve> curves = {
          {"unreduced (k = 1)", "tab:blue", &ref.bifurcation, ref.linear},
          {"reduction " + contact::reduction_label(sc.reduction), "tab:red", &o.bifurcation, o.linear}};
      results::draw(engine::bifurcation_chart(curves, engine::bifurcation_options(s),
                                              "Effect of the creep-coefficient reduction: " + sc.name, false),
                    a.out + "/bifurcation_reduction.png");
    }
  }
  r.summary.write_file(a.out + "/summary.json");
  std::printf("\nrailsim critical speed: %s\n", sc.name.c_str());
  std::printf("  vehicle            %s\n", sc.model.vehicle_name.c_str());
  std::printf("  contact            %s\n", sc.model.coupling.describe().c_str());
  if (a.method == "ramping")
    std::printf("  method             ramping from %.1f km/h (%s) down to %.0f km/h\n", s.ramp_start * 3.6,
                s.ramp_start_source.c_str(), s.v_min * 3.6);
  else
    std::printf("  method             %s over %.0f..%.0f km/h\n", a.method.c_str(), s.v_min * 3.6, s.v_max * 3.6);
  std::printf("  critical speed     %s\n", verdict_text(o).c_str());
  std::printf("  linear crit. speed %s (eigenvalues)\n", kmh(o.linear).c_str());
  if (r.with_baseline) {
    std::printf("  without reduction  %s (linear %s)\n", verdict_text(ref).c_str(), kmh(ref.linear).c_str());
    if (!std::isnan(r.change_percent))
      std::printf("  change             %+.1f %% from the reduction factors\n", r.change_percent);
  }
  std::printf("  wall time          %.1f s\n  results            %s/summary.json\n\n", o.wall + ref.wall,
              a.out.c_str());
  print_ramp_derailment(o.ramping, "");
  if (r.with_baseline) print_ramp_derailment(ref.ramping, "without reduction");
  int code = verdict_exit(o.bifurcation, "");
  if (r.with_baseline) code = verdict_exit(ref.bifurcation, "without reduction", code);
  return code;
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
                      contact::tangential_model_names() + ")")
      ->check(non_empty_value());
  cmd->add_option("--reduction", a->reduction,
                  "Reduction factors: none, elastic_fe, elastoplastic_fe, third_body, one number k, k11,k22,k23, or a "
                  "third-body layer layer:h=<m>,G3=<Pa>[,tau_c=<Pa>] (factors computed by the exact solver for the "
                  "scenario's patch)")
      ->check(non_empty_value());
  cmd->add_option("--reductions", a->reductions,
                  "Study: the analysis once per entry of this list of --reduction forms, in one resumable job "
                  "(e.g. 1,0.9,0.8,0.7,0.6,0.5,elastic_fe,elastoplastic_fe,layer:h=125e-6,G3=820e6; a triple in "
                  "brackets (0.72,0.56,0.56), or entries separated by ';')")
      ->check(non_empty_value());
  cmd->add_option("--cache-dir", a->cache_dir,
                  "Cache folder of computed layer factors (default: $RAILSIM_CACHE_DIR, else ~/.cache/railsim)");
  cmd->add_flag("--compare-models", a->compare_models, "Run once per contact model (see --models) and tabulate");
  cmd->add_option("--models", a->models, "Models for --compare-models, comma-separated")
      ->check(non_empty_value())
      ->capture_default_str();
  cmd->add_flag("!--no-baseline", a->baseline, "With --reduction, skip the unreduced comparison run");
  // Defaults of the sweep settings: the scenario's `critical_speed` section, else
  // engine::CriticalSpeedSettings (80..300 km/h in 20 km/h steps, 6 s, 8 / 0.5 mm, 0.5 mm, 0.5 m/s^2).
  cmd->add_option("--v-min", a->v_min_kmh, "Lowest speed [km/h] (default: scenario, else 80)");
  cmd->add_option("--v-max", a->v_max_kmh, "Highest speed, also the ramping start speed [km/h] (default: scenario, else 300)");
  cmd->add_option("--v-step", a->v_step_kmh, "Speed step of the bifurcation sweep [km/h] (default: scenario, else 20)");
  cmd->add_option("--duration", a->duration, "Simulated time per sweep point [s] (default: scenario, else 6)")
      ->check(number_range(engine::kDurationRange.lo, engine::kDurationRange.hi));
  cmd->add_option("--disturbance", a->large,
                  "Large initial lateral shift (down branch, ramping) [mm] (default: scenario, else 8)")
      ->check(number_range(engine::kDisturbanceRangeMm.lo, engine::kDisturbanceRangeMm.hi));
  cmd->add_option("--small-disturbance", a->small, "Small initial lateral shift (up branch) [mm] (default: scenario, else 0.5)")
      ->check(number_range(engine::kSmallDisturbanceRangeMm.lo, engine::kSmallDisturbanceRangeMm.hi));
  cmd->add_option("--threshold", a->threshold, "Settled amplitude that counts as hunting [mm] (default: scenario, else 0.5)")
      ->check(number_range(engine::kThresholdRangeMm.lo, engine::kThresholdRangeMm.hi));
  cmd->add_option("--deceleration", a->deceleration, "Ramping deceleration [m/s^2] (default: scenario, else 0.5)")
      ->check(number_range(engine::kDecelerationRange.lo, engine::kDecelerationRange.hi));
  cmd->add_flag("!--no-up-branch", a->up_branch, "Sweep only the strongly disturbed (down) branch");
  auto* on = cmd->add_flag("--continuation", a->continuation_on,
                           "Path following on the down branch: below its lowest hunting speed, each speed starts "
                           "from the limit cycle of the one above, down to the fold (default: the scenario's "
                           "setting, else off)");
  cmd->add_flag("--no-continuation", a->continuation_off, "Every down-branch speed from the large disturbance")
      ->excludes(on);
  cmd->add_option("--threads", a->threads, "Worker threads per process (0: all cores)")
      ->check(CLI::Range(0, engine::kMaxThreads))
      ->capture_default_str();
  cmd->callback([a, cmd, &run] {
    for (const char* opt : {"--v-step", "--duration", "--small-disturbance", "--no-up-branch", "--continuation",
                            "--no-continuation", "--deceleration", "--models", "--no-baseline"})
      if (cmd->count(opt) > 0) a->given.emplace_back(opt);
    run = [a] { return run_critical_speed(*a); };
  });
}

}  // namespace railsim::cli
