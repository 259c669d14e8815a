// Equivalent conicity (contact/geometry/conicity.cpp).
#include <catch2/catch.hpp>

#include <cmath>

#include "contact/geometry/conicity.hpp"
#include "core/errors.hpp"
#include "test_support.hpp"

using namespace railsim;
using namespace railsim::contact;

TEST_CASE("A conical wheel has its cone slope as equivalent conicity", "[geometry][conicity]") {
  // Cone F = -lambda s (lambda = 0.05) on a rail crown of radius R_r = 0.3 m
  // (UIC60 R300 crown, physics-reference 6.2). Klingel's delta r = 2 lambda y is
  // corrected for the wheelset roll phi = delta r / (2 l): the contact moves
  // on the wheel by y + (r0 + R_r) phi, so
  // delta r = 2 lambda y / (1 - lambda (r0 + R_r) / l), l = half the lateral
  // distance of the contact points; the equivalent conicity is that slope / 2.
  const Profile w = read_profile(test::data_path("contact_geometry/cone_0.05.csv"), ProfileKind::wheel);
  const Profile r = read_profile("UIC60", ProfileKind::rail);
  TrackSetup ts;
  ts.inclination = std::atan(1.0 / 40.0);
  const WheelRailGeometry g(w, r, ts);
  TableGrid grid;
  grid.y_min = -0.007;
  grid.y_max = 0.007;
  grid.y_step = 2.5e-4;
  const ContactTable t = ContactTable::build(g, grid);
  TableSample s0;
  t.lookup(0.0, s0);
  const double l = 0.5 * (s0.wheel[0].p[0].y - s0.wheel[1].p[0].y);
  const double expected = 0.05 / (1.0 - 0.05 * (0.46 + 0.300) / l);
  for (int a = 1; a <= 6; ++a) CHECK(equivalent_conicity(t, a * 1e-3) == Approx(expected).epsilon(0.005));
  const auto c = rolling_radius_difference(t);
  REQUIRE(c.y.size() == t.rows());
  CHECK(c.delta_r.back() == Approx(2 * expected * 0.007).epsilon(0.005));
  CHECK_THROWS_AS(equivalent_conicity(t, 0.008), InputError);
}

TEST_CASE("S1002/UIC60: conicity is positive and the delta-r curve odd", "[geometry][conicity]") {
  const Profile w = read_profile("S1002", ProfileKind::wheel);
  const Profile r = read_profile("UIC60", ProfileKind::rail);
  TrackSetup ts;
  ts.inclination = std::atan(1.0 / 40.0);
  const WheelRailGeometry g(w, r, ts);
  TableGrid grid;
  grid.y_min = -0.006;
  grid.y_max = 0.006;
  grid.y_step = 2e-4;
  const ContactTable t = ContactTable::build(g, grid);
  const auto c = rolling_radius_difference(t);
  const std::size_t n = c.y.size();
  for (std::size_t i = 0; i < n; ++i) CHECK(c.delta_r[i] == Approx(-c.delta_r[n - 1 - i]).margin(1e-8));
  for (int a = 1; a <= 6; ++a) CHECK(equivalent_conicity(t, a * 1e-3) > 0.0);
}
