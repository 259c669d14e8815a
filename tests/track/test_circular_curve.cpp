// Circular curve: every point lies on the circle of radius R about the centre
// (0, 1/kappa) of the segment-start frame, the chord is 2R sin(theta/2), and the
// small-angle branch joins the closed form smoothly.
#include <catch2/catch.hpp>

#include <cmath>

#include "track/circular_curve.hpp"

using namespace railsim::track;

TEST_CASE("circular curve points lie on the circle", "[tracks][circular]") {
  for (double kappa : {1.0 / 300, -1.0 / 300, 1.0 / 5000, -1.0 / 25}) {
    const double R = 1.0 / std::abs(kappa);
    const CircularCurve c(500.0, kappa, 0.0);
    for (double u = 0; u <= 500; u += 37.5) {
      const auto p = c.offset(u);
      CHECK(std::hypot(p[0], p[1] - 1.0 / kappa) == Approx(R).epsilon(1e-13));
      CHECK(std::hypot(p[0], p[1]) == Approx(2 * R * std::abs(std::sin(0.5 * kappa * u))).margin(1e-10));
      CHECK(c.heading_change(u) == Approx(kappa * u).margin(1e-15));
    }
  }
}

TEST_CASE("arc offset is continuous through the small-angle branch", "[tracks][circular]") {
  const double u = 10.0;
  for (double a : {0.99e-8, 1.01e-8}) {
    const double kappa = a / u;
    const auto p = arc_offset(kappa, u);
    CHECK(p[0] == Approx(u).epsilon(1e-15));
    CHECK(p[1] == Approx(0.5 * kappa * u * u).epsilon(1e-7));
  }
  const auto z = arc_offset(0.0, 7.0);
  CHECK(z[0] == 7.0);
  CHECK(z[1] == 0.0);
}
