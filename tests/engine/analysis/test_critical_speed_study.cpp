// Critical-speed studies (engine/analysis/critical_speed_study.cpp) without the
// program, on the single wheelset of physics-reference.md 8.1 (linear critical
// speed 45.59 m/s = 164.1 km/h): the settings echoed as given, the reduction
// baseline (the unreduced run at the reference speed, the change recomputed from
// the two analyses, the reduced V_L equal to an independent eigenvalue search),
// and one analysis per contact model on the S1002 wheelset (saturation does not
// change the linearised creep forces, so linear and linear_sat share V_L).
#include <catch2/catch.hpp>

#include <cmath>

#include "contact/reduction.hpp"
#include "core/errors.hpp"
#include "engine/analysis/critical_speed_study.hpp"
#include "json_support.hpp"
#include "test_support.hpp"

using namespace railsim;
using namespace railsim::engine;

namespace {

Scenario wheelset() { return load_scenario(test::data_path("scenarios/single_wheelset_flange.yaml")); }

CriticalSpeedStudySettings short_sweep() {
  CriticalSpeedStudySettings s;
  s.v_min = 160.0 / 3.6;
  s.v_max = 170.0 / 3.6;
  s.v_step = 10.0 / 3.6;
  s.duration = 2.0;
  s.up_branch = false;
  s.threads = 2;
  return s;
}

}  // namespace

TEST_CASE("critical-speed study: SI settings, engine options and the record as given", "[critical_speed_study]") {
  CriticalSpeedStudySettings s;
  // Values whose round trip through SI is not exact in binary (7.4 / 3.6 * 3.6 != 7.4).
  s.v_min = 7.4 / 3.6;
  s.v_max = 183.7 / 3.6;
  s.v_step = 3.7 / 3.6;
  s.large_disturbance = 0.015 * 1e-3;
  s.small_disturbance = 0.009 * 1e-3;
  s.threshold = 0.5e-3;
  REQUIRE(s.v_min * 3.6 != 7.4);
  REQUIRE(s.large_disturbance * 1e3 != 0.015);
  const BifurcationOptions b = bifurcation_options(s);
  CHECK(b.v_min == s.v_min);
  CHECK(b.large_disturbance == s.large_disturbance);
  CHECK(b.use_mpi);
  const RampingOptions r = ramping_options(s);
  CHECK(r.v_end == s.v_min);
  CHECK(linear_bracket_low(s) == 1.0);  // 0.25 v_min below 1 m/s
  CHECK(linear_bracket_high(s) == Approx(1.5 * 183.7 / 3.6));
  const Scenario sc = wheelset();
  CriticalSpeedOutcome o;
  o.critical = o.linear = std::nan("");
  const results::Json j = critical_speed_summary(sc, s, o);
  const auto n = nlohmann::json::parse(j.dump());
  CHECK(n["speed_range_kmh"][0].get<double>() == 7.4);
  CHECK(n["speed_range_kmh"][1].get<double>() == 183.7);
  CHECK(n["settings"]["v_step_kmh"].get<double>() == 3.7);
  CHECK(n["settings"]["large_disturbance_mm"].get<double>() == 0.015);
  CHECK(n["settings"]["small_disturbance_mm"].get<double>() == 0.009);
  CHECK(n["critical_speed_kmh"].is_null());
  CHECK(n["method"] == "bifurcation");
  CHECK(parse_critical_speed_method("ramping", "--method") == CriticalSpeedMethod::ramping);
  CHECK_THROWS_AS(parse_critical_speed_method("sweep", "--method"), InputError);
}

TEST_CASE("critical-speed study: the reduction baseline", "[critical_speed_study]") {
  const Scenario base = wheelset();
  const CriticalSpeedStudySettings s = short_sweep();
  const std::string dir = test::temp_dir("cs_study_baseline");
  const Scenario reduced = with_reduction(base, contact::parse_reduction_spec("0.6", "test"), "test");
  const CriticalSpeedWithBaseline r = critical_speed_with_baseline(reduced, "", s, true, true, dir);
  REQUIRE(r.with_baseline);
  CHECK(r.unreduced.linear * 3.6 == Approx(164.1).margin(0.3));  // physics-reference.md 8.1
  CHECK(r.outcome.linear == Approx(linear_critical_speed(reduced, linear_bracket_low(s), linear_bracket_high(s))));
  CHECK(r.outcome.linear != Approx(r.unreduced.linear).epsilon(1e-3));  // the reduction reached the creep forces
  CHECK(r.linear_change_percent ==
        Approx(100.0 * (r.outcome.linear - r.unreduced.linear) / r.unreduced.linear).margin(1e-9));
  const bool both = !std::isnan(r.outcome.critical) && !std::isnan(r.unreduced.critical);
  CHECK(std::isnan(r.change_percent) == !both);
  const auto n = nlohmann::json::parse(r.summary.dump());
  REQUIRE(n.contains("unreduced"));
  CHECK(n["unreduced"]["linear_critical_speed_kmh"].get<double>() == Approx(r.unreduced.linear * 3.6));
  CHECK(r.outcome.bifurcation.points.size() == 2);  // two speeds, down branch only
  CHECK(r.unreduced.bifurcation.points.size() == 2);

  // Factors of 1: nothing to compare with; no baseline without a --reduction.
  const Scenario one = with_reduction(base, contact::parse_reduction_spec("1", "test"), "test");
  CriticalSpeedStudySettings ramp = s;
  ramp.method = CriticalSpeedMethod::ramping;
  ramp.ramp_start = 170.0 / 3.6;
  ramp.v_min = 160.0 / 3.6;
  ramp.deceleration = 5.0;
  ramp.ramp_disturbance = 1e-3;
  const CriticalSpeedWithBaseline r1 = critical_speed_with_baseline(one, "", ramp, true, true, dir + "/one");
  CHECK_FALSE(r1.with_baseline);
  CHECK(std::isnan(r1.linear_change_percent));
  CHECK_FALSE(r1.outcome.ramping.time.empty());
}

TEST_CASE("critical-speed study: one analysis per contact model", "[critical_speed_study]") {
  // The S1002 wheelset (Hertz patches from its contact table): every registered law applies.
  const Scenario base = load_scenario(test::data_path("scenarios/single_wheelset_s1002.yaml"));
  const std::string dir = test::temp_dir("cs_study_models");
  CriticalSpeedStudySettings s = short_sweep();
  s.v_min = 330.0 / 3.6;  // linear bracket up to 1.5 v_max = 510 km/h: V_L (model linear) is about 503 km/h
  s.v_max = 340.0 / 3.6;
  s.duration = 1.0;
  const auto runs = critical_speed_per_model(base, {"linear", "linear_sat"}, s, dir);
  REQUIRE(runs.size() == 2);
  CHECK(runs[0].scenario.model.coupling.options().tangential == "linear");
  CHECK(runs[1].scenario.model.coupling.options().tangential == "linear_sat");
  CHECK(runs[0].outcome.linear ==
        Approx(linear_critical_speed(runs[0].scenario, linear_bracket_low(s), linear_bracket_high(s))));
  // Saturation does not change the creep forces linearised at zero creepage: the same V_L.
  REQUIRE(std::isfinite(runs[0].outcome.linear));
  CHECK(runs[0].outcome.linear == Approx(runs[1].outcome.linear).epsilon(1e-3));
  CHECK(runs[1].outcome.bifurcation.points.size() == 2);
  const auto n = nlohmann::json::parse(runs[1].summary.dump());
  CHECK(n["contact_model"] == "linear_sat");
}
