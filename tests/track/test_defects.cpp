// Deterministic defects: the cosine bump A/2 (1 - cos 2 pi u / lambda) and the
// twist ramp, checked against their defining formulas, finite differences of
// the slopes, the rail convention of irregularity.hpp and the twist h / l_b.
#include <catch2/catch.hpp>

#include <cmath>

#include "track/defects.hpp"

using namespace railsim::track;

namespace {
IrregularityState eval(const IrregularityComponent& c, double s) {
  IrregularityState st;
  if (s >= c.s_begin() && s <= c.s_end()) c.add_to(s, st);
  return st;
}
}  // namespace

TEST_CASE("cosine bump: peak and zero ends and slope", "[tracks][defects]") {
  const CosineDefect d(Channel::lateral, 80.0, 20.0, 0.010);
  CHECK(d.s_begin() == 80.0);
  CHECK(d.s_end() == 100.0);
  CHECK(eval(d, 90.0)[Channel::lateral] == Approx(0.010).epsilon(1e-15));
  CHECK(eval(d, 85.0)[Channel::lateral] == Approx(0.005).epsilon(1e-14));
  CHECK(eval(d, 80.0)[Channel::lateral] == 0.0);
  CHECK(std::abs(eval(d, 100.0)[Channel::lateral]) < 1e-18);
  CHECK(eval(d, 79.0)[Channel::lateral] == 0.0);
  CHECK(eval(d, 101.0)[Channel::lateral] == 0.0);
  // Max slope A pi / lambda at the quarter points.
  CHECK(eval(d, 85.0).slope_of(Channel::lateral) == Approx(0.010 * M_PI / 20.0).epsilon(1e-14));
  for (double s = 80.5; s < 100; s += 1.7) {
    const double h = 1e-4;
    const double fd = (eval(d, s + h)[Channel::lateral] - eval(d, s - h)[Channel::lateral]) / (2 * h);
    CHECK(eval(d, s).slope_of(Channel::lateral) == Approx(fd).margin(1e-10));
  }
  // Only its own channel; lateral alignment moves both rails together.
  const IrregularityState st = eval(d, 90.0);
  CHECK(st[Channel::vertical] == 0.0);
  CHECK(st.left_lateral() == st.right_lateral());
  // Several periods.
  const CosineDefect p(Channel::vertical, 0.0, 5.0, -0.002, 3);
  CHECK(p.s_end() == 15.0);
  CHECK(eval(p, 12.5)[Channel::vertical] == Approx(-0.002).epsilon(1e-14));
}

TEST_CASE("twist defect: cross-level ramp h over the base length and back", "[tracks][defects]") {
  const double h = -0.018, base = 3.0;
  for (TwistRail rail : {TwistRail::both, TwistRail::left, TwistRail::right}) {
    const TwistDefect t(150.0, base, h, 1.0, rail);
    CHECK(t.twist() == Approx(-0.006).epsilon(1e-14));
    CHECK(t.s_end() == Approx(157.0).epsilon(1e-15));
    // Cross-level after the base length, on the hold, and back to zero.
    CHECK(eval(t, 153.0)[Channel::cross_level] == Approx(h).epsilon(1e-14));
    CHECK(eval(t, 153.5)[Channel::cross_level] == Approx(h).epsilon(1e-14));
    CHECK(eval(t, 151.5)[Channel::cross_level] == Approx(0.5 * h).epsilon(1e-14));
    CHECK(std::abs(eval(t, 157.0)[Channel::cross_level]) < 1e-15);
    // Twist measured over the base length: (c(s + l_b) - c(s)) / l_b.
    CHECK((eval(t, 153.0)[Channel::cross_level] - eval(t, 150.0)[Channel::cross_level]) / base ==
          Approx(t.twist()).epsilon(1e-13));
    CHECK(eval(t, 151.0).slope_of(Channel::cross_level) == Approx(h / base).epsilon(1e-14));
    CHECK(eval(t, 155.0).slope_of(Channel::cross_level) == Approx(-h / base).epsilon(1e-14));
    // Which rail moves: z_right - z_left = c in every case.
    const IrregularityState st = eval(t, 153.0);
    CHECK(st.right_vertical() - st.left_vertical() == Approx(h).epsilon(1e-14));
    if (rail == TwistRail::right) CHECK(st.left_vertical() == Approx(0.0).margin(1e-16));
    if (rail == TwistRail::left) CHECK(st.right_vertical() == Approx(0.0).margin(1e-16));
    if (rail == TwistRail::both) CHECK(st.left_vertical() == Approx(-0.5 * h).epsilon(1e-14));
  }
  // Cosine ramp: same end values, smooth start.
  const TwistDefect c(0.0, 4.0, 0.012, 0.0, TwistRail::both, TwistRamp::cosine);
  CHECK(eval(c, 4.0)[Channel::cross_level] == Approx(0.012).epsilon(1e-14));
  CHECK(eval(c, 2.0)[Channel::cross_level] == Approx(0.006).epsilon(1e-14));
  CHECK(eval(c, 0.0).slope_of(Channel::cross_level) == 0.0);
  CHECK(eval(c, 2.0).slope_of(Channel::cross_level) == Approx(0.012 * M_PI / 8.0).epsilon(1e-14));
}
