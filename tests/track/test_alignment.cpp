// Alignment: continuity at the joints, heading and position against an
// independent numerical integration of the curvature (Boost.Odeint, Dormand-
// Prince 5(4) with tight tolerances), derivatives against finite differences.
#include <catch2/catch.hpp>

#include <boost/numeric/odeint.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "test_support.hpp"
#include "track/alignment.hpp"
#include "track/circular_curve.hpp"
#include "track/clothoid.hpp"
#include "track/straight.hpp"
#include "track/track_file.hpp"

using namespace railsim::track;
using railsim::test::source_path;

namespace {

// S-curve with every transition shape, both curve directions and a start pose.
Alignment reverse_curve(TransitionShape shape) {
  std::vector<std::unique_ptr<Segment>> segs;
  const double k1 = 1.0 / 400.0, E1 = 0.12, k2 = -1.0 / 250.0, E2 = -0.15;
  segs.push_back(std::make_unique<Straight>(40.0));
  segs.push_back(std::make_unique<Clothoid>(60.0, 0.0, k1, 0.0, E1, shape));
  segs.push_back(std::make_unique<CircularCurve>(150.0, k1, E1));
  segs.push_back(std::make_unique<Clothoid>(90.0, k1, k2, E1, E2, shape));
  segs.push_back(std::make_unique<CircularCurve>(700.0, k2, E2));  // ~2.8 rad of turn
  segs.push_back(std::make_unique<Clothoid>(70.0, k2, 0.0, E2, 0.0, shape));
  segs.push_back(std::make_unique<Straight>(30.0));
  return Alignment(std::move(segs), 1.5, Pose{10.0, -5.0, 0.3});
}

// Integrate psi' = kappa(s), x' = cos psi, y' = sin psi along the alignment
// with odeint (one integration per segment so the integrator never steps
// across a kink of kappa'), recording the state at the points `at`.
std::vector<std::array<double, 3>> integrate_curvature(const Alignment& a, const std::vector<double>& at) {
  namespace odeint = boost::numeric::odeint;
  using State = std::array<double, 3>;
  auto rhs = [&a](const State& q, State& dq, double s) {
    dq[0] = a.at(s).curvature;
    dq[1] = std::cos(q[0]);
    dq[2] = std::sin(q[0]);
  };
  const AlignmentState st0 = a.at(0.0);
  State q = {st0.heading, st0.x, st0.y};
  std::vector<std::array<double, 3>> out;
  double s = 0.0;
  auto stepper = odeint::make_controlled(1e-13, 1e-13, odeint::runge_kutta_dopri5<State>());
  for (double target : at) {
    // Split at the joints between s and target.
    for (int i = 1; i <= a.segment_count(); ++i) {
      const double j = a.segment_start(i);
      if (j > s && j < target) {
        odeint::integrate_adaptive(stepper, rhs, q, s, j, 0.01);
        s = j;
      }
    }
    if (target > s) odeint::integrate_adaptive(stepper, rhs, q, s, target, 0.01);
    s = target;
    out.push_back(q);
  }
  return out;
}

}  // namespace

TEST_CASE("curvature and cant and their rates are continuous at the joints", "[tracks][alignment]") {
  for (TransitionShape shape : {TransitionShape::linear, TransitionShape::bloss, TransitionShape::cosine}) {
    const Alignment a = reverse_curve(shape);
    double worst_k = 0, worst_E = 0, worst_psi = 0, worst_p = 0;
    for (int i = 1; i < a.segment_count(); ++i) {
      // Design values at the joint from both sides: the end of segment i-1 and the start of segment i.
      const Segment& p = a.segment(i - 1);
      const Segment& q = a.segment(i);
      const Derivs kl = p.curvature(p.length()), kr = q.curvature(0.0);
      const Derivs El = p.cant(p.length()), Er = q.cant(0.0);
      worst_k = std::max(worst_k, std::abs(kl.v - kr.v));
      worst_E = std::max(worst_E, std::abs(El.v - Er.v));
      // The transition shapes that promise a continuous curvature rate deliver it.
      if (shape != TransitionShape::linear) {
        CHECK(std::abs(kl.d1 - kr.d1) < 1e-15);
        CHECK(std::abs(El.d1 - Er.d1) < 1e-15);
      }
      // Heading and position through the evaluator, 1e-9 m either side of the joint.
      const double j = a.segment_start(i), eps = 1e-9;
      const AlignmentState l = a.at(j - eps), r = a.at(j + eps);
      worst_psi = std::max(worst_psi, std::abs(l.heading - r.heading));
      worst_p = std::max(worst_p, std::hypot(l.x - r.x, l.y - r.y) - 2 * eps);
    }
    CHECK(worst_k < 1e-15);
    CHECK(worst_E < 1e-14);
    CHECK(worst_psi < 1e-10);  // what 2e-9 m of curvature turns, plus round-off
    CHECK(worst_p < 1e-10);    // beyond the 2e-9 m moved
    std::printf("[alignment %s] max jump at joints: kappa %.2e 1/m, cant %.2e m, heading %.2e rad, position %.2e m\n",
                transition_shape_name(shape), worst_k, worst_E, worst_psi, worst_p);
  }
}

TEST_CASE("heading and position agree with odeint integration of the curvature", "[tracks][alignment]") {
  for (TransitionShape shape : {TransitionShape::linear, TransitionShape::bloss, TransitionShape::cosine}) {
    const Alignment a = reverse_curve(shape);
    std::vector<double> at;
    for (double s = 7.3; s < a.length(); s += 13.7) at.push_back(s);
    at.push_back(a.length());
    const auto ref = integrate_curvature(a, at);
    double worst_rel_pos = 0, worst_rel_psi = 0;
    for (std::size_t i = 0; i < at.size(); ++i) {
      const AlignmentState st = a.at(at[i]);
      // Relative to the distance travelled (position) and the heading reached.
      const double dpos = std::hypot(st.x - ref[i][1], st.y - ref[i][2]) / at[i];
      const double dpsi = std::abs(st.heading - ref[i][0]) / std::max(std::abs(ref[i][0]), 1.0);
      worst_rel_pos = std::max(worst_rel_pos, dpos);
      worst_rel_psi = std::max(worst_rel_psi, dpsi);
    }
    CHECK(worst_rel_pos < 1e-6);
    CHECK(worst_rel_psi < 1e-6);
    std::printf("[alignment %s] vs odeint over %zu points: position %.2e (rel. to s), heading %.2e (rel.)\n",
                transition_shape_name(shape), at.size(), worst_rel_pos, worst_rel_psi);
  }
}

TEST_CASE("shipped curve files agree with odeint and reach the design radius and cant", "[tracks][alignment]") {
  for (const char* f : {"tracks/curve_R300.yaml", "tracks/curve_R1000.yaml", "tracks/curve_twist.yaml"}) {
    const Track t = load_track(source_path(f));
    const Alignment& a = t.alignment();
    std::vector<double> at;
    for (double s = 5.0; s < a.length(); s += 5.0) at.push_back(s);
    const auto ref = integrate_curvature(a, at);
    double worst = 0;
    for (std::size_t i = 0; i < at.size(); ++i) {
      const AlignmentState st = a.at(at[i]);
      worst = std::max(worst, std::hypot(st.x - ref[i][1], st.y - ref[i][2]) / at[i]);
      CHECK(std::abs(st.heading - ref[i][0]) < 1e-9);
    }
    CHECK(worst < 1e-6);
    std::printf("[%s] position vs odeint: %.2e relative\n", f, worst);
  }
  // Design values in the full curve.
  const Track r300 = load_track(source_path("tracks/curve_R300.yaml"));
  const AlignmentState mid = r300.alignment_at(330.0);
  CHECK(mid.curvature == Approx(-1.0 / 300.0).epsilon(1e-14));
  CHECK(mid.cant == Approx(-0.150).epsilon(1e-14));
  CHECK(mid.cant_angle == Approx(std::asin(-0.150 / 1.5)).epsilon(1e-14));
}

TEST_CASE("reported rates match finite differences of the reported values", "[tracks][alignment]") {
  for (TransitionShape shape : {TransitionShape::linear, TransitionShape::bloss, TransitionShape::cosine}) {
    const Alignment a = reverse_curve(shape);
    const double h = 1e-3;
    for (double s = 41.0; s < a.length() - 1.0; s += 9.1) {
      const AlignmentState m = a.at(s - h), c = a.at(s), p = a.at(s + h);
      if (m.segment != p.segment) continue;  // no differences across a joint
      CHECK(c.dcurvature == Approx((p.curvature - m.curvature) / (2 * h)).margin(1e-10));
      CHECK(c.dcant == Approx((p.cant - m.cant) / (2 * h)).margin(1e-9));
      CHECK(c.dcant_angle == Approx((p.cant_angle - m.cant_angle) / (2 * h)).margin(1e-9));
      CHECK(c.d2cant_angle == Approx((p.cant_angle - 2 * c.cant_angle + m.cant_angle) / (h * h)).margin(2e-6));
      CHECK(c.d2curvature == Approx((p.curvature - 2 * c.curvature + m.curvature) / (h * h)).margin(2e-8));
      // Heading is the integral of curvature: d psi / ds = kappa.
      CHECK(c.curvature == Approx((p.heading - m.heading) / (2 * h)).margin(1e-9));
      // Position moves along the heading: (dx, dy)/ds = (cos psi, sin psi).
      CHECK((p.x - m.x) / (2 * h) == Approx(std::cos(c.heading)).margin(1e-8));
      CHECK((p.y - m.y) / (2 * h) == Approx(std::sin(c.heading)).margin(1e-8));
    }
  }
}

TEST_CASE("outside its ends the alignment continues with the end curvature and cant", "[tracks][alignment]") {
  const Alignment a = reverse_curve(TransitionShape::linear);
  const AlignmentState e = a.at(a.length()), b = a.at(a.length() + 25.0);
  CHECK(b.segment == a.segment_count());
  CHECK(b.curvature == e.curvature);
  CHECK(b.cant == e.cant);
  CHECK(b.heading == Approx(e.heading).margin(1e-14));  // the last segment is straight
  CHECK(std::hypot(b.x - e.x, b.y - e.y) == Approx(25.0).epsilon(1e-12));
  const AlignmentState s0 = a.at(0.0), before = a.at(-10.0);
  CHECK(before.segment == -1);
  CHECK(before.x == Approx(s0.x - 10.0 * std::cos(0.3)).epsilon(1e-14));
  CHECK(before.y == Approx(s0.y - 10.0 * std::sin(0.3)).epsilon(1e-14));
}
