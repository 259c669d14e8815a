// Linear spring-damper between two markers, acting along the three fixed
// track axes (x, y, z) separately (the usual linearised suspension element;
// cooperrider-car.md §5.1). With Delta = u_a - u_b the relative displacement
// of marker a (on body a) with respect to marker b (on body b) from the
// nominal configuration, the force on body a is
//   F_a = P - K Delta - C dDelta/dt,    F_b = -F_a,
// applied at the markers (moments r x F about each CoM). P is the preload on
// body a that holds the nominal configuration in static equilibrium (computed
// when the model is built). Body index -1 is the track-following frame.
// Units: N/m, N s/m, N.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "engine/elements/rigid_body.hpp"

namespace railsim::engine {

using GenForce = std::array<double, kNumDof>;

struct SpringDamper {
  std::string name;
  int body_a = -1, body_b = -1;
  Eigen::Vector3d r_a = Eigen::Vector3d::Zero();  // marker a relative to CoM of a [m]
  Eigen::Vector3d r_b = Eigen::Vector3d::Zero();  // marker b relative to CoM of b [m]
  Eigen::Vector3d k = Eigen::Vector3d::Zero();    // stiffness along x, y, z [N/m]
  Eigen::Vector3d c = Eigen::Vector3d::Zero();    // damping along x, y, z [N s/m]
  Eigen::Vector3d preload = Eigen::Vector3d::Zero();  // force on a at the nominal configuration [N]
};

// Relative displacement and velocity of marker a w.r.t. marker b.
void relative_motion(const std::vector<BodyMotion>& m, int a, const Eigen::Vector3d& ra, int b,
                     const Eigen::Vector3d& rb, Eigen::Vector3d& d, Eigen::Vector3d& v);
// Apply F on a at ra and -F on b at rb.
void apply_pair(std::vector<GenForce>& f, int a, const Eigen::Vector3d& ra, int b, const Eigen::Vector3d& rb,
                const Eigen::Vector3d& F);

// Adds the element's forces to f; returns the force on body a.
Eigen::Vector3d apply_spring_damper(const SpringDamper& e, const std::vector<BodyMotion>& m,
                                    std::vector<GenForce>& f);

}  // namespace railsim::engine
