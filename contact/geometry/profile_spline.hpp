// Parametric interpolating cubic spline through profile points, in chord length.
//
// Each coordinate (y and z) is a C2 cubic spline of the cumulative chord length
// t (t_0 = 0, t_i = t_{i-1} + |P_i - P_{i-1}|) with natural end conditions
// (second derivative zero at both ends). The second derivatives M_i solve the
// classic tridiagonal system (de Boor 1978, "A Practical Guide to Splines",
// ch. IV):  h_{i-1} M_{i-1} + 2 (h_{i-1} + h_i) M_i + h_i M_{i+1}
//            = 6 [(f_{i+1} - f_i)/h_i - (f_i - f_{i-1})/h_{i-1}].
// The parametric form handles vertical parts of a profile (rail sides, flange
// back) where z(y) is not a function. Curvature of the plane curve:
// kappa = (y' z'' - z' y'') / (y'^2 + z'^2)^{3/2}.
// Units: whatever the points are given in (railsim uses metres).
#pragma once

#include <vector>

namespace railsim::contact {

struct CurvePoint {
  double y = 0.0, z = 0.0;    // position
  double dy = 0.0, dz = 0.0;  // first derivative w.r.t. the chord parameter
  double ddy = 0.0, ddz = 0.0;  // second derivative
};

class ParametricSpline {
 public:
  ParametricSpline() = default;
  // Points must be distinct consecutively (checked by the profile reader).
  ParametricSpline(const std::vector<double>& y, const std::vector<double>& z);

  double length() const { return t_.empty() ? 0.0 : t_.back(); }
  // Evaluate at chord parameter t, clamped to [0, length()].
  CurvePoint eval(double t) const;
  const std::vector<double>& knots() const { return t_; }

 private:
  std::vector<double> t_, y_, z_, my_, mz_;
};

}  // namespace railsim::contact
