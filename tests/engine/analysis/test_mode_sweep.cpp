// Mode sweep (engine/analysis/mode_sweep.cpp) on the single wheelset of
// physics-reference.md 8.1: the linear critical speed 45.59 m/s = 164.1 km/h,
// and the least damped mode's real part changing sign there (Hopf point).
#include <catch2/catch.hpp>

#include "engine/analysis/mode_sweep.hpp"
#include "test_support.hpp"

using namespace railsim::engine;

TEST_CASE("mode sweep: least damped mode crosses zero at the linear critical speed", "[mode_sweep]") {
  const Scenario sc = load_scenario(railsim::test::data_path("scenarios/single_wheelset_flange.yaml"));
  const std::vector<double> speeds = {150.0 / 3.6, 160.0 / 3.6, 170.0 / 3.6, 180.0 / 3.6};
  const ModeSweep r = mode_sweep(sc, speeds, 3, speeds.front(), speeds.back());
  REQUIRE(r.modes.size() == speeds.size());
  CHECK(r.linear_critical_speed * 3.6 == Approx(164.1).margin(0.3));
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    REQUIRE_FALSE(r.modes[i].empty());
    CHECK(r.modes[i].size() <= 3);
    const double sigma = r.modes[i][0].eigenvalue.real();
    if (speeds[i] < r.linear_critical_speed) CHECK(sigma < 0.0);
    if (speeds[i] > r.linear_critical_speed) CHECK(sigma > 0.0);
    for (std::size_t k = 1; k < r.modes[i].size(); ++k)  // ranked by decreasing real part
      CHECK(r.modes[i][k].eigenvalue.real() <= r.modes[i][k - 1].eigenvalue.real());
  }
}
