// The engine's view of real profiles (engine/wheel_rail/profile_geometry.hpp): the
// strip table against the exact contact search it was built from (shift and
// yaw between the nodes, mirror symmetry of the two wheels), loads that pass
// continuously through the flange root in both wheelset models (S1002 on
// UIC60 1:40, 6.0-6.5 mm), the lateral model's kinematic roll against
// CONTACT's, and scenario input errors.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <optional>

#include "contact/geometry/profile.hpp"
#include "contact/hertz.hpp"
#include "core/errors.hpp"
#include "engine/analysis/critical_speed.hpp"
#include "engine/data.hpp"
#include "engine/wheel_rail/profile_geometry.hpp"
#include "engine/io/scenario.hpp"
#include "engine/wheel_rail/strip_patches.hpp"
#include "engine/system.hpp"
#include "engine/engine_test_support.hpp"
#include "results/csv_writer.hpp"
#include "test_support.hpp"

using namespace railsim;
using namespace railsim::engine;

namespace {

ProfileGeometryParams s1002_uic60() {
  ProfileGeometryParams p;
  p.setup.inclination = std::atan(1.0 / 40.0);
  p.cache_dir = test::cache_dir();
  return p;
}

const ProfileGeometry& shared_geometry() {
  static const ProfileGeometry g(s1002_uic60(), contact::Material{});
  return g;
}

// The single wheelset on S1002/UIC60 1:40 profiles with linear creep, for the
// engine-level geometry tests; `models` holds the wheelset_model (and roll)
// lines, `spin` whether the spin creepage acts.
Scenario profiles_wheelset(const std::string& models, bool spin) {
  return test::scenario_from_text(
      "vehicle: vehicles/single_wheelset.yaml\n"
      "track: {segments: [{type: straight, length: 1000}]}\n"
      "speed: 30\nduration: 1\n" + models +
      "contact:\n  geometry: {type: profiles, wheel: S1002, rail: UIC60, inclination: 1/40, cache_dir: " +
      test::cache_dir() + "}\n  tangential: linear\n" + (spin ? "" : "  spin: false\n") +
      "  material: {E: 2.1e11, nu: 0.28, mu: 0.3}\n");
}

int state_index(const Scenario& sc, const std::string& name) {
  for (int i = 0; i < sc.model.n_states; ++i)
    if (sc.model.state_names[static_cast<std::size_t>(i)] == name) return i;
  return -1;
}

// Load-weighted lateral force per unit vertical load of one wheel (left-wheel
// view) carrying Q at the rigid pose: Y/Q = -sum N sin(theta) / sum N cos(theta).
double yq_at(const ProfileGeometry& g, double y, double yaw, double Q) {
  contact::StripSet s;
  g.strips(y, yaw, ProfileGeometry::kGapCutoff, s);
  RigidPose pose;
  g.rigid_pose(y, yaw, pose);
  StripLoads L;
  strip_approach_for_load(s, Q, pose.roll, g.contact_modulus(), L);
  double Y = 0.0, Z = 0.0;
  for (int k = 0; k < L.n; ++k) {
    Y -= L.N[k] * std::sin(L.patch[k].contact_angle + pose.roll);
    Z += L.N[k] * std::cos(L.patch[k].contact_angle + pose.roll);
  }
  return Y / Z;
}

}  // namespace

// Between the table's nodes (shift and yaw halfway between them) the
// interpolated strips match the exact contact search at the same strips: the
// rigid pose's roll, and each loaded strip's normal gap, angle, lead and height
// below the axle (CONTACT's rolling radius, r cos theta).
TEST_CASE("profile geometry: the strip table matches the exact search between its nodes", "[engine][geometry]") {
  const ProfileGeometry& g = shared_geometry();
  const contact::Profile wheel = contact::read_profile("S1002", contact::ProfileKind::wheel);
  const contact::Profile rail = contact::read_profile("UIC60", contact::ProfileKind::rail);
  const contact::WheelRailGeometry exact(wheel, rail, s1002_uic60().setup);
  int checked = 0;
  double worst_gap = 0.0, worst_angle = 0.0, worst_lead = 0.0, worst_height = 0.0;
  for (double y : {-0.00905, -0.00305, 0.00005, 0.00215, 0.00405, 0.00555, 0.00805, 0.01105})
    for (double yaw : {0.0, 0.0025, -0.0075, 0.0125, 0.0225}) {
      const contact::WheelsetContact c = exact.solve(y, yaw);
      RigidPose pose;
      g.rigid_pose(y, yaw, pose);
      INFO("y = " << y * 1e3 << " mm, yaw = " << yaw * 1e3 << " mrad");
      CHECK(pose.roll == Approx(c.roll).margin(2e-5 + 0.02 * std::abs(c.roll)));
      contact::StripSet s;
      g.strips(y, yaw, 0.2e-3, s);
      REQUIRE(s.n > 0);
      for (int j = 0; j < s.n; ++j) {
        const contact::StripPoint q = s[j];
        if (q.gap > 0.2e-3) continue;
        const contact::ContactPoint p =
            exact.point_at(contact::Side::left, g.table().strip_parameter(q.index), y, c.z[0], c.roll, yaw);
        worst_gap = std::max(worst_gap, std::abs(q.gap - p.gap));
        worst_angle = std::max(worst_angle, std::abs(q.angle - p.angle));
        // Lead in the wheelset's frame (ahead of the axle's vertical plane):
        // the track-frame x of the point rotated back by the yaw.
        const double lead = p.x * std::cos(yaw) + (p.y - y) * std::sin(yaw);
        worst_lead = std::max(worst_lead, std::abs(q.lead - lead));
        worst_height = std::max(worst_height, std::abs(q.height - p.height));
        CHECK(q.gap == Approx(p.gap).margin(10e-6));
        CHECK(q.angle == Approx(p.angle).margin(0.01));
        CHECK(q.lead == Approx(lead).margin(0.2e-3));
        CHECK(q.height == Approx(p.height).margin(0.05e-3));
        ++checked;
      }
    }
  INFO("largest differences: gap " << worst_gap << " m, angle " << worst_angle << " rad, lead " << worst_lead
                                   << " m, height " << worst_height << " m");
  CHECK(checked >= 200);
}

// Every strip quantity is C1 in the shift (issue 13 item 1): at table nodes
// the one-sided slopes (over 1/1000 of a cell) of the gap, angle, lateral
// position, lead, height below the axle, longitudinal curvature and Winkler
// factor agree to 2 % of the secants of the two cells that meet there, in
// tread and flange-root contact and with yaw. Linear interpolation in y, as
// the table had for the last five, jumps by the difference of the secants.
TEST_CASE("profile geometry: every strip quantity has a continuous slope across table nodes", "[engine][geometry]") {
  const ProfileGeometry& g = shared_geometry();
  const double cell = g.table().grid().y_step, h = 1e-3 * cell;
  const char* names[7] = {"gap", "angle", "lateral", "lead", "height", "A", "f"};
  auto field = [](const contact::StripPoint& p, int f) {
    const double v[7] = {p.gap, p.angle, p.lateral, p.lead, p.height, p.A, p.f};
    return v[f];
  };
  auto find = [](const contact::StripSet& set, int index) -> std::optional<contact::StripPoint> {
    for (int q = 0; q < set.n; ++q)
      if (set.index[q] == index) return set[q];
    return std::nullopt;
  };
  int checked = 0, jumping_secants = 0;
  for (double node : {-0.0061, -0.0021, 0.0, 0.0013, 0.0047, 0.0060, 0.0063, 0.0072})
    for (double yaw : {0.0, 0.0035, -0.012}) {
      contact::StripSet at[5];  // node - cell, node - h, node, node + h, node + cell
      const double ys[5] = {node - cell, node - h, node, node + h, node + cell};
      for (int e = 0; e < 5; ++e) g.strips(ys[e], yaw, 0.5e-3, at[e]);
      for (int j = 0; j < at[2].n; ++j) {
        const contact::StripPoint m = at[2][j];
        if (m.gap > 0.2e-3) continue;
        const std::optional<contact::StripPoint> p[5] = {find(at[0], m.index), find(at[1], m.index), m,
                                                         find(at[3], m.index), find(at[4], m.index)};
        if (!p[0] || !p[1] || !p[3] || !p[4]) continue;
        for (int f = 0; f < 7; ++f) {
          const double secl = (field(m, f) - field(*p[0], f)) / cell, secr = (field(*p[4], f) - field(m, f)) / cell;
          const double sl = (field(m, f) - field(*p[1], f)) / h, sr = (field(*p[3], f) - field(m, f)) / h;
          const double scale = std::max(std::abs(secl), std::abs(secr));
          if (!(scale > 0.0)) continue;
          INFO("node " << node * 1e3 << " mm, yaw " << yaw * 1e3 << " mrad, strip " << m.index << ", " << names[f]
                       << ": slopes " << sl << " / " << sr << ", cell secants " << secl << " / " << secr);
          // plus the rounding of the values over h (heights are ~0.46 m)
          const double rounding = 8e-16 * (std::abs(field(m, f)) + 1e-3) / h;
          CHECK(std::abs(sr - sl) <= 0.02 * scale + rounding);
          if (std::abs(secr - secl) > 0.02 * scale) ++jumping_secants;
          ++checked;
        }
      }
    }
  // The test has teeth: at many of these points neighbouring secants differ by
  // more than the tolerance, which a C0 interpolant would show as its jump.
  INFO("checked " << checked << ", secants differing by > 2 %: " << jumping_secants);
  CHECK(checked >= 300);
  CHECK(jumping_secants >= 50);
}

// Mirror symmetry: the table holds the left wheel; the right wheel of the
// exact search at (y, yaw) equals the left wheel's entry at (-y, -yaw).
TEST_CASE("profile geometry: the right wheel at -y, -yaw mirrors the left wheel", "[engine][geometry]") {
  const ProfileGeometry& g = shared_geometry();
  const contact::Profile wheel = contact::read_profile("S1002", contact::ProfileKind::wheel);
  const contact::Profile rail = contact::read_profile("UIC60", contact::ProfileKind::rail);
  const contact::WheelRailGeometry exact(wheel, rail, s1002_uic60().setup);
  for (double y : {-0.011, -0.006, 0.0, 0.003, 0.0061, 0.009})
    for (double yaw : {0.0, 0.005, -0.02}) {
      const contact::WheelsetContact c = exact.solve(y, yaw);
      const contact::ContactPoint& right = c.wheel[1].p[0];
      contact::StripSet s;
      g.strips(-y, -yaw, ProfileGeometry::kGapCutoff, s);
      int best = 0;
      for (int j = 1; j < s.n; ++j)
        if (std::abs(s.y_wheel[j] - right.y_wheel) < std::abs(s.y_wheel[best] - right.y_wheel)) best = j;
      const contact::StripPoint q = s[best];
      INFO("y = " << y * 1e3 << " mm, yaw = " << yaw * 1e3 << " mrad");
      if (std::abs(q.y_wheel - right.y_wheel) > 0.6e-3) continue;
      CHECK(q.angle == Approx(-right.angle).margin(0.03));             // the right wheel's angle is negative
      CHECK(q.lateral == Approx(-(right.y - y)).margin(0.6e-3));       // its lateral position is at -y
      // The lead (wheelset frame, ahead of the axle) is not mirrored.
      const double lead = right.x * std::cos(yaw) + (right.y - y) * std::sin(yaw);
      CHECK(q.lead == Approx(lead).margin(0.3e-3 + 0.05 * std::abs(lead)));
    }
}

// Across the flange root (the rigid touching point jumps from about 37 to 70
// degrees near 6.25 mm) the lateral force of a wheel carrying 50 kN rises
// steeply but continuously: no change of Y/Q per micrometre above 0.06 (a
// single-point geometry jumps by ~2 in one step), and ten times finer steps
// give ten times smaller changes where the curve is steepest (a jump would
// not shrink). The curve is written to the build's test output for the note.
TEST_CASE("profile geometry: Y/Q passes continuously through the flange root", "[engine][geometry]") {
  const ProfileGeometry& g = shared_geometry();
  results::CsvWriter out(test::cache_dir() + "/flange_root_yq.csv", {"y_mm", "yq_yaw0", "yq_yaw5mrad"}, false, 0, 8);
  double prev0 = 0.0, prev5 = 0.0, step0 = 0.0, step5 = 0.0, at0 = 0.0;
  for (int i = 0; i <= 500; ++i) {
    const double y = 6.0e-3 + i * 1e-6;
    const double a = yq_at(g, y, 0.0, 5e4), b = yq_at(g, y, 0.005, 5e4);
    if (i > 0) {
      if (std::abs(a - prev0) > step0) {
        step0 = std::abs(a - prev0);
        at0 = y;
      }
      step5 = std::max(step5, std::abs(b - prev5));
    }
    prev0 = a;
    prev5 = b;
    out.row({y * 1e3, a, b});
  }
  INFO("largest change of Y/Q per um: " << step0 << " at " << at0 * 1e3 << " mm (yaw 0), " << step5
                                        << " (yaw 5 mrad); Y/Q at 6.5 mm " << prev0);
  CHECK(yq_at(g, 6.0e-3, 0.0, 5e4) > -0.6);  // tread / flange root
  CHECK(prev0 < -1.5);                       // flank
  CHECK(step0 < 0.06);
  CHECK(step5 < 0.06);
  double fine = 0.0, prev = yq_at(g, at0 - 1e-6, 0.0, 5e4);
  for (int i = 1; i <= 10; ++i) {
    const double v = yq_at(g, at0 - 1e-6 + i * 1e-7, 0.0, 5e4);
    fine = std::max(fine, std::abs(v - prev));
    prev = v;
  }
  INFO("largest change per 0.1 um there: " << fine);
  CHECK(fine < 0.3 * step0);
}

// The same in the vehicle model: the full wheelset model at a fixed height and
// roll (the rigid pose's), and the lateral model at its quasi-static load (the
// single wheelset's 7.3 kN: a smaller approach, a steeper rise). The wheel's
// Y and Q are continuous: where they change most per micrometre of shift, ten
// times finer steps change them ten times less (a jump would not shrink).
TEST_CASE("profile geometry: both wheelset models load the flange root continuously", "[engine][geometry]") {
  for (const char* model : {"wheelset_model: full\n", "wheelset_model: lateral\n"}) {
    const Scenario sc = profiles_wheelset(model, false);
    const int lat = state_index(sc, "ws1.lateral");
    REQUIRE(lat >= 0);
    Data d(sc.model);
    Eigen::VectorXd x = Eigen::VectorXd::Zero(sc.model.n_states), xd(x.size());
    const int roll = state_index(sc, "ws1.roll"), vert = state_index(sc, "ws1.vertical");
    const auto& geo = *sc.model.wheelsets[0].geometry;
    auto wheel_at = [&](double y) {
      x[lat] = y;
      if (roll >= 0) {  // full model: the rigid pose's roll and height
        RigidPose p;
        geo.rigid_pose(y, 0.0, p);
        x[roll] = p.roll;
        x[vert] = p.height;
      }
      rhs_or_throw(sc.model, d, 0.0, x.data(), xd.data());
      return d.wheel[0];
    };
    const double W = sc.model.wheelsets[0].static_load[0];
    auto largest_steps = [&](double y0, double dy, int n, double& atY, double& atQ, double& sY, double& sQ) {
      WheelOutput prev = wheel_at(y0);
      sY = sQ = 0.0;
      for (int i = 1; i <= n; ++i) {
        const double y = y0 + i * dy;
        const WheelOutput w = wheel_at(y);
        if (std::abs(w.Y - prev.Y) > sY) {
          sY = std::abs(w.Y - prev.Y);
          atY = y - dy;
        }
        if (std::abs(w.Q - prev.Q) > sQ) {
          sQ = std::abs(w.Q - prev.Q);
          atQ = y - dy;
        }
        prev = w;
      }
    };
    double atY = 0, atQ = 0, sY = 0, sQ = 0, a = 0, b = 0, fY = 0, fQ = 0, dummy = 0;
    largest_steps(6.0e-3, 1e-6, 400, atY, atQ, sY, sQ);
    largest_steps(atY, 1e-7, 10, a, b, fY, dummy);
    largest_steps(atQ, 1e-7, 10, a, b, dummy, fQ);
    INFO(model << "largest change per um: Y " << sY / W << " W at " << atY * 1e3 << " mm, Q " << sQ / W << " W at "
               << atQ * 1e3 << " mm; per 0.1 um there: Y " << fY / W << " W, Q " << fQ / W << " W (W = " << W << " N)");
    CHECK(fY < 0.3 * sY);
    CHECK(fQ < 0.3 * std::max(sQ, 1e-3 * W));
  }
}

// The lateral model's kinematic roll with real profiles is the rigid
// wheelset's roll (ContactGeometry::rigid_pose), checked against the
// Manchester benchmark's equilibrium roll that CONTACT was run with
// (tests/data/reference/contact/mbench_S1002_UIC60_sweep.csv, series yaw0,
// y_ws = 0 .. 10 mm; CONTACT's roll is negative for a shift toward its
// wheel: the opposite sign convention). Same tolerance as the geometry's own
// test (tests/contact/geometry): 5 %, or 1e-5 rad near zero. The knife-edge
// formula (r_L - r_R)/(a_L + a_R) is 3-8 times larger there.
TEST_CASE("profile geometry: the lateral model's kinematic roll is the rigid wheelset roll", "[engine][geometry]") {
  const Scenario sc = profiles_wheelset("wheelset_model: lateral\nwheelset_roll: kinematic\n", true);
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
      "{type: profiles, wheel: S1002, rail: UIC60, inclination: 1/40, cache_dir: " + test::cache_dir() + "}"));
  CHECK(sc.geometry_description.find("S1002") != std::string::npos);
  const double v = linear_critical_speed(sc, 20.0, 200.0);
  CHECK(std::isfinite(v));
  CHECK_THROWS_WITH(load_scenario(with_geometry("{type: profiles, wheel: S1002, inclination: 1/0}")),
                    Catch::Contains("inclination"));
  CHECK_THROWS_WITH(load_scenario(with_geometry("{type: profiles, wheel: S1002, gauge: 3}")),
                    Catch::Contains("gauge"));
  CHECK_THROWS_WITH(load_scenario(with_geometry("{type: profiles, wheel: S1002, shape: round}")),
                    Catch::Contains("shape"));
  CHECK_THROWS_WITH(load_scenario(with_geometry("{type: profiles, wheel: S1002, max_yaw: 0.5}")),
                    Catch::Contains("max_yaw"));
  CHECK_THROWS_AS(load_scenario(with_geometry("{type: profiles, wheel: no_such_profile}")), InputError);
}

// The patch each shape hands to the tangential models against CONTACT's
// exact (boundary-element) contact area for S1002 on UIC60 1:40 at 10 kN
// (tests/data/reference/contact/mbench_S1002_UIC60_sweep.csv, series yaw0,
// both wheels, 0-10 mm; CONTACT's y_ws is positive to the right: the left
// wheel's view is y = -y_ws for the left wheel and +y_ws for the right one).
// Compared where CONTACT's grid (0.2 mm) resolves the patch (width >= 3 mm,
// one patch; 28 positions): tread contact. Measured: Hertz ellipse and
// semi-Hertz both within 7.7 % of the area (worst: the right wheel at 1 mm,
// +6.2 % / -7.7 %), typically 1-3 %; both 15-18 % below at the centred position
// (CONTACT's patch there is 15.8 mm wide, conformal: neither ellipse is).
// In flange contact (6.5-10 mm) CONTACT's patch is 0.8 mm wide (4 cells),
// too coarse to rank the two (Hertz -22..+4 %, semi-Hertz -54..+54 %).
TEST_CASE("profile geometry: patch areas in tread contact against CONTACT, both patch shapes", "[engine][geometry]") {
  const ProfileGeometry& g = shared_geometry();
  const auto ref = railsim::results::read_csv(test::reference_path("contact/mbench_S1002_UIC60_sweep.csv"));
  int compared = 0;
  double worst[2] = {0.0, 0.0};  // largest |area / CONTACT's - 1| per shape
  for (std::size_t i = 0; i < ref.rows.size(); ++i) {
    if (ref.rows[i][ref.column("series")] != "yaw0") continue;
    const bool left = ref.rows[i][ref.column("side")] == "left";
    const double y = (left ? -1.0 : 1.0) * ref.number(i, "y_ws_mm") * 1e-3;
    const double area = ref.number(i, "contact_area_mm2") * 1e-6, width = ref.number(i, "patch_width_s_mm") * 1e-3;
    if (ref.number(i, "npatch") != 1 || width < 3e-3 || width > 10e-3) continue;
    contact::StripSet s;
    g.strips(y, 0.0, ProfileGeometry::kGapCutoff, s);
    RigidPose pose;
    g.rigid_pose(y, 0.0, pose);
    for (int k = 0; k < 2; ++k) {
      const PatchShape shape = k == 0 ? PatchShape::hertz : PatchShape::semi_hertz;
      StripLoads L;
      strip_approach_for_load(s, ref.number(i, "FZ_tr_N"), pose.roll, g.contact_modulus(), L, shape);
      REQUIRE(L.n == 1);
      const double ours = M_PI * L.patch[0].semi_a * L.patch[0].semi_b;
      INFO((left ? "left" : "right") << " wheel, y = " << y * 1e3 << " mm, " << (k ? "semi-Hertz" : "Hertz")
                                     << ": area " << ours * 1e6 << " mm^2 vs CONTACT " << area * 1e6);
      CHECK(ours == Approx(area).epsilon(0.08));
      CHECK(L.N[0] == Approx(ref.number(i, "FN_N")).epsilon(0.01));
      worst[k] = std::max(worst[k], std::abs(ours / area - 1.0));
    }
    ++compared;
  }
  CHECK(compared >= 25);
  INFO("largest area deviation from CONTACT: Hertz " << worst[0] * 100 << " %, semi-Hertz " << worst[1] * 100 << " %");
  CHECK(worst[1] < 0.08);
}

namespace {
// The same patches to 1e-9: loads, ellipses, angles, positions, rate weights.
void check_same_patches(const StripLoads& a, const StripLoads& b) {
  REQUIRE(a.n == b.n);
  for (int k = 0; k < a.n; ++k) {
    CHECK(a.N[k] == Approx(b.N[k]).epsilon(1e-9));
    CHECK(a.patch[k].semi_a == Approx(b.patch[k].semi_a).epsilon(1e-9));
    CHECK(a.patch[k].semi_b == Approx(b.patch[k].semi_b).epsilon(1e-9));
    CHECK(a.patch[k].contact_angle == Approx(b.patch[k].contact_angle).epsilon(1e-9).margin(1e-12));
    CHECK(a.patch[k].lateral == Approx(b.patch[k].lateral).epsilon(1e-9));
    CHECK(a.rate_weight[k] == Approx(b.rate_weight[k]).epsilon(1e-9));
  }
}
}  // namespace

// The lateral model's load-to-approach solve (strip_approach_for_load: its
// evaluations run on the strips penetrated at the first upper bound only,
// and the last one yields the loads) against strip_loads over every strip at
// the approach it returns: it carries the load asked for (1e-9), on the
// S1002/UIC60 strips from the tread to the flange (one and two patches), both
// wheels' sides of the table (y of either sign), with yaw, a rolled vertical
// direction and both patch shapes: the same patches, loads and ellipses; also
// from warm starts.
TEST_CASE("profile geometry: load-to-approach solve equals the load pass at its approach", "[engine][geometry][strips]") {
  const ProfileGeometry& g = shared_geometry();
  int two_patch = 0, compared = 0, warm = 0;
  for (double y_mm = -12.0; y_mm <= 12.0; y_mm += 0.37) {
    for (double yaw : {0.0, 0.012}) {
      contact::StripSet s;
      g.strips(y_mm * 1e-3, yaw, ProfileGeometry::kGapCutoff, s);
      RigidPose pose;
      g.rigid_pose(y_mm * 1e-3, yaw, pose);
      for (double Q : {2e3, 5e4, 1.5e5})
        for (double phi : {0.0, pose.roll})
          for (PatchShape shape : {PatchShape::hertz, PatchShape::semi_hertz}) {
            StripLoads L, R;
            const double w = strip_approach_for_load(s, Q, phi, g.contact_modulus(), L, shape);
            strip_loads(s, w, 0.0, phi, g.contact_modulus(), R, true, shape);
            INFO("y " << y_mm << " mm, yaw " << yaw << ", Q " << Q << " N, roll " << phi);
            CHECK(L.vertical == Approx(Q).epsilon(1e-9));
            CHECK(R.vertical == Approx(Q).epsilon(1e-9));
            check_same_patches(L, R);
            two_patch += L.n >= 2;
            ++compared;
            // Warm starts (Data::approach_warm_start) below, at and above the
            // solution, near and far: the same approach and loads, and the
            // start handed back is the solution's.
            double exact = 0.0;
            strip_approach_for_load(s, Q, phi, g.contact_modulus(), R, shape, &exact);
            REQUIRE(exact > 0.0);
            for (double f : {0.3, 0.97, 1.0, 1.03, 3.0}) {
              INFO("warm start " << f << " x the solution's");
              double start = f * exact;
              StripLoads Lw;
              const double ww = strip_approach_for_load(s, Q, phi, g.contact_modulus(), Lw, shape, &start);
              CHECK(ww == Approx(w).epsilon(1e-9));
              CHECK(start == Approx(exact).epsilon(1e-8));
              CHECK(Lw.vertical == Approx(Q).epsilon(1e-9));
              check_same_patches(Lw, L);
              ++warm;
            }
          }
    }
  }
  CHECK(compared > 1500);
  CHECK(warm == 5 * compared);
  CHECK(two_patch > 0);
}
