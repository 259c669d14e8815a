// The engine's view of real profiles (engine/profile_geometry.hpp): the
// symmetric one-wheel use of the wheelset contact table, the flange jump where
// CONTACT has it, the Hertz patch scaling, and scenario input errors.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>

#include "contact/geometry/profile.hpp"
#include "contact/hertz.hpp"
#include "core/errors.hpp"
#include "engine/analysis/critical_speed.hpp"
#include "engine/profile_geometry.hpp"
#include "engine/scenario.hpp"
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
    WheelContact c;
    g.evaluate(-y, c);  // shift toward the right wheel is -y
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
  WheelContact tread, flange;
  g.evaluate(0.0060, tread);
  g.evaluate(0.0066, flange);
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
