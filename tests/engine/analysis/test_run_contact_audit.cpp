// The contact audit of a run (engine/analysis/run_contact_audit.hpp, through
// engine::run_scenario as `railsim run --contact-audit N` calls it): the audit
// solves the run's own sampled states, its reference is the MIM solution of
// those states (a direct MIM call on each gives the same forces), the run's
// model re-solved reproduces what the run used, the table (CSV) holds every
// state x model with the errors against the reference, the summary's verdict
// follows from the table, and the model on the geometry's coefficients
// ("coefficients") is re-solved with the run's law. Short runs and a coarse reference grid keep it
// quick (the physics of the errors is tested in tests/contact/test_contact_audit.cpp).
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <set>

#include "contact/registry.hpp"
#include "core/errors.hpp"
#include "engine/analysis/scenario_run.hpp"
#include "engine/io/scenario.hpp"
#include "json_support.hpp"
#include "results/csv_writer.hpp"
#include "test_support.hpp"

using namespace railsim;
using namespace railsim::engine;

namespace {
constexpr int kGrid = 16;  // coarse reference: the test checks the plumbing, not MIM's accuracy

Scenario coach(double duration) {
  Scenario sc = load_scenario(test::source_path("scenarios/manchester_coach_critical_speed.yaml"));
  sc.duration = duration;
  for (const auto& b : sc.model.bodies) sc.x0[b.q_index[kLat]] += 0.004;  // across the rails
  return sc;
}
}  // namespace

TEST_CASE("contact audit of a run: reference, reproduction, table and verdict", "[analysis][audit]") {
  const std::string out = test::temp_dir("run_contact_audit");
  ScenarioRunOptions o;
  o.out_dir = out;
  o.contact_audit.samples = 14;
  o.contact_audit.mim_grid = kGrid;
  o.contact_audit.threads = 2;
  o.contact_audit.tolerance = 0.05;
  const ScenarioRunResult r = run_scenario(coach(0.3), o);
  REQUIRE(r.audited);
  const RunContactAudit& a = r.contact_audit;
  REQUIRE(a.states.size() == 14);
  CHECK(a.recorded_rows == r.rows);
  CHECK(a.run_model == "chopaya");
  // The run's model re-solved on the sampled inputs gives exactly what the run used.
  CHECK(a.reproduction == 0.0);
  // The reference is MIM on the states: a direct call agrees.
  const auto mim = contact::make_tangential_model("mim", {kGrid, 1e-6, ""});
  const auto ws = mim->make_workspace();
  for (std::size_t s = 0; s < a.states.size(); ++s) {
    REQUIRE(a.result.audited[s]);
    const auto f = mim->solve(a.states[s].input, ws.get());
    const double muN = a.states[s].input.material.mu * a.states[s].input.patch.Fz;
    CHECK(std::abs(f.Fx - a.result.reference[s].Fx) <= 1e-9 * muN);
    CHECK(std::abs(f.Fy - a.result.reference[s].Fy) <= 1e-9 * muN);
    CHECK(std::abs(f.Mz - a.result.reference[s].Mz) <= 1e-9 * muN * a.states[s].input.patch.b);
  }
  // Every registered model compared by default is audited.
  std::size_t expected = 0;
  for (const auto& e : contact::tangential_models()) expected += e.compared_by_default() ? 1 : 0;
  REQUIRE(a.result.models.size() == expected);

  // The table: one row per state x model, errors recomputed from its own columns.
  const auto csv = results::read_csv(out + "/contact_audit.csv");
  REQUIRE(csv.rows.size() == a.states.size() * a.result.models.size());
  std::set<std::string> models;
  for (std::size_t i = 0; i < csv.rows.size(); ++i) {
    models.insert(csv.rows[i][csv.column("model")]);
    const double e = std::hypot(csv.number(i, "Fx") - csv.number(i, "Fx_mim"), csv.number(i, "Fy") - csv.number(i, "Fy_mim")) /
                     (csv.number(i, "mu") * csv.number(i, "Fz"));
    CHECK(csv.number(i, "error_pct_mu_Fz") == Approx(100.0 * e).epsilon(1e-6).margin(1e-6));
    CHECK(csv.number(i, "time_us") > 0.0);
  }
  CHECK(models.size() == a.result.models.size());

  // The summary: per model statistics of the table, the verdict from them.
  const auto js = test::read_json(out + "/summary.json");
  const auto& ca = js["contact_audit"];
  // The summary written before the audit (the run's verdict, the audit marked running) is replaced by the whole one.
  CHECK_FALSE(ca.contains("status"));
  CHECK(ca["samples"].get<long>() == 14);
  CHECK(ca["run_model"] == "chopaya");
  CHECK(ca["tolerance_pct"].get<double>() == Approx(5.0));
  std::string cheapest;
  double cheapest_cost = INFINITY, best_error = INFINITY, run_error = NAN;
  std::string best;
  for (const auto& m : ca["models"]) {
    double mx = 0.0;
    for (std::size_t i = 0; i < csv.rows.size(); ++i)
      if (csv.rows[i][csv.column("model")] == m["model"].get<std::string>())
        mx = std::max(mx, csv.number(i, "error_pct_mu_Fz"));
    CHECK(m["max_error_pct"].get<double>() == Approx(mx).epsilon(1e-6));
    const bool meets = m["max_error_pct"].get<double>() <= 5.0 && m["failed"].get<long>() == 0;
    CHECK(m["meets_tolerance"].get<bool>() == meets);
    const double cost = m["median_cost_us"].get<double>();
    if (meets && cost < cheapest_cost) cheapest_cost = cost, cheapest = m["model"].get<std::string>();
    if (mx < best_error) best_error = mx, best = m["model"].get<std::string>();
    if (m["model"] == "chopaya") run_error = mx;
  }
  CHECK(ca["cheapest_meeting_tolerance"] == cheapest);
  bool ladder = false;
  for (const auto& e : ca["cheapest_by_tolerance"])
    if (e["tolerance_pct"].get<double>() == 5.0) {
      ladder = true;
      CHECK(e["cheapest"] == cheapest);
    }
  CHECK(ladder);
  CHECK(ca["most_accurate"] == best);
  CHECK(ca["run_model_meets_tolerance"].get<bool>() == (run_error <= 5.0));
  CHECK(std::filesystem::exists(out + "/contact_audit.png.json"));
}

TEST_CASE("contact audit of a run: the model on the geometry's coefficients is re-solved, bad options are named",
          "[analysis][audit][input]") {
  // Kalker's coefficients from the RSGEO table with SHE saturation (model
  // "coefficients", saturation she): audited with the run's law and the
  // coefficients each recorded input carries, so it reproduces the run exactly.
  Scenario sc = load_scenario(test::source_path("scenarios/cooperrider_car.yaml"));
  sc.duration = 0.1;
  ScenarioRunOptions o;
  o.contact_audit.samples = 6;
  o.contact_audit.mim_grid = kGrid;
  const ScenarioRunResult r = run_scenario(sc, o);
  REQUIRE(r.audited);
  const auto& a = r.contact_audit;
  CHECK(a.run_model == "coefficients");
  const int k = a.result.find(a.run_model);
  REQUIRE(k >= 0);
  CHECK(std::isfinite(a.result.models[static_cast<std::size_t>(k)].median_cost_ns));
  CHECK(a.reproduction == 0.0);
  std::size_t with_table_coefficients = 0;
  for (std::size_t s = 0; s < a.states.size(); ++s) {
    const auto& f = a.result.forces[static_cast<std::size_t>(k)][s];
    CHECK(f.Fx == a.states[s].forces.Fx);
    CHECK(f.Fy == a.states[s].forces.Fy);
    with_table_coefficients += a.states[s].input.coefficients.C11 > 0 ? 1 : 0;
    const double e = std::hypot(f.Fx - a.result.reference[s].Fx, f.Fy - a.result.reference[s].Fy) /
                     (a.states[s].input.material.mu * a.states[s].input.patch.Fz);
    CHECK(a.result.errors[static_cast<std::size_t>(k)][s] == Approx(e).epsilon(1e-12));
  }
  CHECK(with_table_coefficients == a.states.size());
  // Only the run's model beyond the ones compared by default.
  std::size_t expected = 1;
  for (const auto& e : contact::tangential_models()) expected += e.compared_by_default() ? 1 : 0;
  CHECK(a.result.models.size() == expected);

  // Bad options fail before the run.
  ScenarioRunOptions bad;
  bad.contact_audit.samples = 10001;
  CHECK_THROWS_WITH(run_scenario(sc, bad), Catch::Contains("[1, 10000]"));
  bad.contact_audit.samples = -1;
  CHECK_THROWS_WITH(run_scenario(sc, bad), Catch::Contains("[1, 10000]"));
  bad.contact_audit.samples = 5;
  bad.contact_audit.tolerance = std::nan("");
  CHECK_THROWS_WITH(run_scenario(sc, bad), Catch::Contains("tolerance"));
  bad.contact_audit.tolerance = 0.0;
  CHECK_THROWS_WITH(run_scenario(sc, bad), Catch::Contains("tolerance"));
  // Prescribed coefficients without a patch shape: nothing to solve, said so
  // before the run (no channels written: the check used to come after it).
  Scenario single = load_scenario(test::source_path("scenarios/single_wheelset.yaml"));
  single.duration = 0.05;
  ScenarioRunOptions so;
  so.contact_audit.samples = 4;
  so.contact_audit.mim_grid = kGrid;
  so.out_dir = test::temp_dir("audit_no_patch");
  CHECK_THROWS_WITH(run_scenario(single, so), Catch::Contains("without a patch shape"));
  CHECK_FALSE(std::filesystem::exists(so.out_dir + "/channels.csv"));
}
