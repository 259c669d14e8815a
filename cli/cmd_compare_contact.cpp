// `railsim compare-contact CASES.yaml --out DIR`: every tangential contact model
// against the exact solver, with its cost, on a file of contact cases (format of
// `railsim contact`, support_contact_cases.hpp).
//
// Reference: the MIM boundary-element model ("mim", contact/mim/) on a fine grid
// (--reference-grid elements across the minor axis, --reference-tolerance).
// Errors: contact/force_error.hpp (fractions relative to the reference resultant
// |F_ref|, Mz relative to |Mz_ref|; written in percent). Cost per call:
// solve_timed (repeated calls, std::chrono::steady_clock, fastest window).
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
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/support_contact_cases.hpp"
#include "contact/force_error.hpp"
#include "contact/kalker_coefficients.hpp"
#include "contact/mim_table.hpp"
#include "contact/reduction.hpp"
#include "contact/registry.hpp"
#include "core/errors.hpp"
#include "results/chart.hpp"
#include "results/csv_writer.hpp"
#include "results/json_writer.hpp"
#include "results/pareto_front.hpp"

namespace railsim::cli {

namespace {

namespace fs = std::filesystem;
using results::Json;

constexpr double kFailureThreshold = 0.10;  // error of F above which the map marks a failure
constexpr const char* kMimTable = "mim_table";

struct CompareArgs {
  std::string cases;
  std::string out;
  std::string models;
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

struct ModelStats {
  double max_F = 0.0, sum_F = 0.0, sum_F2 = 0.0;
  double max_Fx = 0.0, max_Fy = 0.0, max_Mz = 0.0;
  double sum_cost_us = 0.0, max_cost_us = 0.0;
  int cases = 0, invalid = 0;
  int map_points = 0, map_failures = 0;
  double mean_F() const { return cases ? sum_F / cases : NAN; }
  double rms_F() const { return cases ? std::sqrt(sum_F2 / cases) : NAN; }
  double mean_cost_us() const { return cases ? sum_cost_us / cases : NAN; }
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
  const bool explicit_list = !names.empty();
  if (!explicit_list)
    for (const auto& e : contact::tangential_models())
      if (e.compared_by_default()) names.emplace_back(e.name);  // mim_table: below, when cached
  std::set<std::string> seen;
  for (const auto& n : names)
    if (!seen.insert(n).second) throw InputError("--models: model '" + n + "' listed twice");
  // Validate every name before any expensive work (unknown names: InputError with the list).
  for (const auto& n : names)
    if (n != kMimTable) {
      bool known = false;
      for (const auto& e : contact::tangential_models()) known = known || n == e.name;
      if (!known)
        throw InputError("--models: unknown contact model '" + n + "' (known models: " +
                         contact::tangential_model_names() + ")");
    }
  const bool table_wanted = seen.count(kMimTable) > 0;
  std::vector<Candidate> out;
  for (const auto& n : names) {
    if (n == kMimTable) continue;
    Candidate c;
    c.name = n;
    for (const auto& e : contact::tangential_models())
      if (n == e.name) c.description = e.description;
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

// One reference solve, timed once (the reference is slow; a single call suffices).
TimedForces reference_solve(const contact::TangentialModel& ref, const contact::ContactInput& in,
                            contact::TangentialWorkspace* ws, const std::string& what) {
  const auto t0 = std::chrono::steady_clock::now();
  TimedForces r;
  r.forces = ref.solve(in, ws);
  r.time_ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count();
  if (!r.forces.valid) spdlog::warn("reference for {}: {}", what, r.forces.reason);
  return r;
}

// --------------------------------------------------------------- failure map

struct MapAxes {
  std::vector<double> creepage;  // magnitude |(xi, eta)| [-], log-spaced
  std::vector<double> spin;      // phi [1/m], linear from 0
  double dir_x = 0.0, dir_y = 1.0;
  double creepage_full_slip = 0.0;  // 3 mu Fz / (G c^2 C): full slip of the cubic laws
  double spin_unit = 0.0;           // mu Fz / (G c^3 C23): normalised spin 1
};

MapAxes map_axes(const contact::ContactInput& in, const std::string& direction, int points) {
  MapAxes m;
  if (direction == "longitudinal") m.dir_x = 1.0, m.dir_y = 0.0;
  if (direction == "diagonal") m.dir_x = m.dir_y = std::sqrt(0.5);
  const auto& p = in.patch;
  const double c = std::sqrt(p.a * p.b);
  const double G = in.material.shear_modulus();
  const auto C = contact::kalker_coefficients(p.a / p.b, in.material.nu);
  const double C_dir = std::hypot(m.dir_x * C.C11, m.dir_y * C.C22);
  const double muFz = in.material.mu * p.Fz;
  m.creepage_full_slip = 3.0 * muFz / (G * c * c * C_dir);
  m.spin_unit = muFz / (G * c * c * c * C.C23);
  // Creepage from 3 % to 3x the full-slip creepage; spin up to normalised spin 2.
  const double lo = 0.03 * m.creepage_full_slip, hi = 3.0 * m.creepage_full_slip;
  for (int i = 0; i < points; ++i) {
    const double t = points > 1 ? static_cast<double>(i) / (points - 1) : 0.0;
    m.creepage.push_back(lo * std::pow(hi / lo, t));
    m.spin.push_back(2.0 * m.spin_unit * t);
  }
  return m;
}

void failure_map(const CompareArgs& a, const ContactCase& base, std::vector<Candidate>& models,
                 const contact::TangentialModel& ref, contact::TangentialWorkspace* ref_ws,
                 std::vector<ModelStats>& stats, Json& summary) {
  const MapAxes ax = map_axes(base.input, a.map_direction, a.map_points);
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
  const auto t0 = std::chrono::steady_clock::now();
  for (const double phi : ax.spin) {
    for (const double s : ax.creepage) {
      contact::ContactInput in = base.input;
      in.creep = {s * ax.dir_x, s * ax.dir_y, phi};
      const contact::ContactForces r = reference_solve(ref, in, ref_ws, "failure map").forces;
      for (std::size_t m = 0; m < models.size(); ++m) {
        const contact::ForceError e = contact::force_error(models[m].model->solve(in, models[m].ws.get()), r, in);
        const bool failed = !(e.F <= kFailureThreshold);
        ++stats[m].map_points;
        stats[m].map_failures += failed ? 1 : 0;
        auto& series = chart.series[2 * m + (failed ? 1 : 0)];
        series.x.push_back(s);
        series.y.push_back(phi);
        csv.cell(models[m].name).cell(s).cell(in.creep.xi).cell(in.creep.eta).cell(phi);
        csv.cell(100.0 * e.F).cell(100.0 * e.Mz).cell(failed).end_row();
      }
    }
  }
  results::draw(chart, a.out + "/failure_map.png");
  Json m = Json::object();
  m.set("case", base.id);
  m.set("direction", a.map_direction);
  m.set("points_per_axis", a.map_points);
  m.set("creepage_range", Json::array().push(ax.creepage.front()).push(ax.creepage.back()));
  m.set("spin_range_1_per_m", Json::array().push(ax.spin.front()).push(ax.spin.back()));
  m.set("full_slip_creepage", ax.creepage_full_slip);
  m.set("spin_normalisation_1_per_m", ax.spin_unit);
  m.set("failure_threshold_pct", 100.0 * kFailureThreshold);
  m.set("wall_time_s", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  m.set("axes", "x: |(xi, eta)| log-spaced from 0.03 to 3 times the full-slip creepage 3 mu Fz / (G c^2 C) "
                "(C = C11, C22 or their root mean square for the diagonal); y: phi from 0 to 2 mu Fz / (G c^3 C23)");
  summary.set("failure_map", m);
}

// --------------------------------------------------------------- main

void speed_accuracy_chart(const CompareArgs& a, const std::vector<Candidate>& models,
                          const std::vector<ModelStats>& stats, const std::vector<bool>& front,
                          double reference_cost_us) {
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
  c.lines.push_back({100.0 * kFailureThreshold, "10 %", "r", false});
  results::draw(c, a.out + "/speed_vs_accuracy.png");
}

int run_compare_contact(const CompareArgs& a) {
  // All input checks first: models, case file, options.
  std::vector<Candidate> models = make_candidates(a);
  if (models.empty()) throw InputError("--models: no model to compare");
  ContactCaseSet set = load_contact_cases(a.cases);
  if (!a.reduction.empty()) set_reduction(set, contact::parse_reduction(a.reduction, "--reduction"));
  const ContactCase* map_case = &set.cases.front();
  if (!a.map_case.empty()) {
    map_case = nullptr;
    std::string ids;
    for (const auto& c : set.cases) {
      if (c.id == a.map_case) map_case = &c;
      ids += (ids.empty() ? "" : ", ") + c.id;
    }
    if (!map_case) throw InputError("--map-case: no case '" + a.map_case + "' in " + a.cases + " (cases: " + ids + ")");
  }
  std::error_code ec;
  fs::create_directories(a.out, ec);
  if (ec) throw InputError("--out " + a.out + ": cannot create the folder (" + ec.message() + ")");

  contact::TangentialModelOptions ro;
  ro.grid = a.reference_grid;
  ro.tolerance = a.reference_tolerance;
  const auto ref = contact::make_tangential_model("mim", ro);
  const auto ref_ws = ref->make_workspace();

  // Reference solutions.
  spdlog::info("compare-contact: {} cases, reference MIM grid {} (tolerance {:g})", set.cases.size(),
               a.reference_grid, a.reference_tolerance);
  std::vector<TimedForces> reference;
  std::vector<double> ref_us;
  for (const auto& c : set.cases) {
    reference.push_back(reference_solve(*ref, c.input, ref_ws.get(), "case '" + c.id + "'"));
    ref_us.push_back(reference.back().time_ns * 1e-3);
  }
  // Median: the first solve on a new grid also sets up the solver.
  std::vector<double> sorted_us = ref_us;
  std::sort(sorted_us.begin(), sorted_us.end());
  const double ref_cost_us = sorted_us[sorted_us.size() / 2];

  results::CsvWriter csv(a.out + "/comparison.csv",
                         {"model", "case", "a", "b", "Fz", "mu", "xi", "eta", "phi", "Fx", "Fy", "Mz", "Fx_ref",
                          "Fy_ref", "Mz_ref", "err_Fx_pct", "err_Fy_pct", "err_Mz_pct", "err_F_pct", "valid",
                          "reason", "cost_us", "ref_cost_us"});
  std::vector<ModelStats> stats(models.size());
  for (std::size_t m = 0; m < models.size(); ++m) {
    spdlog::info("compare-contact: {} ({}/{})", models[m].name, m + 1, models.size());
    auto& st = stats[m];
    for (std::size_t i = 0; i < set.cases.size(); ++i) {
      const auto& c = set.cases[i];
      const TimedForces r = solve_timed(*models[m].model, c.input, models[m].ws.get());
      const auto& f = r.forces;
      const auto& g = reference[i].forces;
      const contact::ForceError e = contact::force_error(f, g, c.input);
      const double us = r.time_ns * 1e-3;
      ++st.cases;
      st.invalid += f.valid ? 0 : 1;
      st.max_F = std::max(st.max_F, e.F);
      st.sum_F += e.F;
      st.sum_F2 += e.F * e.F;
      st.max_Fx = std::max(st.max_Fx, e.Fx);
      st.max_Fy = std::max(st.max_Fy, e.Fy);
      st.max_Mz = std::max(st.max_Mz, e.Mz);
      st.sum_cost_us += us;
      st.max_cost_us = std::max(st.max_cost_us, us);
      const auto& p = c.input.patch;
      csv.cell(models[m].name).cell(c.id).cell(p.a).cell(p.b).cell(p.Fz).cell(c.input.material.mu);
      csv.cell(c.input.creep.xi).cell(c.input.creep.eta).cell(c.input.creep.phi);
      csv.cell(f.Fx).cell(f.Fy).cell(f.Mz).cell(g.Fx).cell(g.Fy).cell(g.Mz);
      csv.cell(100.0 * e.Fx).cell(100.0 * e.Fy).cell(100.0 * e.Mz).cell(100.0 * e.F);
      csv.cell(f.valid).cell(f.reason).cell(us).cell(ref_us[i]).end_row();
    }
  }

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

  if (a.map_points > 0) failure_map(a, *map_case, models, *ref, ref_ws.get(), stats, summary);

  std::vector<double> cost, err;
  for (const auto& s : stats) cost.push_back(s.mean_cost_us()), err.push_back(s.max_F);
  const std::vector<bool> front = results::pareto_front(cost, err);
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
  speed_accuracy_chart(a, models, stats, front, ref_cost_us);

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
  std::printf("\nresults in %s (comparison.csv, summary.json, speed_vs_accuracy.png, failure_map.png)\n\n",
              a.out.c_str());
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
      ->check(CLI::Range(1e-12, 1e-3))
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
  cmd->callback([a, &run] { run = [a] { return run_compare_contact(*a); }; });
}

}  // namespace railsim::cli
