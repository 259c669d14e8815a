// `railsim compare-contact CASES.yaml --out DIR`: every tangential contact model
// against the exact solver, with its cost, on a file of contact cases (format of
// `railsim contact`, support_contact_cases.hpp). The comparison itself (reference,
// errors, cost, Pareto front, failure map) is engine/analysis/contact_comparison.hpp;
// this file chooses the models, writes the files and prints the table.
// Reference: MIM on --reference-grid elements, --reference-tolerance; errors written
// in percent.
//
// Outputs:
//   DIR/comparison.csv        one row per model and case: forces, reference forces,
//                             errors [%], validity flag, cost per call [us];
//   DIR/summary.json          per model: max / mean / RMS error of F, max errors of
//                             Fx, Fy, Mz, mean cost, Pareto flag, failure-map share;
//   DIR/speed_vs_accuracy.png max error of F over the cases against mean cost per
//                             call (log-log), one labelled point per model, the
//                             Pareto front as a step line;
//   DIR/failure_map.csv/.png  for each model, over a grid of creepage magnitude
//                             (log, in one direction) and spin phi [1/m] on the
//                             patch of one case: where the error of F exceeds 10 %.
// Model list: --models (comma-separated), default every registered model plus
// "mim_table" when its table is already in the cache (or --with-mim-table: build it).
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/support_option_checks.hpp"
#include "cli/support_contact_cases.hpp"
#include "contact/mim_table/mim_table.hpp"
#include "contact/reduction.hpp"
#include "contact/registry.hpp"
#include "core/errors.hpp"
#include "core/output_lock.hpp"
#include "engine/analysis/contact_comparison.hpp"
#include "results/chart.hpp"
#include "results/csv_writer.hpp"
#include "results/json_writer.hpp"
#include "results/pareto_front.hpp"

namespace railsim::cli {

namespace {

namespace fs = std::filesystem;
using results::Json;

constexpr const char* kMimTable = "mim_table";

struct CompareArgs {
  std::string cases;
  std::string out;
  std::string models;
  bool models_given = false;  // --models on the command line (an empty list is an error, not the default)
  std::string reduction;
  std::string cache_dir;
  std::string map_case;
  std::string map_direction = "lateral";
  int reference_grid = 60;
  double reference_tolerance = 1e-8;
  int map_points = 16;
  bool with_mim_table = false;
};

struct Candidate {
  std::string name;
  std::string description;
  std::unique_ptr<contact::TangentialModel> model;
  std::unique_ptr<contact::TangentialWorkspace> ws;
};

std::vector<std::string> split_names(const std::string& list) {
  std::vector<std::string> names;
  std::stringstream ss(list);
  for (std::string n; std::getline(ss, n, ',');) {
    n.erase(0, n.find_first_not_of(" \t"));
    n.erase(n.find_last_not_of(" \t") + 1);
    if (!n.empty()) names.push_back(n);
  }
  return names;
}

// The cached MIM table (standard spec) when present and valid; nullptr otherwise.
// With `build`, a missing or refused table is built (with progress on the log).
std::shared_ptr<const contact::MimTable> find_mim_table(const std::string& cache_dir, bool build, bool wanted) {
  const contact::MimTableSpec spec = contact::MimTableSpec::standard();
  if (build) {
    spdlog::info("mim_table: loading or building the standard table ({} MIM solves when missing)", spec.size());
    return contact::load_or_build_mim_table(spec, cache_dir, [](const std::string& m) { spdlog::info("{}", m); });
  }
  const std::string path = contact::mim_table_cache_path(spec, cache_dir);
  if (!fs::exists(path)) {
    if (wanted)
      throw InputError("--models: mim_table has no cached table (" + path + "); give --with-mim-table to build it (" +
                       std::to_string(spec.size()) + " MIM solves)");
    spdlog::info("mim_table: no cached table at {}; not compared (--with-mim-table builds it)", path);
    return nullptr;
  }
  try {
    return contact::MimTable::load(path, spec);
  } catch (const InputError& e) {
    if (wanted) throw InputError(std::string(e.what()) + "; give --with-mim-table to rebuild it");
    spdlog::warn("{}; mim_table not compared (--with-mim-table rebuilds it)", e.what());
    return nullptr;
  }
}

std::vector<Candidate> make_candidates(const CompareArgs& a) {
  std::vector<std::string> names = split_names(a.models);
  if (a.models_given && names.empty())
    throw InputError("--models '" + a.models + "': no model named (give a comma-separated list, or omit --models for "
                     "every registered model)");
  const bool explicit_list = !names.empty();
  if (!explicit_list)
    for (const auto& e : contact::tangential_models())
      if (e.compared_by_default()) names.emplace_back(e.name);  // mim_table: below, when cached
  std::set<std::string> seen;
  for (const auto& n : names)
    if (!seen.insert(n).second) throw InputError("--models: model '" + n + "' listed twice");
  // Validate every name before any expensive work (unknown names: InputError with the list).
  for (const auto& n : names) tangential_model_option("--models", n);
  const bool table_wanted = seen.count(kMimTable) > 0;
  std::vector<Candidate> out;
  for (const auto& n : names) {
    if (n == kMimTable) continue;
    Candidate c;
    c.name = n;
    c.description = contact::find_tangential_model(n).description;
    c.model = contact::make_tangential_model(n);
    c.ws = c.model->make_workspace();
    out.push_back(std::move(c));
  }
  if (table_wanted || (!explicit_list) || a.with_mim_table) {
    if (auto t = find_mim_table(a.cache_dir, a.with_mim_table, table_wanted)) {
      Candidate c;
      c.name = kMimTable;
      c.description = "cached table of exact MIM solutions, cubic Hermite interpolation";
      c.model = std::make_unique<contact::MimTableModel>(std::move(t));
      out.push_back(std::move(c));
    }
  }
  return out;
}

// --------------------------------------------------------------- failure map

void write_failure_map(const CompareArgs& a, const engine::ComparisonCase& base, const std::vector<Candidate>& models,
                       const engine::ContactComparison& r, const engine::ContactComparisonOptions& o, Json& summary) {
  const engine::FailureMapAxes& ax = r.map.axes;
  results::CsvWriter csv(a.out + "/failure_map.csv",
                         {"model", "creepage", "xi", "eta", "phi", "err_F_pct", "err_Mz_pct", "failed"});
  results::Chart chart;
  chart.title = "Where each model's error of F exceeds 10 % of MIM (grid " + std::to_string(a.reference_grid) +
                "); case '" + base.id + "', " + a.map_direction + " creepage";
  chart.xlabel = "creepage magnitude |(xi, eta)| [-] (" + a.map_direction + ")";
  chart.ylabel = "spin phi [1/m]";
  chart.logx = true;
  for (std::size_t m = 0; m < models.size(); ++m) {
    chart.panels.push_back(models[m].name);
    chart.series.push_back({m == 0 ? "error <= 10 %" : "", {}, {}, "markers", "tab:green", static_cast<int>(m)});
    chart.series.push_back({m == 0 ? "error > 10 %" : "", {}, {}, "crosses", "tab:red", static_cast<int>(m)});
  }
  chart.lines.push_back({ax.creepage_full_slip, "full slip of the cubic laws, 3 mu Fz / (G c^2 C)", "0.5", true});
  for (const auto& p : r.map.points) {
    auto& series = chart.series[2 * p.model + (p.failed ? 1 : 0)];
    series.x.push_back(p.creepage);
    series.y.push_back(p.creep.phi);
    csv.cell(models[p.model].name).cell(p.creepage).cell(p.creep.xi).cell(p.creep.eta).cell(p.creep.phi);
    csv.cell(100.0 * p.error.F).cell(100.0 * p.error.Mz).cell(p.failed).end_row();
  }
  csv.close();
  results::draw(chart, a.out + "/failure_map.png");
  Json m = Json::object();
  m.set("case", base.id);
  m.set("direction", a.map_direction);
  m.set("points_per_axis", a.map_points);
  m.set("creepage_range", Json::array().push(ax.creepage.front()).push(ax.creepage.back()));
  m.set("spin_range_1_per_m", Json::array().push(ax.spin.front()).push(ax.spin.back()));
  m.set("full_slip_creepage", ax.creepage_full_slip);
  m.set("spin_normalisation_1_per_m", ax.spin_unit);
  m.set("failure_threshold_pct", 100.0 * o.failure_threshold);
  m.set("wall_time_s", r.map.wall_time_s);
  m.set("axes", "x: |(xi, eta)| log-spaced from 0.03 to 3 times the full-slip creepage 3 mu Fz / (G c^2 C) "
                "(C = C11, C22 or their root mean square for the diagonal); y: phi from 0 to 2 mu Fz / (G c^3 C23)");
  summary.set("failure_map", m);
}

// --------------------------------------------------------------- main

void speed_accuracy_chart(const CompareArgs& a, const std::vector<Candidate>& models,
                          const std::vector<engine::ModelStats>& stats, const std::vector<bool>& front,
                          double reference_cost_us, double failure_threshold) {
  // Errors below 0.01 % are drawn at 0.01 % (log axis).
  constexpr double kFloorPct = 1e-2;
  results::Chart c;
  c.title = "Speed against accuracy: max error of F over the cases vs MIM (grid " +
            std::to_string(a.reference_grid) + ")";
  c.xlabel = "mean cost per call [us]";
  c.ylabel = "max over cases of |F - F_MIM| / |F_MIM| [%]";
  c.logx = c.logy = true;
  results::ChartSeries on{"on the Pareto front", {}, {}, "markers", "tab:blue"};
  results::ChartSeries off{"dominated", {}, {}, "markers", "tab:gray"};
  std::vector<double> cost, err;
  for (std::size_t m = 0; m < models.size(); ++m) {
    const double x = stats[m].mean_cost_us();
    const double y = std::max(100.0 * stats[m].max_F, kFloorPct);
    cost.push_back(x);
    err.push_back(y);
    (front[m] ? on : off).x.push_back(x);
    (front[m] ? on : off).y.push_back(y);
    c.annotations.push_back({models[m].name, {x, y}});
  }
  results::ChartSeries step{"Pareto front", {}, {}, "step", "tab:blue"};
  results::pareto_staircase(cost, err, front, step.x, step.y);
  c.series = {step, on, off};
  c.lines.push_back({reference_cost_us, "MIM reference (grid " + std::to_string(a.reference_grid) + ")", "0.5", true});
  c.lines.push_back({100.0 * failure_threshold, "10 %", "r", false});
  results::draw(c, a.out + "/speed_vs_accuracy.png");
}

int run_compare_contact(const CompareArgs& a) {
  // All input checks first: models, case file, options.
  std::vector<Candidate> models = make_candidates(a);
  if (models.empty()) throw InputError("--models: no model to compare");
  ContactCaseSet set = load_contact_cases(a.cases);
  if (!a.reduction.empty()) set_reduction(set, contact::parse_reduction(a.reduction, "--reduction"));
  engine::ContactComparisonOptions o;
  o.reference_grid = a.reference_grid;
  o.reference_tolerance = a.reference_tolerance;
  o.map_points = a.map_points;
  o.map_direction = engine::parse_creep_direction(a.map_direction, "--map-direction");
  if (!a.map_case.empty()) {
    bool found = false;
    std::string ids;
    for (std::size_t i = 0; i < set.cases.size(); ++i) {
      if (set.cases[i].id == a.map_case) o.map_case = i, found = true;
      ids += (ids.empty() ? "" : ", ") + set.cases[i].id;
    }
    if (!found) throw InputError("--map-case: no case '" + a.map_case + "' in " + a.cases + " (cases: " + ids + ")");
  }
  std::error_code ec;
  fs::create_directories(a.out, ec);
  if (ec) throw InputError("--out " + a.out + ": cannot create the folder (" + ec.message() + ")");
  const OutputLock lock(a.out, "compare-contact");  // one writer per output folder

  std::vector<engine::ComparisonCase> cases;
  for (const auto& c : set.cases) cases.push_back({c.id, c.input});
  std::vector<engine::ComparedModel> compared;
  for (const auto& m : models) compared.push_back({m.name, m.description, m.model.get(), m.ws.get()});
  const engine::ContactComparison r = engine::compare_contact_models(cases, compared, o);
  const double ref_cost_us = r.reference_median_cost_us;

  results::CsvWriter csv(a.out + "/comparison.csv",
                         {"model", "case", "a", "b", "Fz", "mu", "xi", "eta", "phi", "Fx", "Fy", "Mz", "Fx_ref",
                          "Fy_ref", "Mz_ref", "err_Fx_pct", "err_Fy_pct", "err_Mz_pct", "err_F_pct", "valid",
                          "reason", "cost_us", "ref_cost_us"});
  for (std::size_t m = 0; m < models.size(); ++m)
    for (std::size_t i = 0; i < cases.size(); ++i) {
      const auto& in = cases[i].input;
      const auto& f = r.results[m][i].forces;
      const auto& e = r.results[m][i].error;
      const auto& g = r.reference[i];
      const auto& p = in.patch;
      csv.cell(models[m].name).cell(cases[i].id).cell(p.a).cell(p.b).cell(p.Fz).cell(in.material.mu);
      csv.cell(in.creep.xi).cell(in.creep.eta).cell(in.creep.phi);
      csv.cell(f.Fx).cell(f.Fy).cell(f.Mz).cell(g.Fx).cell(g.Fy).cell(g.Mz);
      csv.cell(100.0 * e.Fx).cell(100.0 * e.Fy).cell(100.0 * e.Mz).cell(100.0 * e.F);
      csv.cell(f.valid).cell(f.reason).cell(r.results[m][i].cost_us).cell(r.reference_cost_us[i]).end_row();
    }
  csv.close();

  Json summary = Json::object();
  summary.set("cases_file", a.cases);
  summary.set("cases", static_cast<long>(set.cases.size()));
  summary.set("reduction", contact::describe_reduction(set.reduction));
  Json jr = Json::object();
  jr.set("model", "mim");
  jr.set("grid", a.reference_grid);
  jr.set("tolerance", a.reference_tolerance);
  jr.set("median_cost_us", ref_cost_us);
  jr.set("cost_note", "one timed call per case (no repetition); median over the cases");
  summary.set("reference", jr);
  summary.set("error_definition",
              "err_F = |(Fx, Fy) - (Fx_ref, Fy_ref)| / max(|(Fx_ref, Fy_ref)|, 1e-3 mu Fz); err_Fx, err_Fy: the "
              "component differences over the same scale; err_Mz = |Mz - Mz_ref| / max(|Mz_ref|, 1e-2 mu Fz "
              "sqrt(ab)); in percent; relative to the reference resultant, not to mu Fz");
  summary.set("pareto_criteria", "mean cost per call [us] over the cases and max err_F over the cases");
  if (r.has_map) write_failure_map(a, cases[o.map_case], models, r, o, summary);

  const std::vector<engine::ModelStats>& stats = r.stats;
  const std::vector<bool>& front = r.pareto_front;
  Json list = Json::array();
  for (std::size_t m = 0; m < models.size(); ++m) {
    const auto& s = stats[m];
    Json j = Json::object();
    j.set("model", models[m].name);
    j.set("description", models[m].description);
    j.set("max_err_F_pct", 100.0 * s.max_F);
    j.set("mean_err_F_pct", 100.0 * s.mean_F());
    j.set("rms_err_F_pct", 100.0 * s.rms_F());
    j.set("max_err_Fx_pct", 100.0 * s.max_Fx);
    j.set("max_err_Fy_pct", 100.0 * s.max_Fy);
    j.set("max_err_Mz_pct", 100.0 * s.max_Mz);
    j.set("mean_cost_us", s.mean_cost_us());
    j.set("max_cost_us", s.max_cost_us);
    j.set("invalid_cases", s.invalid);
    j.set("pareto_front", static_cast<bool>(front[m]));
    if (s.map_points > 0) j.set("failure_map_share", static_cast<double>(s.map_failures) / s.map_points);
    list.push(j);
  }
  summary.set("models", list);
  summary.write_file(a.out + "/summary.json");
  speed_accuracy_chart(a, models, stats, front, ref_cost_us, o.failure_threshold);

  std::printf("\nrailsim compare-contact: %zu cases of %s against MIM grid %d (median %.0f us/call)\n", set.cases.size(),
              a.cases.c_str(), a.reference_grid, ref_cost_us);
  std::printf("errors of F relative to |F_MIM| (max / mean over cases), of Mz relative to |Mz_MIM|\n\n");
  std::printf("%-18s %10s %10s %10s %12s %7s %8s %8s\n", "model", "max F %", "mean F %", "max Mz %", "cost us",
              "Pareto", "invalid", "map >10%");
  for (std::size_t m = 0; m < models.size(); ++m) {
    const auto& s = stats[m];
    char share[16] = "-";
    if (s.map_points > 0) std::snprintf(share, sizeof share, "%.0f%%", 100.0 * s.map_failures / s.map_points);
    std::printf("%-18s %10.2f %10.2f %10.1f %12.3g %7s %8d %8s\n", models[m].name.c_str(), 100.0 * s.max_F,
                100.0 * s.mean_F(), 100.0 * s.max_Mz, s.mean_cost_us(), front[m] ? "yes" : "", s.invalid, share);
  }
  std::printf("\nresults in %s (comparison.csv, summary.json, speed_vs_accuracy.png%s)\n\n", a.out.c_str(),
              r.has_map ? ", failure_map.csv, failure_map.png" : "");
  return kExitSuccess;
}

}  // namespace

void register_compare_contact(CLI::App& app, CommandRunner& run) {
  auto a = std::make_shared<CompareArgs>();
  auto* cmd = app.add_subcommand("compare-contact",
                                 "Every tangential contact model against the exact MIM solver: errors, cost, "
                                 "Pareto front and failure map");
  cmd->add_option("cases", a->cases, "Case file (YAML, the format of `railsim contact`)")->required();
  cmd->add_option("--out", a->out, "Output folder")->required();
  cmd->add_option("--models", a->models,
                  "Models to compare, comma-separated (default: all registered, plus mim_table when cached): " +
                      contact::tangential_model_names());
  cmd->add_option("--reference-grid", a->reference_grid, "MIM reference: elements across the minor axis")
      ->check(CLI::Range(8, 400))
      ->capture_default_str();
  cmd->add_option("--reference-tolerance", a->reference_tolerance, "MIM reference: tangential solver tolerance")
      ->check(number_range(1e-12, 1e-3))
      ->capture_default_str();
  cmd->add_option("--map-points", a->map_points,
                  "Failure map: points per axis (creepage x spin); 0 = no map")
      ->check(CLI::Range(0, 60))
      ->capture_default_str();
  cmd->add_option("--map-case", a->map_case, "Failure map: id of the case whose patch is used (default: the first)");
  cmd->add_option("--map-direction", a->map_direction, "Failure map: creepage direction")
      ->check(CLI::IsMember({"longitudinal", "lateral", "diagonal"}))
      ->capture_default_str();
  cmd->add_option("--reduction", a->reduction,
                  "Reduction of Kalker's coefficients (overrides the file): none, elastic_fe, elastoplastic_fe, "
                  "third_body, one number k, or k11,k22,k23");
  cmd->add_flag("--with-mim-table", a->with_mim_table,
                "Include mim_table, building its table when it is not cached (56,277 MIM solves)");
  cmd->add_option("--cache-dir", a->cache_dir,
                  "mim_table cache folder (default $RAILSIM_CACHE_DIR, $XDG_CACHE_HOME/railsim or ~/.cache/railsim)");
  cmd->callback([a, cmd, &run] {
    a->models_given = cmd->count("--models") > 0;
    run = [a] { return run_compare_contact(*a); };
  });
}

}  // namespace railsim::cli
