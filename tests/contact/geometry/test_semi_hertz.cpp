// STRIPES semi-Hertz (contact/geometry/semi_hertz.cpp): equals Hertz for a
// quadratic gap; close to CONTACT for a non-Hertzian S1002/UIC60 position.
#include <catch2/catch.hpp>

#include <cmath>

#include "contact/geometry/semi_hertz.hpp"
#include "contact/hertz.hpp"
#include "core/errors.hpp"
#include "mbench_reference.hpp"

using namespace railsim;
using namespace railsim::contact;

TEST_CASE("Semi-Hertz equals Hertz for constant curvatures", "[geometry][semi_hertz]") {
  const Material m;  // 210 GPa, 0.28
  SemiHertzWorkspace ws;
  struct Case {
    double A, B, Fn;
  };
  for (const Case c : {Case{1.0 / 0.92, 1.0 / 0.6, 75e3}, Case{1.0 / 0.92, 10.0, 10e3}, Case{1.0 / 0.92, 0.4, 10e3}}) {
    GapProfile gp;
    const int n = 801;
    const double hw = 1.2 * std::sqrt(hertz_from_load(c.A, c.B, c.Fn, m).approach / c.B) + 1e-3;
    for (int j = 0; j < n; ++j) {
      const double q = -hw + 2 * hw * j / (n - 1);
      gp.q.push_back(q);
      gp.h.push_back(c.B * q * q);
      gp.A.push_back(c.A);
    }
    const auto s = semi_hertz_from_load(gp, c.Fn, m, ws);
    const auto h = hertz_from_load(c.A, c.B, c.Fn, m);
    INFO("A = " << c.A << " B = " << c.B);
    CHECK(s.area == Approx(M_PI * h.a * h.b).epsilon(0.01));
    CHECK(s.p_max == Approx(h.p0).epsilon(0.01));
    CHECK(s.approach == Approx(h.approach).epsilon(0.01));
    CHECK(s.length == Approx(2 * h.a).epsilon(0.01));
    CHECK(s.parts == 1);
  }
}

TEST_CASE("Semi-Hertz on non-Hertzian S1002/UIC60 positions agrees with CONTACT", "[geometry][semi_hertz][mbench]") {
  // y_ws = 0 (centred wheelset): near two-point tread contact, CONTACT's patch
  // 15.8 mm wide. Right wheel at y_ws = 5 mm: flange root plus tread, a
  // two-part patch 11.8 mm wide in CONTACT.
  const Profile w = read_profile("S1002", ProfileKind::wheel);
  const Profile r = read_profile("UIC60", ProfileKind::rail);
  TrackSetup ts;
  ts.inclination = std::atan(1.0 / 40.0);
  const WheelRailGeometry g(w, r, ts);
  const Material m = Material::from_shear_modulus(82000e6, 0.28, 0.3);  // CONTACT's case (d)
  SemiHertzWorkspace ws;
  int n = 0;
  for (const auto& row : test::read_mbench()) {
    if (row.series != "yaw0") continue;
    const bool centred = row.side == "left" && row.y_ws == 0.0;
    const bool two_part = row.side == "right" && std::abs(row.y_ws - 0.005) < 1e-9;
    if (!centred && !two_part) continue;
    const Side side = row.side == "left" ? Side::left : Side::right;
    const auto c = g.at_roll(-row.y_ws, 0.0, row.roll);
    const auto& p = c.wheel[static_cast<std::size_t>(side)].p[0];
    const auto gp = g.gap_profile(side, p, -row.y_ws, c.z[static_cast<std::size_t>(side)], row.roll, 0.0, 0.014, 561);
    const auto s = semi_hertz_from_load(gp, row.FN, m, ws);
    const auto h = hertz_from_load(p.A, p.B, row.FN, m);
    WARN(row.side << " y_ws = " << row.y_ws * 1e3 << " mm: semi-Hertz area " << s.area * 1e6 << " mm2 (CONTACT "
                  << row.area * 1e6 << ", Hertz " << M_PI * h.a * h.b * 1e6 << "), pmax " << s.p_max / 1e6
                  << " MPa (CONTACT " << row.pmax / 1e6 << ", Hertz " << h.p0 / 1e6 << "), width " << s.width * 1e3
                  << " mm (CONTACT " << row.width * 1e3 << "), parts " << s.parts);
    CHECK(s.area == Approx(row.area).epsilon(0.10));
    CHECK(s.p_max == Approx(row.pmax).epsilon(0.05));
    CHECK(s.width == Approx(row.width).epsilon(0.10));
    CHECK(s.parts == (two_part ? 2 : 1));
    // Hertz from the local curvatures misses the wide patch by far more.
    CHECK(std::abs(2.0 * h.b - row.width) > 0.3 * row.width);
    ++n;
  }
  CHECK(n == 2);
}

TEST_CASE("Hertz semi-axes at single-patch Hertzian positions match CONTACT", "[geometry][semi_hertz][mbench]") {
  const Profile w = read_profile("S1002", ProfileKind::wheel);
  const Profile r = read_profile("UIC60", ProfileKind::rail);
  TrackSetup ts;
  ts.inclination = std::atan(1.0 / 40.0);
  const WheelRailGeometry g(w, r, ts);
  const Material m = Material::from_shear_modulus(82000e6, 0.28, 0.3);
  int n = 0;
  double worst = 0;
  for (const auto& row : test::read_mbench()) {
    if (row.series != "yaw0" || test::excluded(row, "axes")) continue;
    const Side side = row.side == "left" ? Side::left : Side::right;
    const auto c = g.at_roll(-row.y_ws, 0.0, row.roll);
    const auto& p = c.wheel[static_cast<std::size_t>(side)].p[0];
    const auto h = hertz_from_load(p.A, p.B, row.FN, m);
    // CONTACT's extents count whole 0.2 mm elements (rounded up): allow that rounding.
    const double ds = 0.2e-3;
    auto err = [ds](double ours, double ref) {
      if (ours > ref) return (ours - ref) / ref;
      if (ours >= ref - ds) return 0.0;
      return (ref - ds - ours) / ref;
    };
    INFO(row.side << " y_ws = " << row.y_ws * 1e3 << " mm: 2a " << 2 * h.a * 1e3 << " vs " << row.length * 1e3
                  << ", 2b " << 2 * h.b * 1e3 << " vs " << row.width * 1e3);
    CHECK(err(2 * h.a, row.length) < 0.05);
    CHECK(err(2 * h.b, row.width) < 0.05);
    worst = std::max({worst, err(2 * h.a, row.length), err(2 * h.b, row.width)});
    ++n;
  }
  WARN(n << " Hertzian positions, worst semi-axis error beyond element rounding " << worst * 100 << " %");
  CHECK(n >= 35);
}

TEST_CASE("Semi-Hertz rejects bad input", "[geometry][semi_hertz][errors]") {
  SemiHertzWorkspace ws;
  GapProfile gp;
  CHECK_THROWS_AS(semi_hertz_from_load(gp, 1e4, Material{}, ws), InputError);
  for (int j = 0; j < 11; ++j) {
    gp.q.push_back(j * 1e-4);
    gp.h.push_back(1e-3 * (j - 5) * (j - 5) * 1e-8);
    gp.A.push_back(1.0);
  }
  CHECK_THROWS_AS(semi_hertz_from_load(gp, -1.0, Material{}, ws), InputError);
}
