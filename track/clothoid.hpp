// Transition curve between two curvatures and cants: the clothoid (linear
// change of curvature, physics-reference §10.1) and two smoother shapes.
//
//   kappa(u) = k0 + (k1 - k0) f(t),   E(u) = E0 + (E1 - E0) f(t),   t = u / L
//   heading change  dpsi(u) = k0 u + (k1 - k0) L F(t),  F(t) = int_0^t f
//
//   linear (clothoid, Euler spiral): f = t,               F = t^2/2
//   bloss  (Bloss 1936):             f = 3t^2 - 2t^3,      F = t^3 - t^4/2
//   cosine (sinusoidal ramp):        f = (1 - cos(pi t))/2, F = t/2 - sin(pi t)/(2 pi)
//
// The cant follows the same shape as the curvature (linear cant ramp for the
// clothoid). Bloss and cosine make dkappa/ds continuous at the joints.
// Offset = int_0^u (cos dpsi, sin dpsi): Gauss-Legendre quadrature (Boost.Math,
// 20 points) on sub-intervals of at most 0.25 rad of heading change, which
// integrates these smooth integrands to round-off. Units m, 1/m, rad.
#pragma once

#include <string_view>

#include "track/segment.hpp"

namespace railsim::track {

enum class TransitionShape { linear, bloss, cosine };
const char* transition_shape_name(TransitionShape s);

class Clothoid final : public Segment {
 public:
  // Curvature k0 -> k1 [1/m] and cant E0 -> E1 [m] over `length` [m].
  Clothoid(double length, double k0, double k1, double E0, double E1,
           TransitionShape shape = TransitionShape::linear);
  const char* kind() const override { return "clothoid"; }
  Derivs curvature(double u) const override;
  Derivs cant(double u) const override;
  double heading_change(double u) const override;
  std::array<double, 2> offset(double u) const override;
  TransitionShape shape() const { return shape_; }

 private:
  // Shape function f(t) and its t-derivatives.
  Derivs shape_at(double t) const;
  double k0_, k1_, E0_, E1_;
  TransitionShape shape_;
};

}  // namespace railsim::track
