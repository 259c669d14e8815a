// The vehicle's (quasi-)static state at the start of a run: positions (and
// the full model's spin perturbations and the yaw dampers' elongations) for
// which every body is at rest in its track frame at t = 0, at the run's speed
// V(t0) and track distance s(t0) (the creep forces of a wheelset in a curve
// need the speed: the state balances them against the cant deficiency and the
// suspension). With x = (q, v, beta, e) and x' = f(t0, x) the model's own
// right-hand side (system.hpp), find
//   v = 0,  a(q, 0, beta, e) = 0,  beta' = 0,  e' = 0.
// On straight level track it is the nominal state (x = 0: the static wheel
// loads, finalize_model); in a curve, on cant, or with a track irregularity
// under a wheel it is the quasi-static curving state, so that a run starts
// without a transient that is only the model settling. The user's initial
// deviations (the scenario's `initial:`) are added on top of it.
//
// Method (static_equilibrium), stage by stage until one converges:
//  1. Newton from x = 0 on the m = (positions, beta, e) unknowns and the
//     acceleration rows, the Jacobian by coloured differences (ModelOde),
//     steps scaled so that no wheelset moves by more than 1 mm / 2 mrad, then
//     halved until the merit ||W g|| falls (W: generalised masses, so that
//     the residual is a set of forces and moments). Converges on straight
//     track and, for the full wheelset model, in the body of
//     R 300 m with 150 mm cant (16-18 iterations).
//  2. In a curve x = 0 is far from equilibrium: every body sits on the centre
//     line of its own track frame, so the suspension carries the curve's
//     versine and heading change between the bodies (the car body, a chord
//     between its bogies 19 m apart, sits kappa L^2 / 8 = 0.15 m inside the
//     centre line at R 300 m; its bogies are yawed 32 mrad against it). The
//     lateral model's Newton, its merit falling all the way, walks ws3 up its
//     flange and out of the geometry, also from the stage-2 start (a root
//     finder has no notion of the dynamics' stability; probably because on
//     the flank the lateral model's quasi-static load Q gives a lateral
//     reaction Q tan(delta) that grows with the contact angle, so the forces
//     on ws3 balance better as it climbs). So first: Newton on
//     the suspension alone, the wheelsets held at x = 0 (5 iterations; a
//     nearly linear problem), then Newton on everything from there.
//  3. When that fails too, pseudo-transient continuation from the stage-2
//     suspension state (Kelley & Keyes 1998, "Convergence analysis of
//     pseudo-transient continuation", SIAM J. Numer. Anal. 35: 508-523):
//     linearly implicit Euler steps of the damped dynamics frozen at (t0, s0),
//       (I / dt_k - J(x_k)) dx = f(t0, x_k),  x_{k+1} = x_k + dx,
//     with the pseudo-time step grown by switched evolution relaxation
//     (Mulder & van Leer 1985, J. Comput. Phys. 59: 232-246),
//       dt_{k+1} = dt_k ||f(x_{k-1})|| / ||f(x_k)||  (factor clamped to 0.5-4),
//     from 1 ms to 1e8 s, i.e. from the vehicle's own damped motion (creep
//     damping at speed V, dampers, the numerical damping of implicit Euler) to
//     Newton on the full system; a step that would move a wheelset by more
//     than 1 mm / 2 mrad, or where the model fails, is retried with dt / 4.
//     It follows the dynamics to the state a run settles to, not to any root:
//     63 steps for the lateral model in that curve. Newton polishes the result
//     (one iteration). ||.|| weights the acceleration rows by the generalised
//     masses and the velocity rows by mass / 0.1 s.
// Convergence: largest |acceleration| <= tolerance [m/s^2, rad/s^2] (and for
// the pseudo-transient stage every velocity too [m/s, rad/s]). Measured, the
// coach at 80 km/h in R 300 m / 150 mm (tests/engine/test_equilibrium.cpp):
// residual 7e-8 (lateral) and 3e-8 (full), t = 0 loads within 0.004 % of a
// settled run's. When no stage converges the caller starts nominal and says
// so (scenario.cpp: a warning in summary.json with the residual).
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
  // static_equilibrium: the stages that found it ("newton", "held wheelsets +
  // newton", "held wheelsets + pseudo-transient + newton"; `iterations` are the
  // last Newton's), the other stages' counts and why the earlier stages failed.
  std::string method;
  int held_iterations = 0;     // Newton iterations with the wheelsets held, when that stage ran
  int pseudo_time_steps = 0;   // of the pseudo-transient stage, when it ran
  std::string newton_failure;  // why the earlier stages failed, when a later one ran
};

// The stages above at time t0 (at most `max_iterations` per Newton stage). No
// throw on non-convergence (the caller decides); NumericalError when the model
// fails at x = 0.
EquilibriumResult static_equilibrium(const Model& model, double t0 = 0.0, int max_iterations = 80,
                                     double tolerance = 1e-6);

// The stages on their own. Newton from `start` (its velocities set to zero);
// with hold_wheelsets the wheelsets stay where `start` puts them and only the
// other bodies (and the yaw dampers) are solved for.
EquilibriumResult newton_equilibrium(const Model& model, const Eigen::VectorXd& start, double t0, int max_iterations,
                                     double tolerance, bool hold_wheelsets = false);
// Pseudo-transient continuation from `start` until every acceleration and
// velocity is below `tolerance` [m/s^2, rad/s^2; m/s, rad/s], at most
// `max_steps` pseudo-time steps; `iterations` counts them.
EquilibriumResult pseudo_transient_equilibrium(const Model& model, const Eigen::VectorXd& start, double t0,
                                               int max_steps, double tolerance);

}  // namespace railsim::engine
