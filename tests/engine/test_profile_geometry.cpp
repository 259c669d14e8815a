// The engine's view of real profiles (engine/profile_geometry.hpp): the
// symmetric one-wheel use of the wheelset contact table, the flange jump where
// CONTACT has it, the Hertz patch scaling, and scenario input errors.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "contact/geometry/profile.hpp"
#include "contact/hertz.hpp"
#include "core/errors.hpp"
#include "engine/data.hpp"
#include "engine/analysis/critical_speed.hpp"
#include "engine/profile_geometry.hpp"
#include "engine/scenario.hpp"
#include "engine/system.hpp"
#include "results/csv_writer.hpp"
#include "engine_test_support.hpp"
#include "test_support.hpp"

using namespace railsim;
using namespace railsim::engine;

namespace {

ProfileGeometryParams s1002_uic60(const std::string& cache) {
  ProfileGeometryParams p;
  p.setup.inclination = std::atan(1.0 / 40.0);
  p.cache_dir = cache;
  return p;
}

// The single wheelset on S1002/UIC60 1:40 profiles with linear creep, for the
// engine-level geometry tests; `models` holds the wheelset_model (and roll)
// lines, `spin` whether the spin creepage acts.
Scenario profiles_wheelset(const std::string& cache, const std::string& models, bool spin) {
  return test::scenario_from_text(
      "vehicle: vehicles/single_wheelset.yaml\n"
      "track: {segments: [{type: straight, length: 1000}]}\n"
      "speed: 30\nduration: 1\n" + models +
      "contact:\n  geometry: {type: profiles, wheel: S1002, rail: UIC60, inclination: 1/40, cache_dir: " + cache +
      "}\n  tangential: linear\n" + (spin ? "" : "  spin: false\n") +
      "  material: {E: 2.1e11, nu: 0.28, mu: 0.3}\n");
}

// Index of a named state (-1 when absent).
int state_index(const Scenario& sc, const std::string& name) {
  for (int i = 0; i < sc.model.n_states; ++i)
    if (sc.model.state_names[static_cast<std::size_t>(i)] == name) return i;
  return -1;
}

}  // namespace

TEST_CASE("profile geometry: the right wheel at -y mirrors the left wheel at +y", "[engine][geometry]") {
  const std::string cache = test::temp_dir("profile_geometry");
  const contact::Material steel;
  const ProfileGeometryParams p = s1002_uic60(cache);
  const ProfileGeometry g(p, steel);
  // The same table read the other way: the wheelset table's right wheel.
  const contact::Profile wheel = contact::read_profile("S1002", contact::ProfileKind::wheel);
  const contact::Profile rail = contact::read_profile("UIC60", contact::ProfileKind::rail);
  const contact::WheelRailGeometry wr(wheel, rail, p.setup);
  const auto table = contact::ContactTable::cached(wr, wheel, rail, p.grid, cache);
  for (double y : {-0.011, -0.006, -0.002, 0.0, 0.003, 0.0061, 0.009}) {
    contact::TableSample t;
    table.lookup(y, t);
    const auto& right = t.wheel[static_cast<int>(contact::Side::right)].p[0];
    const ContactPointGeometry c = g.main_point(-y);  // shift toward the right wheel is -y
    INFO("y = " << y * 1e3 << " mm");
    // Mirror symmetry of profiles and set-up (radius to 1 um, angle to 1e-4 rad:
    // the table is interpolated at mirrored points of its grid).
    CHECK(c.rolling_radius == Approx(right.radius).margin(1e-6));
    CHECK(c.contact_angle == Approx(-right.angle).margin(1e-4));
    CHECK(c.lateral == Approx(-(right.y - y)).margin(1e-5));
  }
}

TEST_CASE("profile geometry: flange jump and Hertz patch", "[engine][geometry]") {
  const contact::Material steel;
  const ProfileGeometry g(s1002_uic60(test::temp_dir("profile_geometry_jump")), steel);
  CHECK(g.r0() == Approx(0.46).margin(2e-3));
  CHECK(g.l0() == Approx(0.75).margin(0.01));
  // CONTACT's sweep (S1002/UIC60 1:40, see tests/contact_geometry): the
  // touching point jumps from the flange root (contact angle below 30 deg) to
  // the flank (about 65-70 deg) between 6.0 and 6.5 mm.
  const ContactPointGeometry tread = g.main_point(0.0060), flange = g.main_point(0.0066);
  CHECK(tread.contact_angle < 0.52);
  CHECK(flange.contact_angle > 1.0);
  CHECK(flange.rolling_radius > tread.rolling_radius + 5e-3);
  CHECK(flange.lateral < tread.lateral - 5e-3);  // the point moves toward the flange
  // The tabulated patch at N0 scales as N^(1/3), exactly Hertz for fixed A, B.
  const double N = 80e3;
  const auto h = contact::hertz_from_load(tread.A, tread.B, N, steel);
  CHECK(tread.semi_a * std::cbrt(N / tread.N0) == Approx(h.a).epsilon(1e-9));
  CHECK(tread.semi_b * std::cbrt(N / tread.N0) == Approx(h.b).epsilon(1e-9));
}

TEST_CASE("profile geometry in a scenario: runs, and bad input names the key", "[engine][geometry]") {
  const std::string dir = test::temp_dir("profile_geometry_scenario");
  std::ifstream in(test::data_path("scenarios/single_wheelset_s1002.yaml"));
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  text.replace(text.find("vehicle: ../../../"), 18, "vehicle: " + test::source_path(""));
  const auto geo = text.find("  geometry: {type: table");
  const auto eol = text.find('\n', geo);
  auto with_geometry = [&](const std::string& g) {
    std::string t = text;
    t.replace(geo, eol - geo, "  geometry: " + g);
    t.replace(t.find("  saturation: she\n"), 18, "");
    t.replace(t.find("tangential: coefficients"), 24, "tangential: chopaya");
    const std::string path = dir + "/s.yaml";
    std::ofstream(path) << t;
    return path;
  };
  const Scenario sc = load_scenario(with_geometry(
      "{type: profiles, wheel: S1002, rail: UIC60, inclination: 1/40, cache_dir: " + dir + "/cache}"));
  CHECK(sc.geometry_description.find("S1002") != std::string::npos);
  const double v = linear_critical_speed(sc, 20.0, 200.0);
  CHECK(std::isfinite(v));
  CHECK_THROWS_WITH(load_scenario(with_geometry("{type: profiles, wheel: S1002, inclination: 1/0}")),
                    Catch::Contains("inclination"));
  CHECK_THROWS_WITH(load_scenario(with_geometry("{type: profiles, wheel: S1002, gauge: 3}")),
                    Catch::Contains("gauge"));
  CHECK_THROWS_WITH(load_scenario(with_geometry("{type: profiles, wheel: S1002, shape: round}")),
                    Catch::Contains("shape"));
  CHECK_THROWS_AS(load_scenario(with_geometry("{type: profiles, wheel: no_such_profile}")), InputError);
}

// Two-point contact (full wheelset model). S1002 on UIC60 at 1:40 has a second
// local minimum of the gap on the tread between 4.0 and 5.25 mm of shift
// (`railsim geometry`; the touching point jumps from ~7 to ~17 deg contact
// angle near 4.9 mm), and none at the flange jump (6.25 mm, where the point
// slides continuously through the flange root). Across that tread jump the
// wheel load must pass from one point to the other through a range where both
// carry load, instead of the single point's jump of the lateral force. The
// left wheel is held where it carries W = 50 kN (bisection on the wheelset
// height); spin and creepages are off, so the lateral force is the normal
// forces' component alone, Y = -sum N_k sin(delta_k) (one point: -W tan delta).
TEST_CASE("profile geometry: two-point contact shares the load across the tread jump", "[engine][geometry]") {
  const std::string dir = test::temp_dir("profile_geometry_two_point");
  const Scenario sc = profiles_wheelset(dir, "wheelset_model: full\n", false);
  const auto& geo = *sc.model.wheelsets[0].geometry;
  const int lat = state_index(sc, "ws1.lateral"), vert = state_index(sc, "ws1.vertical");
  REQUIRE(lat >= 0);
  REQUIRE(vert >= 0);
  const double W = 50e3;
  Data d(sc.model);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(sc.model.n_states), xd(x.size());
  auto left_at = [&](double s, double z) {
    x[lat] = s;
    x[vert] = z;
    rhs_or_throw(sc.model, d, 0.0, x.data(), xd.data());
    return d.wheel[0];
  };
  // Wheel held at Q = W: bisection on the height (Q falls as the wheel rises).
  auto loaded = [&](double s) {
    double lo = -2e-3, hi = 2e-3;
    for (int it = 0; it < 60; ++it) {
      const double z = 0.5 * (lo + hi);
      (left_at(s, z).Q > W ? lo : hi) = z;
    }
    return left_at(s, 0.5 * (lo + hi));
  };
  double step_two = 0.0, step_one = 0.0, prev_two = 0.0, prev_one = 0.0;
  // Vertical load at a fixed wheelset height, every 1 um: it grows fast where
  // the second point closes (~0.08 W per 10 um) but without a jump where the
  // points swap roles (its reference, the rigid touching position, is
  // continuous in the shift).
  double step_fixed = 0.0, prev_fixed = 0.0;
  for (int i = 0; i <= 1600; ++i) {
    const double q_fixed = left_at(3.9e-3 + i * 1e-6, 0.0).Q;
    if (i > 0) step_fixed = std::max(step_fixed, std::abs(q_fixed - prev_fixed));
    prev_fixed = q_fixed;
  }
  int shared = 0;
  for (int i = 0; i <= 320; ++i) {
    const double s = 3.9e-3 + i * 5e-6;  // 3.9 .. 5.5 mm in 5 um steps
    const WheelOutput w = loaded(s);
    REQUIRE(w.Q == Approx(W).epsilon(1e-6));
    const ContactPointGeometry p0 = geo.main_point(s);
    const double y_one = -W * std::tan(p0.contact_angle);
    // Both points loaded: the lateral force differs from the main point's alone.
    if (std::abs(w.Y - y_one) > 0.01 * W) ++shared;
    if (i > 0) {
      step_two = std::max(step_two, std::abs(w.Y - prev_two));
      step_one = std::max(step_one, std::abs(y_one - prev_one));
    }
    prev_two = w.Y;
    prev_one = y_one;
  }
  INFO("largest change of Y per 5 um: two points " << step_two / W << " W, main point alone " << step_one / W
                                                   << " W; shifts with both points loaded: " << shared
                                                   << "; of Q at a fixed height per 1 um: " << step_fixed / W << " W");
  // Measured: 0.0057 W against 0.172 W, both points loaded over 0.72 mm.
  CHECK(step_one > 0.1 * W);  // the jump of the single point
  CHECK(shared >= 40);        // >= 0.2 mm of shared load
  CHECK(step_two < 0.1 * step_one);
  CHECK(step_fixed < 0.006 * W);  // measured 0.0033 W
}

// The same tread jump in the lateral (quasi-static) wheelset model: the left
// wheel's load Q from the wheelset's statics (its weight alone, ~8.9 kN, so
// the approach and the shared range are smaller than at 50 kN: ~(8.9/50)^(2/3)
// of it) is shared by the two points with the full model's load law; the
// lateral force per unit load, Y/Q, must pass smoothly where the main point
// alone jumps (-tan delta). Roll held at zero: the kinematic roll from the
// main points' rolling radii jumps with them and would hide the comparison.
TEST_CASE("profile geometry: the lateral model shares the load between two points", "[engine][geometry]") {
  const std::string dir = test::temp_dir("profile_geometry_two_point_lateral");
  const Scenario sc = profiles_wheelset(dir, "wheelset_model: lateral\nwheelset_roll: none\n", false);
  const auto& geo = *sc.model.wheelsets[0].geometry;
  const int body = sc.model.wheelsets[0].body;
  const int lat = state_index(sc, "ws1.lateral");
  REQUIRE(lat >= 0);
  Data d(sc.model);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(sc.model.n_states), xd(x.size());
  double step_two = 0.0, step_one = 0.0, prev_two = 0.0, prev_one = 0.0;
  int shared = 0;
  for (int i = 0; i <= 320; ++i) {
    const double s = 3.9e-3 + i * 5e-6;  // 3.9 .. 5.5 mm in 5 um steps
    x[lat] = s;
    rhs_or_throw(sc.model, d, 0.0, x.data(), xd.data());
    const WheelOutput& w = d.wheel[0];
    REQUIRE(w.Q > 0.0);
    const ContactPointGeometry p0 = geo.main_point(s);
    const double two = w.Y / w.Q;
    REQUIRE(d.motion[static_cast<std::size_t>(body)].q[kRoll] == 0.0);
    const double one = -std::tan(p0.contact_angle);
    if (std::abs(two - one) > 0.01) ++shared;
    if (i > 0) {
      step_two = std::max(step_two, std::abs(two - prev_two));
      step_one = std::max(step_one, std::abs(one - prev_one));
    }
    prev_two = two;
    prev_one = one;
  }
  INFO("largest change of Y/Q per 5 um: two points " << step_two << ", main point alone " << step_one
                                                     << "; shifts with both points loaded: " << shared);
  // Measured: 0.0045 against 0.177, both points loaded over 0.2 mm.
  CHECK(step_one > 0.1);
  CHECK(shared >= 20);  // >= 0.1 mm
  CHECK(step_two < 0.1 * step_one);
}

// The lateral model's kinematic roll with real profiles is the rigid
// wheelset's roll (ContactGeometry::rigid_pose), checked against the
// Manchester benchmark's equilibrium roll that CONTACT was run with
// (tests/data/reference/contact/mbench_S1002_UIC60_sweep.csv, series yaw0,
// y_ws = 0 .. 10 mm; CONTACT's roll is negative for a shift toward its
// wheel: the opposite sign convention). Same tolerance as the geometry's own
// test (tests/contact_geometry): 5 %, or 1e-5 rad near zero. The knife-edge
// formula (r_L - r_R)/(a_L + a_R) is 3-8 times larger there.
TEST_CASE("profile geometry: the lateral model's kinematic roll is the rigid wheelset roll", "[engine][geometry]") {
  const std::string dir = test::temp_dir("profile_geometry_roll");
  const Scenario sc = profiles_wheelset(dir, "wheelset_model: lateral\nwheelset_roll: kinematic\n", true);
  const int body = sc.model.wheelsets[0].body;
  const int lat = state_index(sc, "ws1.lateral");
  REQUIRE(lat >= 0);
  const auto ref = railsim::results::read_csv(test::reference_path("contact/mbench_S1002_UIC60_sweep.csv"));
  Data d(sc.model);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(sc.model.n_states), xd(x.size());
  int compared = 0;
  for (std::size_t i = 0; i < ref.rows.size(); ++i) {
    if (ref.rows[i][ref.column("series")] != "yaw0" || ref.rows[i][ref.column("side")] != "left") continue;
    const double y = ref.number(i, "y_ws_mm") * 1e-3, roll = -ref.number(i, "roll_ws_rad");
    x[lat] = y;
    rhs_or_throw(sc.model, d, 0.0, x.data(), xd.data());
    const double phi = d.motion[static_cast<std::size_t>(body)].q[kRoll];
    INFO("y = " << y * 1e3 << " mm: roll " << phi << " vs CONTACT's " << roll);
    CHECK(std::abs(phi - roll) <= std::max(1e-5, 0.05 * std::abs(roll)));
    ++compared;
  }
  CHECK(compared >= 21);
}
