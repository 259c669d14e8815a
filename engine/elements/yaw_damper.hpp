// Yaw damper with series stiffness: a Maxwell element (spring k_s in series
// with a linear damper c) between two markers along the track x axis. The
// damper elongation e is a state of its own:
//   F_a = -k_s (Delta - e),   de/dt = k_s (Delta - e) / c,
// with Delta the relative x displacement of marker a w.r.t. marker b. At low
// frequency it acts as a damper c, above k_s/c [rad/s] as a spring k_s
// (Iwnicki 2006, Handbook of Railway Vehicle Dynamics, ch. 7). Units: N/m, N s/m.
#pragma once

#include <string>

#include "engine/elements/spring_damper.hpp"

namespace railsim::engine {

struct YawDamper {
  std::string name;
  int body_a = -1, body_b = -1;
  Eigen::Vector3d r_a = Eigen::Vector3d::Zero(), r_b = Eigen::Vector3d::Zero();
  double series_stiffness = 0.0;  // k_s [N/m]
  double damping = 0.0;           // c [N s/m]
  int state = -1;                 // index of e in the state vector
};

// Adds the force, returns de/dt.
double apply_yaw_damper(const YawDamper& e, double elongation, const std::vector<BodyMotion>& m,
                        std::vector<GenForce>& f);

}  // namespace railsim::engine
