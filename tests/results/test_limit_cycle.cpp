// Settled limit-cycle amplitude: the amplitude after transients, not the first peak.
#include <catch2/catch.hpp>

#include <cmath>

#include "results/limit_cycle.hpp"

using namespace railsim::results;

TEST_CASE("settled amplitude ignores a large decaying transient", "[results]") {
  std::vector<double> t, y;
  for (int i = 0; i <= 200000; ++i) {
    const double ti = i * 1e-4;  // 20 s
    t.push_back(ti);
    // 4 mm limit cycle at 2.5 Hz plus a 10 mm transient decaying at 1/s, offset 0.5 mm
    y.push_back(0.5e-3 + 4e-3 * std::sin(2 * M_PI * 2.5 * ti) + 10e-3 * std::exp(-1.0 * ti) * std::cos(2 * M_PI * 1.7 * ti));
  }
  const auto lc = settled_amplitude(t, y, 0.3);
  CHECK(lc.amplitude == Approx(4e-3).epsilon(0.01));
  CHECK(lc.frequency == Approx(2.5).epsilon(0.01));
  CHECK(lc.mean == Approx(0.5e-3).margin(5e-5));
  CHECK(std::fabs(lc.growth) < 0.02);
}

TEST_CASE("a decaying oscillation has negative growth and a small settled amplitude", "[results]") {
  std::vector<double> t, y;
  for (int i = 0; i <= 100000; ++i) {
    const double ti = i * 2e-4;  // 20 s
    t.push_back(ti);
    y.push_back(5e-3 * std::exp(-0.3 * ti) * std::sin(2 * M_PI * 3.0 * ti));
  }
  const auto lc = settled_amplitude(t, y, 0.3);
  CHECK(lc.growth < -0.2);
  CHECK(lc.amplitude < 5e-3 * std::exp(-0.3 * 13.0));
}

TEST_CASE("a signal at rest has zero amplitude", "[results]") {
  std::vector<double> t, y;
  for (int i = 0; i < 100; ++i) t.push_back(i), y.push_back(1.0);
  const auto lc = settled_amplitude(t, y);
  CHECK(lc.amplitude == 0.0);
  CHECK(lc.half_cycles == 0);
}
