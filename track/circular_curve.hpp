// Circular curve: constant curvature kappa = +-1/R (> 0 turning left) and
// constant cant E (see segment.hpp). Closed-form offset of an arc of length u:
//   x = sin(kappa u)/kappa,  y = (1 - cos(kappa u))/kappa = 2 sin^2(kappa u/2)/kappa
// (the second form avoids cancellation for small kappa u; kappa -> 0 gives the
// straight line). Units m, 1/m.
#pragma once

#include "track/segment.hpp"

namespace railsim::track {

// Offset of an arc of constant curvature `kappa` after length u (u may be
// negative: the arc continued backwards). Used for extrapolation too.
std::array<double, 2> arc_offset(double kappa, double u);

class CircularCurve final : public Segment {
 public:
  // kappa: signed curvature (+1/R left, -1/R right); cant E [m].
  CircularCurve(double length, double kappa, double cant);
  const char* kind() const override { return "circular"; }
  Derivs curvature(double) const override { return {kappa_, 0.0, 0.0}; }
  Derivs cant(double) const override { return {cant_, 0.0, 0.0}; }
  double heading_change(double u) const override { return kappa_ * u; }
  std::array<double, 2> offset(double u) const override { return arc_offset(kappa_, u); }

 private:
  double kappa_;
  double cant_;
};

}  // namespace railsim::track
