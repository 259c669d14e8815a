// Transition curves against closed forms: the clothoid's Fresnel power series
// (physics-reference §10.1 gives its first terms; general term
// x = sum (-1)^n s^(4n+1) / ((4n+1)(2n)! (2RL)^(2n)),
// y = sum (-1)^n s^(4n+3) / ((4n+3)(2n+1)! (2RL)^(2n+1))), the heading
// s^2/(2RL), the end heading L/(2R) shared by every shape, the Bloss curvature
// (1/R)(3u^2 - 2u^3) and the shift of the circle ~ L^2/(24R).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>

#include "track/clothoid.hpp"

using namespace railsim::track;

namespace {

std::array<double, 2> fresnel_series(double s, double R, double L) {
  const double a = 2.0 * R * L;
  double x = 0, y = 0, fact2n = 1;  // (2n)!
  for (int n = 0; n < 12; ++n) {
    if (n > 0) fact2n *= (2.0 * n - 1) * (2.0 * n);
    const double sign = n % 2 ? -1.0 : 1.0;
    x += sign * std::pow(s, 4 * n + 1) / ((4 * n + 1) * fact2n * std::pow(a, 2 * n));
    y += sign * std::pow(s, 4 * n + 3) / ((4 * n + 3) * fact2n * (2 * n + 1) * std::pow(a, 2 * n + 1));
  }
  return {x, y};
}

}  // namespace

TEST_CASE("clothoid offset matches the Fresnel power series", "[tracks][clothoid]") {
  double worst = 0;
  for (double R : {150.0, 300.0, 1000.0}) {
    for (double L : {30.0, 80.0, 150.0}) {
      const Clothoid c(L, 0.0, 1.0 / R, 0.0, 0.1);
      for (double u = 0; u <= L; u += L / 7) {
        const auto p = c.offset(u), q = fresnel_series(u, R, L);
        worst = std::max({worst, std::abs(p[0] - q[0]), std::abs(p[1] - q[1])});
        CHECK(c.heading_change(u) == Approx(u * u / (2 * R * L)).margin(1e-15));
        CHECK(c.curvature(u).v == Approx(u / (R * L)).margin(1e-15));
      }
    }
  }
  CHECK(worst < 1e-10);
  std::printf("[clothoid] offset vs Fresnel series: max difference %.2e m\n", worst);
}

TEST_CASE("every transition shape turns by L/(2R) and reaches 1/R and the full cant", "[tracks][clothoid]") {
  const double R = 400, L = 90, E = 0.11;
  for (TransitionShape shape : {TransitionShape::linear, TransitionShape::bloss, TransitionShape::cosine}) {
    const Clothoid c(L, 0.0, 1.0 / R, 0.0, E, shape);
    CHECK(c.heading_change(L) == Approx(L / (2 * R)).epsilon(1e-14));
    CHECK(c.curvature_end() == Approx(1.0 / R).epsilon(1e-14));
    CHECK(c.cant_end() == Approx(E).epsilon(1e-14));
    CHECK(c.curvature_start() == 0.0);
    CHECK(c.cant_start() == 0.0);
    // Shift of the circle p = y(L) - R (1 - cos(L/2R)): L^2/(24R) for the clothoid.
    if (shape == TransitionShape::linear) {
      const double p = c.offset(L)[1] - R * (1 - std::cos(L / (2 * R)));
      CHECK(p == Approx(L * L / (24 * R)).epsilon(2e-3));
    }
  }
  // Bloss: kappa = (1/R)(3u^2 - 2u^3), zero curvature rate at both ends.
  const Clothoid b(L, 0.0, 1.0 / R, 0.0, E, TransitionShape::bloss);
  for (double t : {0.1, 0.35, 0.5, 0.8}) CHECK(b.curvature(t * L).v == Approx((3 * t * t - 2 * t * t * t) / R).epsilon(1e-14));
  CHECK(b.curvature(0.0).d1 == 0.0);
  CHECK(std::abs(b.curvature(L).d1) < 1e-18);
  CHECK(b.curvature(0.5 * L).d1 == Approx(1.5 / (R * L)).epsilon(1e-14));  // max rate 1.5 / (R L)
}

TEST_CASE("a long transition (several radians of turn) is still integrated accurately", "[tracks][clothoid]") {
  // 1000 m from straight to R = 100 m: 5 rad of turn.
  const double R = 100, L = 1000;
  const Clothoid c(L, 0.0, 1.0 / R, 0.0, 0.0);
  const auto p = c.offset(L);
  // Reference: composite Simpson with 2e5 panels of cos/sin(u^2/(2RL)).
  const int n = 200000;
  double x = 0, y = 0;
  for (int i = 0; i <= n; ++i) {
    const double u = L * i / n, w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
    x += w * std::cos(u * u / (2 * R * L));
    y += w * std::sin(u * u / (2 * R * L));
  }
  x *= L / n / 3;
  y *= L / n / 3;
  CHECK(p[0] == Approx(x).margin(1e-9));
  CHECK(p[1] == Approx(y).margin(1e-9));
}
