// Distributed normal contact from strips (engine/wheel_rail/strip_patches.hpp) against
// Hertz's exact solution: on a quadratic gap (curvatures A, B) the strips'
// Winkler law gives Hertz's approach for the load, and the equivalent ellipse
// is Hertz's, for B/A from 0.05 to 10; the load grows continuously (no jump)
// while a second patch closes and the two merge; and the approach for a load
// is the inverse of the load for an approach.
#include <catch2/catch.hpp>

#include <cmath>

#include "contact/hertz.hpp"
#include "engine/wheel_rail/strip_patches.hpp"

using namespace railsim;

namespace {
// A quadratic gap g = B q^2 (normal, flat contact plane) on strips of width d.
contact::StripSet quadratic(double A, double B, double d, int half, double offset = 0.0, int first_index = 0) {
  contact::StripSet s;
  s.width = d;
  for (int j = -half; j <= half && s.n < contact::StripSet::kMax; ++j) {
    contact::StripPoint p;
    const double q = j * d;
    p.index = first_index + j + half;
    p.gap = B * q * q + offset;
    p.angle = 0.0;
    p.lateral = 0.75 + q;
    p.height = 0.46;
    p.A = A;
    p.f = contact::StripContactTable::winkler_factor(B / A);
    s.add(p);
  }
  return s;
}
double Es(const contact::Material& m) { return m.E / (2.0 * (1.0 - m.nu * m.nu)); }
}  // namespace

TEST_CASE("strip contact reproduces Hertz on a quadratic gap", "[engine][strips]") {
  const contact::Material m;
  for (double ratio : {0.05, 0.2, 0.5, 1.0, 2.0, 5.0, 10.0}) {
    const double A = 1.087, B = A * ratio, N = 2e4;
    const contact::HertzPatch h = contact::hertz_from_load(A, B, N, m);
    // Strips 1/40 of the interpenetration half-width.
    const double d = std::sqrt(h.approach / B) / 40.0;
    const contact::StripSet s = quadratic(A, B, d, 75);
    engine::StripLoads L;
    const double w = engine::strip_approach_for_load(s, N, 0.0, Es(m), L);
    INFO("B/A = " << ratio << ": approach " << w << " vs Hertz " << h.approach << ", a " << L.patch[0].semi_a
                  << " vs " << h.a << ", b " << L.patch[0].semi_b << " vs " << h.b);
    REQUIRE(L.n == 1);
    CHECK(L.N[0] == Approx(N).epsilon(1e-9));
    CHECK(w == Approx(h.approach).epsilon(2e-3));
    CHECK(L.patch[0].semi_a == Approx(h.a).epsilon(3e-3));
    CHECK(L.patch[0].semi_b == Approx(h.b).epsilon(3e-3));
    CHECK(L.patch[0].lateral == Approx(0.75).margin(1e-9));  // symmetric patch centred on the minimum
  }
}

TEST_CASE("strip contact: loads are continuous while a second patch closes and merges", "[engine][strips]") {
  const contact::Material m;
  const double A = 1.0, B = 2.0, d = 2e-4;
  // Two parabolic basins 6 mm apart, the second raised by 30 um; a ridge between.
  contact::StripSet s;
  s.width = d;
  for (int j = 0; j <= 100; ++j) {
    contact::StripPoint p;
    const double q = j * d;
    const double g1 = B * q * q, g2 = B * (q - 0.02) * (q - 0.02) * 1.0 + 30e-6;
    p.index = j;
    p.gap = std::min(g1, g2);
    p.angle = 0.0;
    p.lateral = 0.75 + q;
    p.height = 0.46;
    p.A = A;
    p.f = contact::StripContactTable::winkler_factor(B / A);
    s.add(p);
  }
  engine::StripLoads L;
  double prev = 0.0, largest_step = 0.0;
  int patches_seen[3] = {0, 0, 0};
  for (int k = 1; k <= 4000; ++k) {
    const double w = k * 5e-8;  // up to 200 um
    engine::strip_loads(s, w, 0.0, 0.0, Es(m), L);
    double N = 0.0;
    for (int p = 0; p < L.n; ++p) N += L.N[p];
    CHECK(L.vertical == Approx(N).epsilon(1e-12));
    largest_step = std::max(largest_step, N - prev);
    CHECK(N >= prev);  // monotone in the approach
    prev = N;
    patches_seen[std::min(L.n, 2)]++;
  }
  INFO("largest load step per 0.05 um: " << largest_step << " N, final load " << prev << " N");
  CHECK(patches_seen[1] > 0);
  CHECK(patches_seen[2] > 0);          // the second patch closed, then the ridge filled
  CHECK(largest_step < 1e-3 * prev);   // no jump
}

TEST_CASE("strip contact: approach for a load inverts the load for an approach", "[engine][strips]") {
  const contact::Material m;
  const contact::StripSet s = quadratic(1.0, 0.4, 2e-4, 70, 0.0);
  for (double N : {1e3, 1e4, 5e4, 1.5e5}) {
    engine::StripLoads L;
    const double w = engine::strip_approach_for_load(s, N, 0.0, Es(m), L);
    engine::StripLoads L2;
    engine::strip_loads(s, w, 0.0, 0.0, Es(m), L2);
    CHECK(L2.vertical == Approx(N).epsilon(1e-9));
  }
}

TEST_CASE("semi-Hertzian patch: Hertz's ellipse on a quadratic gap", "[engine][strips][semi_hertz]") {
  const contact::Material m;
  for (double ratio : {0.05, 0.5, 1.0, 5.0, 10.0}) {
    const double A = 1.087, B = A * ratio, N = 2e4;
    const contact::HertzPatch h = contact::hertz_from_load(A, B, N, m);
    const double d = std::sqrt(h.approach / B) / 40.0;
    const contact::StripSet s = quadratic(A, B, d, 75);
    engine::StripLoads L;
    engine::strip_approach_for_load(s, N, 0.0, Es(m), L, engine::PatchShape::semi_hertz);
    INFO("B/A = " << ratio << ": a " << L.patch[0].semi_a << " vs " << h.a << ", b " << L.patch[0].semi_b << " vs "
                  << h.b);
    REQUIRE(L.n == 1);
    CHECK(L.N[0] == Approx(N).epsilon(1e-9));  // the loads are the strips' either way
    CHECK(L.patch[0].semi_a == Approx(h.a).epsilon(5e-3));
    CHECK(L.patch[0].semi_b == Approx(h.b).epsilon(5e-3));
  }
}

TEST_CASE("semi-Hertzian patch: area and length follow a varying longitudinal curvature",
          "[engine][strips][semi_hertz]") {
  // Quadratic lateral gap h = B q^2 with the longitudinal curvature rising
  // across the patch, A(q) = A0 (1 + c q / b_H) (a flange root: the rolling
  // radius changes across the patch). Reference: Ayasse & Chollet's strip
  // half-lengths x(q) = sqrt((eps delta - B q^2) / (c_A A(q))) with the
  // ellipse's eps and c_A, integrated by fine Simpson quadrature here.
  const contact::Material m;
  const double A0 = 1.0, B = 4.0, N = 3e4;
  const contact::HertzPatch h0 = contact::hertz_from_load(A0, B, N, m);
  for (double c : {0.0, 0.3, -0.3, 0.6}) {
    const double d = std::sqrt(h0.approach / B) / 60.0;
    contact::StripSet s = quadratic(A0, B, d, 110);
    for (int j = 0; j < s.n; ++j) {
      const double q = s.lateral[j] - 0.75;
      s.A[j] = A0 * (1.0 + c * q / h0.b);
    }
    engine::StripLoads Lh, Ls;
    engine::strip_approach_for_load(s, N, 0.0, Es(m), Lh, engine::PatchShape::hertz);
    const double w = engine::strip_approach_for_load(s, N, 0.0, Es(m), Ls, engine::PatchShape::semi_hertz);
    REQUIRE(Lh.n == 1);
    REQUIRE(Ls.n == 1);
    // The patch's Hertz ellipse (load-weighted A, B_e, approach p_max = w on a flat plane).
    const double A = Lh.patch[0].A, a = Lh.patch[0].semi_a, b = Lh.patch[0].semi_b, delta = w;
    const double Be = B;  // the half-depth width of B q^2 gives B exactly
    const double eps = Be * b * b / delta, cA = Be * b * b / (A * a * a);
    auto x_half = [&](double q) {
      const double g = eps * delta - B * q * q;
      return g > 0.0 ? std::sqrt(g / (cA * A0 * (1.0 + c * q / h0.b))) : 0.0;
    };
    const double qmax = std::sqrt(eps * delta / B);
    const int n = 20000;
    double area = 0.0, amax = 0.0;
    for (int k = 0; k <= n; ++k) {  // Simpson on the substitution q = qmax sin(t) (smooth at the ends)
      const double t = -M_PI / 2 + M_PI * k / n;
      const double f = 2.0 * x_half(qmax * std::sin(t)) * qmax * std::cos(t);
      area += f * (k == 0 || k == n ? 1.0 : (k % 2 ? 4.0 : 2.0));
    }
    area *= M_PI / n / 3.0;
    for (int k = 0; k <= n; ++k) amax = std::max(amax, x_half(-qmax + 2.0 * qmax * k / n));
    INFO("c = " << c << ": a " << Ls.patch[0].semi_a << " vs " << amax << ", area " << M_PI * Ls.patch[0].semi_a *
                                                                                     Ls.patch[0].semi_b
                << " vs " << area << " (Hertz ellipse a " << a << ", b " << b << ")");
    CHECK(Ls.patch[0].semi_a == Approx(amax).epsilon(5e-3));
    CHECK(M_PI * Ls.patch[0].semi_a * Ls.patch[0].semi_b == Approx(area).epsilon(5e-3));
    if (c == 0.0) {
      CHECK(Ls.patch[0].semi_a == Approx(a).epsilon(5e-3));
      CHECK(Ls.patch[0].semi_b == Approx(b).epsilon(5e-3));
    } else {
      // The load-weighted A is A0 (symmetric loads, A linear in q); the strips
      // lengthen where A falls more than they shorten where it rises
      // (1/sqrt(1 + c q/b) is convex, Jensen): the area exceeds the ellipse's.
      CHECK(A == Approx(A0).epsilon(1e-6));
      CHECK(M_PI * Ls.patch[0].semi_a * Ls.patch[0].semi_b > M_PI * a * b);
    }
  }
}
