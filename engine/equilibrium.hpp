// The vehicle's (quasi-)static state at the start of a run: positions (and
// the full model's spin perturbations and the yaw dampers' elongations) for
// which every body is at rest in the track frame at t = 0, solved by Newton's
// method on the model's own right-hand side (velocities zero):
//   find q, beta, e such that  a(q, 0, beta, e) = 0,  beta' = 0,  e' = 0,
// with the Jacobian by coloured differences (system.hpp, ModelOde). On
// straight level track it is the nominal state (x = 0: the static wheel loads,
// finalize_model); in a curve, on cant, or with a track irregularity under a
// wheel it is the quasi-static curving state, so that a run starts without a
// transient that is only the model settling (the loads then agree with the
// static ones within the Newton tolerance). The user's initial deviations
// (the scenario's `initial:`) are added on top of it.
#pragma once

#include <Eigen/Core>
#include <string>

#include "engine/model.hpp"

namespace railsim::engine {

struct EquilibriumResult {
  Eigen::VectorXd x;     // the state (velocities zero)
  int iterations = 0;
  double residual = 0.0;  // max |acceleration| [m/s^2, rad/s^2] at the solution
  bool converged = false;
  std::string message;    // why not, when not converged
};

// Newton from x = 0 at time t0 (steps limited to 1 mm of wheelset shift and
// 2 mrad of yaw, halved until the residual falls); at most `max_iterations`. No throw on
// non-convergence (the caller decides); NumericalError when the model fails.
EquilibriumResult static_equilibrium(const Model& model, double t0 = 0.0, int max_iterations = 80,
                                     double tolerance = 1e-6);

}  // namespace railsim::engine
