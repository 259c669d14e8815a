// `railsim modes` through the railsim binary: the least damped mode of the
// single wheelset loses its damping at the Routh-Hurwitz critical speed
// (physics-reference.md 8.1: 45.59 m/s = 164.1 km/h), files, bad input.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

#include "json_support.hpp"
#include "results/csv_writer.hpp"
#include "test_support.hpp"

using railsim::test::run_railsim;

TEST_CASE("railsim modes: damping of the least damped mode changes sign at the critical speed", "[cli][modes]") {
  const std::string dir = railsim::test::temp_dir("cli_modes");
  const std::string scenario = railsim::test::data_path("scenarios/single_wheelset_flange.yaml");
  const auto r = run_railsim("modes '" + scenario + "' --v-min 100 --v-max 220 --v-step 10 --count 2 --out '" + dir + "'");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK(r.output.find("linear critical speed: 164.1 km/h") != std::string::npos);
  CHECK(std::filesystem::exists(dir + "/modes.png"));
  const auto t = railsim::results::read_csv(dir + "/modes.csv");
  REQUIRE(t.rows.size() == 13 * 2);
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    const double v = t.number(i, "speed_kmh"), zeta = t.number(i, "damping_ratio");
    if (t.number(i, "rank") != 1) continue;
    INFO("v = " << v << " km/h");
    if (v < 160) CHECK(zeta > 0);
    if (v > 170) CHECK(zeta < 0);
  }
  // Unstable already at --v-min (above 164.1 km/h): no critical speed in the range, only its bound.
  const auto above = run_railsim("modes '" + scenario + "' --v-min 180 --v-max 200 --v-step 10 --out '" + dir + "/above'");
  INFO(above.output);
  REQUIRE(above.exit_code == 0);
  CHECK(above.output.find("linear critical speed: at or below 180.0 km/h (unstable already at --v-min") !=
        std::string::npos);
  const auto js = railsim::test::read_json(dir + "/above/summary.json");
  CHECK(js["linear_critical_speed_kmh"].is_null());
  CHECK(js["unstable_at_v_min"] == true);
  CHECK(railsim::test::read_json(dir + "/summary.json")["unstable_at_v_min"] == false);
  CHECK(run_railsim("modes '" + scenario + "' --v-min 200 --v-max 100 --out '" + dir + "'").exit_code == 2);
  CHECK(run_railsim("modes '" + scenario + "' --count 0 --out '" + dir + "'").exit_code == 2);
}
