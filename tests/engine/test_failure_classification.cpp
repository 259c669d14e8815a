// Numerical failure is not derailment (issue 14): a wheelset that climbs past
// its flange is a derailment (physics: status "derailed", running safety
// FAIL, exit 0 with the verdict); a run stopped by the integrator or by a
// state no physics reaches (a wheelset beyond a flangeless geometry's range,
// an explicit method on the stiff contact) is a numerical failure (exit 3,
// time, place, model, last step) with no running-safety verdict.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "core/errors.hpp"
#include "engine/io/scenario.hpp"
#include "engine/simulation.hpp"
#include "json_support.hpp"
#include "test_support.hpp"

using namespace railsim;

TEST_CASE("a wheel climbing its flange is reported as a derailment, with the running safety failed",
          "[engine][cli][derailment]") {
  const std::string out = test::temp_dir("flange_climb");
  const auto r = test::run_railsim("run " + test::data_path("engine/flange_climb.yaml") + " --out " + out);
  INFO(r.output);
  CHECK(r.exit_code == 0);
  const auto js = test::read_json(out + "/summary.json");
  CHECK(js["status"] == "derailed");
  const std::string what = js["derailment"].get<std::string>();
  CHECK(what.find("climbed past its flange") != std::string::npos);
  CHECK(what.find("ws1") != std::string::npos);
  CHECK(what.find("t = ") != std::string::npos);
  CHECK(what.find("lateral wheelset") != std::string::npos);
  CHECK(js["running_safety"]["pass"] == false);
  // Before it left the rail the wheel was above Nadal's limit, (tan g - mu) / (1 + mu tan g)
  // with mu = 0.5 at the geometry's flange angle.
  const auto& yq = js["running_safety"]["wheelsets"][0]["wheels"]["right"]["yq_instantaneous"];
  const double tg = std::tan(js["running_safety"]["flange_angle_deg"].get<double>() * M_PI / 180.0);
  CHECK(yq["nadal_limit"].get<double>() == Approx((tg - 0.5) / (1.0 + 0.5 * tg)).epsilon(1e-9));
  CHECK(yq["max"].get<double>() > yq["nadal_limit"].get<double>());
}

TEST_CASE("the same scene stopped by the integrator is a numerical failure, with no verdict",
          "[engine][cli][derailment]") {
  // An absurd step budget (20 steps per output interval of 0.5 s with steps of
  // at most 2 ms): the integrator stops at its first output, long before the defect.
  const std::string out = test::temp_dir("flange_climb_explicit");
  const auto r = test::run_railsim("run " + test::data_path("engine/flange_climb.yaml") + " --out " + out +
                                   " --set output_interval=0.5 --set integrator.max_steps=20");
  INFO(r.output);
  CHECK(r.exit_code == 3);
  const auto js = test::read_json(out + "/summary.json");
  CHECK(js["status"] == "failed");
  CHECK(js["running_safety"].is_string());  // "not evaluated: the run failed numerically"
  CHECK(js["running_safety"].get<std::string>().find("not evaluated") != std::string::npos);
  CHECK(!js.contains("derailment"));
  const std::string err = js["error"].get<std::string>();
  CHECK(err.find("t = ") != std::string::npos);
  CHECK(err.find("last step") != std::string::npos);
}

TEST_CASE("a wheelset beyond a flangeless geometry's range is a numerical failure, not a derailment",
          "[engine][cli][derailment]") {
  // Conical wheels (no flange) above the critical speed: the oscillation grows
  // until the wheelset leaves the 5 mm range.
  const std::string out = test::temp_dir("unstable_conical");
  const auto r = test::run_railsim("run " + test::data_path("engine/unstable_scenario.yaml") + " --out " + out);
  INFO(r.output);
  CHECK(r.exit_code == 3);
  const auto js = test::read_json(out + "/summary.json");
  CHECK(js["status"] == "failed");
  CHECK(js["running_safety"].is_string());
  CHECK(js["error"].get<std::string>().find("not a derailment") != std::string::npos);
}

TEST_CASE("leaving the model's range is its own kind of failure, told apart from the integrator's",
          "[engine][derailment]") {
  // The conical wheelset above its critical speed (the case above): the motion grows until the wheelset
  // leaves the flangeless geometry's range. A run reports it as a numerical failure (above); an analysis can
  // tell that the motion got there (ModelRangeError), not the integrator. The same scene with an integrator
  // allowed three steps stops as a plain numerical failure.
  engine::Scenario sc = engine::load_scenario(test::data_path("engine/unstable_scenario.yaml"));
  CHECK_THROWS_AS(engine::simulate(sc.model, sc.integrator, sc.x0, sc.duration, sc.output_interval), ModelRangeError);
  sc.integrator.max_steps = 3;
  try {
    engine::simulate(sc.model, sc.integrator, sc.x0, sc.duration, sc.output_interval);
    FAIL("the run should stop");
  } catch (const ModelRangeError&) {
    FAIL("an integrator out of steps is not the model's range");
  } catch (const DerailmentError&) {
    FAIL("an integrator out of steps is not a derailment");
  } catch (const NumericalError& e) {
    CHECK(std::string(e.what()).find("max_steps") != std::string::npos);
  }
}
