// Tests of contact/mim/profile_gap.cpp: the non-Hertzian S1002 / UIC60 1:40
// patch (Manchester contact benchmark, CONTACT's sweep, yaw 0, left wheel)
// from the geometry's gap profile, solved with the exact normal solver and
// compared with CONTACT's patch (same element size 0.2 mm).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "contact/geometry/profile.hpp"
#include "contact/geometry/wheel_rail_geometry.hpp"
#include "contact/mim/mim_model.hpp"
#include "contact/mim/profile_gap.hpp"
#include "contact/geometry/mbench_reference.hpp"
#include "core/errors.hpp"

using namespace railsim;
using namespace railsim::contact;
using namespace railsim::contact::mim;

TEST_CASE("S1002/UIC60 non-Hertzian patch matches CONTACT's", "[mim][profile_gap][mbench]") {
  const Profile w = read_profile("S1002", ProfileKind::wheel);
  const Profile r = read_profile("UIC60", ProfileKind::rail);
  TrackSetup ts;
  ts.inclination = std::atan(1.0 / 40.0);
  const WheelRailGeometry geo(w, r, ts);
  const Material m = Material::from_shear_modulus(82000e6, 0.28, 0.3);  // CONTACT's case (d)
  MimSolver solver;
  int compared = 0;
  for (const auto& row : test::read_mbench()) {
    if (row.series != "yaw0" || row.side != "left" || row.npatch != 1 || row.y_ws > 4.1e-3) continue;
    const auto c = geo.at_roll(-row.y_ws, 0.0, row.roll);
    const ContactPoint& p = c.wheel[0].p[0];
    const GapProfile gp = geo.gap_profile(Side::left, p, -row.y_ws, c.z[0], row.roll, 0.0, 0.014, 1401);
    const GapOnGrid gg = gap_from_profile(gp, 0.2e-3, 2.0 * row.pen);
    const MimSolution& s = solver.solve_normal(gg.grid, gg.h, row.FN, m);
    // Extent of the loaded elements.
    int imin = gg.grid.mx, imax = -1, jmin = gg.grid.my, jmax = -1;
    for (int j = 0; j < gg.grid.my; ++j)
      for (int i = 0; i < gg.grid.mx; ++i)
        if (s.pn[gg.grid.index(i, j)] > 0) imin = std::min(imin, i), imax = std::max(imax, i), jmin = std::min(jmin, j), jmax = std::max(jmax, j);
    const double area = s.n_contact * gg.grid.element_area();
    const double length = (imax - imin + 1) * gg.grid.dx, width = (jmax - jmin + 1) * gg.grid.dy;
    WARN("y_ws " << row.y_ws * 1e3 << " mm: area " << area * 1e6 << " mm2 (CONTACT " << row.area * 1e6 << "), pmax "
                 << s.normal.pmax / 1e6 << " MPa (" << row.pmax / 1e6 << "), approach " << s.approach * 1e3 << " mm ("
                 << row.pen * 1e3 << "), length " << length * 1e3 << " mm (" << row.length * 1e3 << "), width "
                 << width * 1e3 << " mm (" << row.width * 1e3 << "), grid " << gg.grid.mx << "x" << gg.grid.my);
    CHECK(s.normal.converged);
    CHECK(area == Approx(row.area).epsilon(0.05));
    CHECK(s.normal.pmax == Approx(row.pmax).epsilon(0.05));
    CHECK(s.approach == Approx(row.pen).epsilon(0.05));
    CHECK(std::abs(length - row.length) <= 2 * gg.grid.dx + 1e-9);
    CHECK(std::abs(width - row.width) <= 2 * gg.grid.dy + 1e-9);
    // Steady rolling on the non-Hertzian patch converges too.
    const MimSolution& t = solver.solve_gap(gg.grid, gg.h, row.FN, {0.001, 0.0, 0.5}, m);
    CHECK(t.converged());
    CHECK(t.Fx < 0.0);
    ++compared;
  }
  CHECK(compared >= 3);
}

TEST_CASE("gap profile conversion rejects bad input", "[mim][profile_gap]") {
  GapProfile gp;
  CHECK_THROWS_AS(gap_from_profile(gp, 0.2e-3, 1e-4), InputError);
  gp.q = {-1e-3, 0.0, 1e-3};
  gp.h = {1e-3, 0.0, 1e-3};
  gp.A = {1.0, 1.0, 1.0};
  CHECK_THROWS_AS(gap_from_profile(gp, 0.0, 1e-4), InputError);
  CHECK_THROWS_AS(gap_from_profile(gp, 0.2e-3, -1.0), InputError);
  const GapOnGrid g = gap_from_profile(gp, 0.2e-3, 1e-4);
  CHECK(g.grid.size() == static_cast<int>(g.h.size()));
  CHECK(*std::min_element(g.h.begin(), g.h.end()) < 2e-4);  // linear interpolation, centres at +-0.1 mm
}
