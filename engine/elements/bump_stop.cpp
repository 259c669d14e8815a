// Piecewise-linear bump stop; see bump_stop.hpp.
#include "engine/elements/bump_stop.hpp"

#include <cmath>

namespace railsim::engine {

double bump_stop_force(const BumpStop& e, double x) {
  const auto& X = e.deflection;
  const auto& F = e.force;
  if (X.empty() || x <= X.front()) return 0.0;
  const std::size_t n = X.size();
  std::size_t i = 1;
  while (i < n - 1 && x > X[i]) ++i;
  const double slope = (F[i] - F[i - 1]) / (X[i] - X[i - 1]);
  return F[i - 1] + slope * (x - X[i - 1]);
}

void apply_bump_stop(const BumpStop& e, const std::vector<BodyMotion>& m, std::vector<GenForce>& f) {
  Eigen::Vector3d d, v;
  relative_motion(m, e.body_a, e.r_a, e.body_b, e.r_b, d, v);
  const double delta = d[e.axis];
  const double mag = bump_stop_force(e, std::abs(delta));
  if (mag == 0.0) return;
  Eigen::Vector3d F = Eigen::Vector3d::Zero();
  F[e.axis] = delta > 0 ? -mag : mag;
  apply_pair(f, e.body_a, e.r_a, e.body_b, e.r_b, F);
}

}  // namespace railsim::engine
