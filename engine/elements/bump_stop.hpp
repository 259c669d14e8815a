// Bump stop / piecewise-linear spring between two markers along one track
// axis. The force magnitude is a piecewise-linear function of the deflection
// magnitude |Delta| given as a table of (deflection, force) points starting
// at (clearance, 0); below the first point the force is zero (free play),
// beyond the last point the last slope continues. The force on body a is
//   F_a = -sign(Delta) f(|Delta|)    (symmetric stop),
// with Delta the relative displacement of marker a w.r.t. marker b along the
// axis (spring_damper.hpp). Units: m, N.
#pragma once

#include <string>
#include <vector>

#include "engine/elements/spring_damper.hpp"

namespace railsim::engine {

struct BumpStop {
  std::string name;
  int body_a = -1, body_b = -1;
  Eigen::Vector3d r_a = Eigen::Vector3d::Zero(), r_b = Eigen::Vector3d::Zero();
  int axis = 1;                       // 0 x, 1 y, 2 z
  std::vector<double> deflection;     // increasing, >= 0 [m]
  std::vector<double> force;          // >= 0 [N], first entry 0
};

// Force magnitude for a deflection magnitude (piecewise-linear table).
double bump_stop_force(const BumpStop& e, double deflection);
void apply_bump_stop(const BumpStop& e, const std::vector<BodyMotion>& m, std::vector<GenForce>& f);

}  // namespace railsim::engine
