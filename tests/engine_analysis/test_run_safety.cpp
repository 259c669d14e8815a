// Running safety and curving evaluation of a recorded run (engine/analysis/
// run_safety.hpp, curving.hpp) on synthetic histories with hand-computed
// values: instantaneous Y/Q against Nadal, 2 m sliding means, where and when
// the maxima occur, the flange angle of a geometry, and curve-body statistics.
#include <catch2/catch.hpp>

#include <cmath>

#include "engine/analysis/curving.hpp"
#include "engine/analysis/run_safety.hpp"
#include "engine/conical_geometry.hpp"
#include "engine/geometry_table.hpp"
#include "test_support.hpp"

using namespace railsim::engine;

namespace {
constexpr double kDeg = M_PI / 180.0;

// One wheelset at offset +1 m; vehicle reference at 10 m/s from 0 m, samples every 0.01 s
// (0.1 m), so the wheelset runs from 1.0 m to 101.0 m. All loads 50 kN, Y = 0, then:
//  left wheel:  Y = 30 kN on the wheelset distances [40, 41] m (a 1 m plateau);
//               Q = 25 kN at the single sample 80 m (unloading 0.5);
//  right wheel: Y = 80 kN at the single sample 70 m (|Y/Q| = 1.6 > Nadal).
RunHistory synthetic_history() {
  RunHistory h;
  h.vehicle = "synthetic";
  h.total_mass = 10000;
  WheelsetHistory w;
  w.name = "ws1";
  w.offset = 1.0;
  w.static_wheel_load = 50e3;
  h.wheelsets.push_back(w);
  auto& ws = h.wheelsets[0];
  for (int i = 0; i <= 1000; ++i) {
    const double t = 0.01 * i, s = 10.0 * t, sw = s + 1.0;
    h.time.push_back(t);
    h.distance.push_back(s);
    h.speed.push_back(10.0);
    for (auto* v : {&ws.y, &ws.yaw, &ws.curvature, &ws.curvature_rate, &ws.cant}) v->push_back(0.0);
    const bool plateau = sw >= 40.0 - 1e-9 && sw <= 41.0 + 1e-9;
    const bool spike = std::abs(sw - 70.0) < 1e-6;
    const bool dip = std::abs(sw - 80.0) < 1e-6;
    ws.wheel[0].Y.push_back(plateau ? 30e3 : 0.0);
    ws.wheel[0].Q.push_back(dip ? 25e3 : 50e3);
    ws.wheel[1].Y.push_back(spike ? 80e3 : 0.0);
    ws.wheel[1].Q.push_back(50e3);
    for (auto& wl : ws.wheel)
      for (auto* v : {&wl.Fx, &wl.Fy, &wl.Mz, &wl.xi, &wl.eta, &wl.spin, &wl.Tgamma}) v->push_back(0.0);
  }
  return h;
}
}  // namespace

TEST_CASE("run safety of a synthetic history: Nadal, 2 m means, where and when", "[safety][run]") {
  const RunHistory h = synthetic_history();
  const double gamma = 70.0 * kDeg, mu = 0.3;
  const RunSafety r = evaluate_run_safety(h, gamma, mu);
  // Nadal (tan 70 - 0.3) / (1 + 0.3 tan 70) = 1.342 (physics-reference §9.1 table).
  CHECK(r.nadal == Approx(1.342).margin(5e-4));
  REQUIRE(r.en14363_evaluated);
  REQUIRE(r.wheelsets.size() == 1);
  const WheelsetSafety& w = r.wheelsets[0];
  // Left: instantaneous |Y/Q| = 30/50 = 0.6 first reached at 40 m (t = 3.9 s): below Nadal.
  CHECK(w.wheel[0].max_abs_yq.value == Approx(0.6));
  CHECK(w.wheel[0].max_abs_yq.distance == Approx(40.0).margin(1e-9));
  CHECK(w.wheel[0].max_abs_yq.time == Approx(3.9).margin(1e-9));
  CHECK(w.wheel[0].nadal_pass);
  // (Y/Q)_2m: the linearly interpolated plateau has the area 0.6 x (1.0 + 2 x 0.1 / 2) = 0.66 m,
  // best window centred at 40.5 m ([39.5, 41.5] holds it all): 0.66 / 2 = 0.33, at t = 3.95 s.
  CHECK(w.en14363.yq_left.max_abs == Approx(0.33).epsilon(1e-9));
  CHECK(w.en14363.yq_left.at_distance == Approx(40.5).margin(1e-9));
  CHECK(w.wheel[0].yq_2m_time == Approx(3.95).margin(1e-9));
  CHECK(w.en14363.yq_left.pass);
  // Right: one sample of Y/Q = 1.6 at 70 m fails Nadal (t = 6.9 s); its 2 m mean is the
  // triangle 1.6 x 0.2 / 2 = 0.16 m over 2 m = 0.08 and passes the 0.8 limit.
  CHECK(w.wheel[1].max_abs_yq.value == Approx(1.6));
  CHECK(w.wheel[1].max_abs_yq.distance == Approx(70.0).margin(1e-9));
  CHECK(w.wheel[1].max_abs_yq.time == Approx(6.9).margin(1e-9));
  CHECK_FALSE(w.wheel[1].nadal_pass);
  CHECK(w.en14363.yq_right.max_abs == Approx(0.08).epsilon(1e-9));
  // Sum Y: plateau 30 kN x 1.1 m = 33 kN m -> 16.5 kN at 40.5 m; Prud'homme 10 + 100/3 kN.
  CHECK(w.en14363.sum_y.max_abs == Approx(16.5e3).epsilon(1e-9));
  CHECK(w.sum_y_time == Approx(3.95).margin(1e-9));
  CHECK(w.en14363.sum_y.limit == Approx(43333.33).epsilon(1e-6));
  CHECK(w.en14363.sum_y.pass);
  // Unloading (50 - 25) / 50 = 0.5 at 80 m, t = 7.9 s: passes 0.6.
  CHECK(w.en14363.max_unloading == Approx(0.5));
  CHECK(w.en14363.unloading_at == Approx(80.0).margin(1e-9));
  CHECK(w.unloading_time == Approx(7.9).margin(1e-9));
  CHECK(w.en14363.unloading_pass);
  CHECK(w.en14363.pass);
  // Nadal fails on the right wheel, so the wheelset and the run fail.
  CHECK_FALSE(w.pass);
  CHECK_FALSE(r.pass);
  // With a steeper flange (75 deg, mu 0.1: Nadal 2.645) everything passes.
  CHECK(evaluate_run_safety(h, 75.0 * kDeg, 0.1).pass);
}

TEST_CASE("run safety: a vehicle that does not advance has no 2 m windows", "[safety][run]") {
  RunHistory h = synthetic_history();
  for (auto& s : h.distance) s = 5.0;
  const RunSafety r = evaluate_run_safety(h, 70.0 * kDeg, 0.3);
  CHECK_FALSE(r.en14363_evaluated);
  CHECK_FALSE(r.notes.empty());
  CHECK(r.wheelsets[0].wheel[1].max_abs_yq.value == Approx(1.6));
  CHECK_THROWS(evaluate_run_safety(RunHistory{}, 1.0, 0.3));
}

TEST_CASE("flange angle: conical wheels fall back to 70 deg, the S1002/UIC60 table has its flank", "[safety][run]") {
  ConicalParams p;
  p.flange_clearance = 0.009;
  p.flange_stiffness = 1.5e7;
  const FlangeAngle c = flange_angle(ConicalGeometry(p));
  CHECK(c.fallback);
  CHECK(c.angle == Approx(70.0 * kDeg));
  CHECK(c.source.find("fallback") != std::string::npos);
  const FlangeAngle t = flange_angle(GeometryTable(railsim::test::data_path("engine/rsgeo_1in10.dat")));
  INFO(t.source);
  CHECK_FALSE(t.fallback);
  // S1002 flank on UIC60 at 1:40: about 70 deg (physics-reference §9.1, "S1002 max flank angle").
  CHECK(t.angle / kDeg > 65.0);
  CHECK(t.angle / kDeg < 75.0);
}

TEST_CASE("curving statistics over the body of a circular curve", "[curving][run]") {
  // Two wheelsets at +-1 m, reference at 10 m/s from 0 to 200 m (0.5 m samples). Track at
  // track distance x: straight to 50 m, transition 50..70 m, circle R = 500 m left from 70 m.
  // Both wheelsets are in the circle from reference distance 71 m; with 50 m settling the
  // body starts at 121 m. Leading wheelset yaw -2 mrad (heads right = toward the outer
  // rail: angle of attack +2 mrad), trailing +0.5 mrad (-0.5 mrad); the leading right
  // (outer) wheel has Y/Q 0.3 and T-gamma 100 N in the circle, 0 elsewhere.
  RunHistory h;
  h.total_mass = 20000;
  for (double off : {1.0, -1.0}) {
    WheelsetHistory w;
    w.name = off > 0 ? "lead" : "trail";
    w.offset = off;
    w.static_wheel_load = 50e3;
    h.wheelsets.push_back(w);
  }
  for (int i = 0; i <= 400; ++i) {
    const double s = 0.5 * i;
    h.time.push_back(s / 10.0);
    h.distance.push_back(s);
    h.speed.push_back(10.0);
    for (auto& w : h.wheelsets) {
      const double x = s + w.offset;
      const bool circle = x >= 70.0;
      w.curvature.push_back(circle ? 1.0 / 500.0 : (x > 50.0 ? (x - 50.0) / (20.0 * 500.0) : 0.0));
      w.curvature_rate.push_back(!circle && x > 50.0 ? 1.0 / (20.0 * 500.0) : 0.0);
      w.cant.push_back(0.0);
      const bool lead = w.offset > 0;
      w.yaw.push_back(circle ? (lead ? -2e-3 : 0.5e-3) : 0.0);
      w.y.push_back(circle ? -4e-3 : 0.0);
      for (int k = 0; k < 2; ++k) {
        const bool hot = circle && lead && k == 1;
        w.wheel[k].Q.push_back(50e3);
        w.wheel[k].Y.push_back(hot ? 15e3 : 0.0);
        w.wheel[k].Tgamma.push_back(hot ? 100.0 : 0.0);
        for (auto* v : {&w.wheel[k].Fx, &w.wheel[k].Fy, &w.wheel[k].Mz, &w.wheel[k].xi, &w.wheel[k].eta,
                        &w.wheel[k].spin})
          v->push_back(0.0);
      }
    }
  }
  const auto curves = evaluate_curving(h);
  REQUIRE(curves.size() == 1);
  const CurveResult& c = curves[0];
  CHECK(c.curvature == Approx(1.0 / 500.0));
  CHECK(c.start == Approx(121.0));
  CHECK(c.end == Approx(200.0));
  CHECK(c.samples == 159);
  CHECK(c.unbalanced_acceleration == Approx(100.0 / 500.0));
  CHECK(c.expected_sum_Y == Approx(20000 * 0.2));
  CHECK(c.sum_Y == Approx(15e3));
  REQUIRE(c.wheelsets.size() == 2);
  CHECK(c.wheelsets[0].angle_of_attack.mean == Approx(2e-3));
  CHECK(c.wheelsets[1].angle_of_attack.mean == Approx(-0.5e-3));
  CHECK(c.wheelsets[0].lateral_shift.mean == Approx(4e-3));
  CHECK(c.wheelsets[0].wheel[1].outer);
  CHECK_FALSE(c.wheelsets[0].wheel[0].outer);
  CHECK(c.wheelsets[0].wheel[1].yq.mean == Approx(0.3));
  CHECK(c.wheelsets[0].wheel[1].yq.max == Approx(0.3));
  CHECK(c.wheelsets[0].wheel[1].Tgamma.mean == Approx(100.0));
  CHECK(c.wheelsets[1].wheel[1].Tgamma.max == Approx(0.0));
  // Straight track: no curves.
  for (auto& w : h.wheelsets) std::fill(w.curvature.begin(), w.curvature.end(), 0.0);
  CHECK(evaluate_curving(h).empty());
}
