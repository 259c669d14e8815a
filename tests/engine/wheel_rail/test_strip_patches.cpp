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
    contact::StripPoint& p = s.add();
    const double q = j * d;
    p.index = first_index + j + half;
    p.gap = B * q * q + offset;
    p.angle = 0.0;
    p.lateral = 0.75 + q;
    p.height = 0.46;
    p.A = A;
    p.f = contact::StripContactTable::winkler_factor(B / A);
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
    contact::StripPoint& p = s.add();
    const double q = j * d;
    const double g1 = B * q * q, g2 = B * (q - 0.02) * (q - 0.02) * 1.0 + 30e-6;
    p.index = j;
    p.gap = std::min(g1, g2);
    p.angle = 0.0;
    p.lateral = 0.75 + q;
    p.height = 0.46;
    p.A = A;
    p.f = contact::StripContactTable::winkler_factor(B / A);
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
