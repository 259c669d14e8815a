// Maxwell yaw damper; see yaw_damper.hpp.
#include "engine/elements/yaw_damper.hpp"

namespace railsim::engine {

double apply_yaw_damper(const YawDamper& e, double elongation, const std::vector<BodyMotion>& m,
                        std::vector<GenForce>& f) {
  Eigen::Vector3d d, v;
  relative_motion(m, e.body_a, e.r_a, e.body_b, e.r_b, d, v);
  const double spring = e.series_stiffness * (d.x() - elongation);
  apply_pair(f, e.body_a, e.r_a, e.body_b, e.r_b, Eigen::Vector3d(-spring, 0.0, 0.0));
  return spring / e.damping;
}

}  // namespace railsim::engine
