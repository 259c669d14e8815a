// The recorder of a run (engine/analysis/run_history.hpp): running gear and
// measuring points from the vehicle's topology, the point accelerations an
// accelerometer reads (hand-computed from chosen state derivatives and track
// quantities), the lateral shift relative to the rails, and the quasi-static
// car-body acceleration of the coach in the R 300 m curve against the
// uncompensated acceleration of the track.
#include <catch2/catch.hpp>

#include <cmath>

#include "engine/analysis/run_history.hpp"
#include "engine/analysis/run_safety.hpp"
#include "engine/wheel_rail/track_flexibility.hpp"
#include "engine/analysis/track_zones.hpp"
#include "engine/io/scenario.hpp"
#include "engine/simulation.hpp"
#include "engine/track_input.hpp"
#include "test_support.hpp"

using namespace railsim;
using namespace railsim::engine;

namespace {
const AccelerationPoint& point(const RunHistory& h, const std::string& name) {
  for (const auto& p : h.points)
    if (p.name == name) return p;
  FAIL("no measuring point " << name);
  return h.points.front();
}
}  // namespace

TEST_CASE("running gear and measuring points of the Manchester coach", "[safety][history]") {
  const Scenario sc = load_scenario(test::source_path("scenarios/manchester_coach.yaml"));
  const RunHistory h(sc.model);
  REQUIRE(h.bogies.size() == 2);
  CHECK(h.bogies[0].name == "bogie1");
  CHECK(h.bogies[0].mass == Approx(2615.0 + 2 * 1813.0));
  CHECK(h.bogies[0].wheelsets.size() == 2);
  REQUIRE(h.car_bodies.size() == 1);
  CHECK(h.car_bodies[0] == "car");
  // 2 frame points per bogie, the car above both bogie centres and at its two ends.
  CHECK(h.points.size() == 8);
  CHECK(point(h, "bogie1@ws1").role == PointRole::bogie_frame_above_wheelset);
  CHECK(point(h, "bogie1@ws1").r.x() == Approx(10.78 - 9.5));
  CHECK(point(h, "car@bogie2").r.x() == Approx(-9.5));
  // Ends: above the outermost wheelsets unless given.
  CHECK(point(h, "car@end1").offset == Approx(10.78));
  CHECK(point(h, "car@end2").offset == Approx(-10.78));
  AccelerationOptions o;
  o.body_ends = {12.5, -12.5};
  const RunHistory h2(sc.model, o);
  CHECK(point(h2, "car@end1").r.x() == Approx(12.5));
  const auto names = h.channel_names();
  CHECK(std::find(names.begin(), names.end(), "ws1.y_rel") != names.end());
  CHECK(std::find(names.begin(), names.end(), "car.ay@bogie1") != names.end());
  CHECK(std::find(names.begin(), names.end(), "bogie2.az@ws4") != names.end());
  // A single bogie on the track has a frame but no car body; a lone wheelset neither.
  const RunHistory hb(load_scenario(test::source_path("scenarios/bogie.yaml")).model);
  CHECK(hb.bogies.size() == 1);
  CHECK(hb.car_bodies.empty());
  CHECK(hb.points.size() == 2);
  const RunHistory hw(load_scenario(test::source_path("scenarios/single_wheelset.yaml")).model);
  CHECK(hw.bogies.empty());
  CHECK(hw.points.empty());
}

TEST_CASE("point accelerations: relative kinematics, track frame and gravity through roll", "[safety][history]") {
  const Scenario sc = load_scenario(test::source_path("scenarios/manchester_coach.yaml"));
  const Model& m = sc.model;
  RunHistory h(m);
  Data d(m);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(m.n_states);
  d.xdot = Eigen::VectorXd::Zero(m.n_states);
  const int car = m.body_index("car");
  const RigidBody& b = m.bodies[car];
  const double phi = 0.01, ydd = 0.3, zdd = -0.2, phidd = 0.05, chidd = 0.02, psidd = 0.04;
  x[b.q_index[kRoll]] = phi;
  d.xdot[b.v_index[kLat]] = ydd;
  d.xdot[b.v_index[kVert]] = zdd;
  d.xdot[b.v_index[kRoll]] = phidd;
  d.xdot[b.v_index[kPitch]] = chidd;
  d.xdot[b.v_index[kYaw]] = psidd;
  TrackSample& T = d.track[car];
  T.curvature = 1.0 / 500.0;
  T.curvature_rate = 1.0 / (500.0 * 100.0);
  T.cant = 0.08;
  // Also a wheelset's rails shifted by 2 mm: its lateral shift relative to the rails.
  const int ws1 = m.wheelsets[0].body;
  x[m.bodies[ws1].q_index[kLat]] = 0.005;
  d.track[ws1].lat_left = d.track[ws1].lat_right = 0.002;
  rail_positions(m, d, x.data());  // where the rails are, as the right-hand side finds them
  h.record(m, 0.0, x, d);
  CHECK(h.wheelsets[0].y.back() == Approx(0.003));
  CHECK(h.wheelsets[0].y_absolute.back() == Approx(0.005));
  const double V = m.speed.v0, g = kGravity, c = std::cos(0.08), s = std::sin(0.08);
  // Above bogie 1: r = (9.5, 0, 0) from the car's CoM.
  const double rx = 9.5;
  const double fy = V * V * (T.curvature + T.curvature_rate * rx) * c - g * s;
  const double fz = V * V * T.curvature * s + g * c;
  const AccelerationPoint& p = point(h, "car@bogie1");
  CHECK(p.ay.back() == Approx(ydd + psidd * rx + fy + fz * phi).epsilon(1e-12));
  CHECK(p.az.back() == Approx(zdd - chidd * rx + fz - g - fy * phi).epsilon(1e-12));
  // The rear end, r = (-10.78, 0, 0).
  const double re = -10.78;
  const double fye = V * V * (T.curvature + T.curvature_rate * re) * c - g * s;
  CHECK(point(h, "car@end2").ay.back() == Approx(ydd + psidd * re + fye + fz * phi).epsilon(1e-12));
  // Recording needs the state derivative.
  Data no_derivative(m);
  CHECK_THROWS_AS(h.record(m, 0.0, x, no_derivative), std::invalid_argument);
}

TEST_CASE("coach in the R 300 m curve: quasi-static car-body acceleration is the uncompensated one and more",
          "[safety][history]") {
  // 80 km/h, R 300 m, 150 mm cant: a_nc = V^2/R cos(phi) - g sin(phi) = 0.656 m/s^2 toward the
  // centre (-y in this right-hand curve). The car body rolls outward on its suspension, so the
  // accelerometer reads more than a_nc (gravity through the roll adds), by the roll coefficient.
  const Scenario sc = load_scenario(test::source_path("scenarios/manchester_coach_curve_R300.yaml"));
  RunHistory h(sc.model);
  simulate(sc.model, sc.integrator, sc.x0, sc.duration, sc.output_interval,
           [&](double t, const Eigen::VectorXd& x, const Data& d) { h.record(sc.model, t, x, d); });
  const auto& track = dynamic_cast<const TrackInput&>(*sc.model.track).track();
  const RunSafety r = evaluate_run_safety(h, track_sections(track), 70.0 * M_PI / 180.0, 0.3);
  const double V = 80.0 / 3.6, phic = std::asin(0.150 / 1.5);
  const double anc = V * V / 300.0 * std::cos(phic) - kGravity * std::sin(phic);
  CHECK(anc == Approx(0.656).margin(0.002));
  for (const char* item : {"car@bogie1", "car@bogie2"}) {
    const Quantity* q = r.find("car_ay_qst", item);
    REQUIRE(q != nullptr);
    REQUIRE(q->sections.size() == 1);
    INFO(item << ": F0 = " << q->sections[0].p_mid);
    CHECK(q->sections[0].p_mid < 0.0);  // toward the centre of the right-hand curve
    CHECK(q->value > anc);
    CHECK(q->value < 1.5 * anc);
  }
}
