// Rigid contact search (contact/geometry/wheel_rail_geometry.cpp) against
// CONTACT's Manchester-benchmark sweep (S1002 / UIC60 1:40, README section (d)).
//
// Frame mapping: CONTACT's track y points to the right and z down; railsim's y
// to the left and z up. A CONTACT shift y_ws is railsim y = -y_ws, its yaw is
// railsim yaw = -yaw_ws, roll is the same rotation. Positions: y = -ycp_tr.
// Contact angles keep their sign per wheel side. CONTACT's contact reference
// point lies on the rail surface, the approach pen below the undeformed wheel
// along the normal, so its rolling radius is r_rigid - pen / cos(delta).
#include <catch2/catch.hpp>

#include <cmath>

#include "contact/geometry/wheel_rail_geometry.hpp"
#include "core/errors.hpp"
#include "mbench_reference.hpp"

using namespace railsim;
using namespace railsim::contact;

namespace {
const WheelRailGeometry& mbench_geometry() {
  static const Profile w = read_profile("S1002", ProfileKind::wheel);
  static const Profile r = read_profile("UIC60", ProfileKind::rail);  // upright; 1/40 applied below
  static const WheelRailGeometry g = [] {
    TrackSetup ts;
    ts.inclination = std::atan(1.0 / 40.0);
    return WheelRailGeometry(w, r, ts);
  }();
  return g;
}
}  // namespace

TEST_CASE("Rail placement reproduces CONTACT's set-up", "[geometry][search]") {
  // CONTACT: left rail-profile origin at track y = -760.53 mm (ycp_tr - ycp_rail at y_ws = 0).
  static const Profile w = read_profile("S1002", ProfileKind::wheel);
  static const Profile r = read_profile("UIC60_MBench", ProfileKind::rail);
  const WheelRailGeometry g(w, r, TrackSetup{});
  CHECK(g.rail_offset() == Approx(0.751872596 + 0.00865996198).margin(2e-6));
}

TEST_CASE("Contact points match CONTACT's Manchester sweep (yaw0, A22)", "[geometry][search][mbench]") {
  const auto& g = mbench_geometry();
  int compared = 0, skipped = 0;
  double worst_y = 0, worst_x = 0, worst_r = 0, worst_a = 0;
  for (const auto& row : test::read_mbench()) {
    if (row.series == "yaw24mrad_const") continue;
    const Side side = row.side == "left" ? Side::left : Side::right;
    const auto c = g.at_roll(-row.y_ws, -row.yaw, row.roll);
    const ContactPoint& p = c.wheel[static_cast<std::size_t>(side)].p[0];
    INFO(row.series << " " << row.side << " y_ws = " << row.y_ws * 1e3 << " mm");
    if (test::excluded(row, "position")) {
      ++skipped;
      continue;
    }
    ++compared;
    const double dy = -p.y - row.ycp_tr;
    const double dx = p.x - row.xcp;  // x forward in both frames
    const double da = p.angle - row.delta;
    CHECK(std::abs(dy) < 0.5e-3);
    CHECK(std::abs(dx) < 0.5e-3);
    CHECK(std::abs(da) < 0.5 * M_PI / 180.0);
    worst_y = std::max(worst_y, std::abs(dy));
    worst_x = std::max(worst_x, std::abs(dx));
    worst_a = std::max(worst_a, std::abs(da));
    if (!test::excluded(row, "radius")) {
      // CONTACT's rolling radius is the height of the contact point below the
      // axle, r cos(theta), theta the angular position of the point ahead of the
      // wheel's lowest point (x_w = r sin(theta) in wheelset axes; zero without yaw);
      // ours is the wheel-circle radius r. Both with the approach along the normal.
      const double yaw = -row.yaw, yws = -row.y_ws;
      const double xw = std::cos(yaw) * p.x + std::sin(yaw) * (p.y - yws);
      const double r_eff = p.radius * std::sqrt(1.0 - (xw / p.radius) * (xw / p.radius));
      const double dr = (r_eff - row.pen / std::cos(row.delta)) - row.r_roll;
      CHECK(std::abs(dr) < 0.05e-3);
      worst_r = std::max(worst_r, std::abs(dr));
    }
  }
  WARN("compared " << compared << " patches (" << skipped << " excluded); worst |dy| = " << worst_y * 1e3
                   << " mm, |dx| = " << worst_x * 1e3 << " mm, |dr| = " << worst_r * 1e3
                   << " mm, |d angle| = " << worst_a * 180 / M_PI << " deg");
  CHECK(compared >= 76);
}

TEST_CASE("Equilibrium roll matches the Manchester regression vector", "[geometry][search][mbench]") {
  const auto& g = mbench_geometry();
  double prev_roll = 0.0;
  for (const auto& row : test::read_mbench()) {
    if (row.series != "yaw0" || row.side != "left") continue;
    const auto c = g.solve(-row.y_ws, 0.0);
    INFO("y_ws = " << row.y_ws * 1e3 << " mm: roll " << c.roll << " vs " << row.roll);
    CHECK(std::abs(c.roll - row.roll) <= std::max(1e-5, 0.05 * std::abs(row.roll)));
    CHECK(std::abs(c.z[0] - c.z[1]) < 1e-12);
    // Both wheels touch: the main point gap is zero.
    CHECK(std::abs(c.wheel[0].p[0].gap) < 1e-8);
    CHECK(std::abs(c.wheel[1].p[0].gap) < 1e-8);
    // The jump to flange contact lies between 6.0 and 6.5 mm as in the reference.
    if (std::abs(row.y_ws - 6.5e-3) < 1e-9) CHECK(std::abs(c.roll) > 5.0 * std::abs(prev_roll));
    prev_roll = c.roll;
  }
}

TEST_CASE("Flange contact onset and two-point contact for S1002/UIC60 1:40", "[geometry][search]") {
  const auto& g = mbench_geometry();
  // Flangeway clearance: the touching point jumps from the flange root to the
  // flank (contact angle near 70 deg) at one shift; CONTACT's sweep has the jump
  // between y_ws = 6.0 and 6.5 mm. Scan in 1 um steps.
  double jump = NAN;
  WheelsetContact before;
  for (int i = 0; i <= 300; ++i) {
    const double y = 6.0e-3 + i * 1e-6;
    const auto c = g.solve(y);
    if (i > 0 && std::abs(c.wheel[0].p[0].y_wheel - before.wheel[0].p[0].y_wheel) > 2e-3) {
      jump = y;
      break;
    }
    before = c;
  }
  INFO("flange jump at y = " << jump * 1e3 << " mm");
  CHECK(jump > 6.0e-3);
  CHECK(jump <= 6.5e-3);
  // Just before the jump the flank is a second point with a small gap, reported
  // separately (never averaged with the root point).
  REQUIRE(before.wheel[0].n >= 2);
  const ContactPoint& flank = before.wheel[0].p[static_cast<std::size_t>(before.wheel[0].n - 1)];
  CHECK(before.wheel[0].p[0].angle < 45.0 * M_PI / 180.0);
  CHECK(flank.angle > 60.0 * M_PI / 180.0);
  CHECK(flank.gap > 0.0);
  CHECK(flank.gap < 0.1e-3);
  // Symmetry: the right wheel at -y mirrors the left wheel at +y.
  const auto m = g.solve(-before.y);
  CHECK(m.roll == Approx(-before.roll).margin(1e-9));
  CHECK(m.wheel[1].p[0].angle == Approx(-before.wheel[0].p[0].angle).margin(1e-6));
  CHECK(m.wheel[1].p[0].radius == Approx(before.wheel[0].p[0].radius).margin(1e-8));
}

TEST_CASE("Curvatures of the tread contact match a Hertzian check", "[geometry][search]") {
  const auto& g = mbench_geometry();
  const auto c = g.solve(0.004);
  const ContactPoint& p = c.wheel[1].p[0];  // right wheel on its tread
  // A = cos(gamma_w) / (2 r): within 1 % of 1/(2r) on a tread (slope < 1:10).
  CHECK(p.A == Approx(1.0 / (2.0 * p.radius)).epsilon(0.01));
  CHECK(p.B > 0.0);
  // The gap profile is zero at the point and grows on both sides like B q^2.
  const auto gp = g.gap_profile(Side::right, p, 0.004, c.z[1], c.roll, 0.0, 0.5e-3, 11);
  CHECK(std::abs(gp.h[5]) < 1e-9);
  CHECK(gp.h[0] == Approx(p.B * 0.25e-6).epsilon(0.1));
  CHECK(gp.h[10] == Approx(p.B * 0.25e-6).epsilon(0.1));
}

TEST_CASE("Out-of-range positions give InputError", "[geometry][search][errors]") {
  const auto& g = mbench_geometry();
  CHECK_THROWS_AS(g.solve(0.06), InputError);
  CHECK_THROWS_AS(g.solve(0.0, 0.5), InputError);
  CHECK_THROWS_AS(g.solve(NAN), InputError);
  // Far beyond the flangeway clearance the wheel rides on its flange tip.
  CHECK_THROWS_WITH(g.solve(0.045), Catch::Contains("flange climbing"));
  // The message names the pose it was given: the yaw, and the roll when the caller prescribed it.
  CHECK_THROWS_WITH(g.solve(0.045, 0.002), Catch::Contains("y = 0.045 m, yaw = 0.002 rad is out of range"));
  CHECK_THROWS_WITH(g.at_roll(0.045, 0.002, 0.001),
                    Catch::Contains("y = 0.045 m, yaw = 0.002 rad, roll = 0.001 rad (given) is out of range"));
  CHECK_NOTHROW(g.solve(0.012));
  TrackSetup bad;
  bad.gauge = 3.0;
  CHECK_THROWS_WITH(bad.validate(), Catch::Contains("gauge"));
  // The gauge is measured below the top of rail: at depth 0 (the top itself)
  // no gauge-side point lies above it, so 0 is refused as out of range rather
  // than failing later without naming the key.
  TrackSetup top;
  top.gauge_depth = 0.0;
  CHECK_THROWS_WITH(top.validate(), Catch::Contains("'gauge_depth': expected a value in (0, 0.05] m (got 0)"));
  top.gauge_depth = 0.014;
  CHECK_NOTHROW(top.validate());
}

TEST_CASE("Rail inclination texts: 1/N, a slope or none, anything else named", "[geometry][errors]") {
  CHECK(parse_inclination("1/40", "--inclination") == Approx(std::atan(1.0 / 40.0)));
  CHECK(parse_inclination("0.05", "--inclination") == Approx(std::atan(0.05)));
  CHECK(parse_inclination("none", "--inclination") == 0.0);
  CHECK(parse_inclination("0", "--inclination") == 0.0);
  // Non-finite parts (1/inf read as slope 0), a NUL inside the text (read up to it), empty parts, steep or
  // negative slopes.
  for (const std::string& bad : {std::string("1/inf"), std::string("1/1e400"), std::string("inf"), std::string("nan"),
                                std::string("1/0"), std::string("-1/40"), std::string("1/40x"),
                                std::string("1/40\0x", 6), std::string(""), std::string("/40"), std::string("1/"),
                                std::string("1/2")}) {
    INFO("'" << bad << "'");
    CHECK_THROWS_WITH(parse_inclination(bad, "--inclination"),
                      Catch::Contains("--inclination '") && Catch::Contains("expected 1/N"));
  }
  // A control byte in the text is shown, not passed on (a NUL ended the message there).
  CHECK_THROWS_WITH(parse_inclination(std::string("1/40\0x", 6), "--inclination"),
                    Catch::Contains("--inclination '1/40\\x00x': expected 1/N"));
}
