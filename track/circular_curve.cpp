// Circular curve; see circular_curve.hpp.
#include "track/circular_curve.hpp"

#include <cmath>

namespace railsim::track {

std::array<double, 2> arc_offset(double kappa, double u) {
  const double a = kappa * u;
  if (std::abs(a) < 1e-8) {
    // Series: x = u - kappa^2 u^3/6, y = kappa u^2/2 (error ~ a^4 u, far below round-off here).
    return {u - kappa * kappa * u * u * u / 6.0, 0.5 * kappa * u * u};
  }
  const double h = std::sin(0.5 * a);
  return {std::sin(a) / kappa, 2.0 * h * h / kappa};
}

CircularCurve::CircularCurve(double length, double kappa, double cant)
    : Segment(length), kappa_(kappa), cant_(cant) {}

}  // namespace railsim::track
