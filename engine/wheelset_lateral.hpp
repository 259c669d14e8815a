// Wheelset model "lateral": lateral shift y and yaw psi are states; the
// vertical wheel loads follow from quasi-static equilibrium of the wheelset
// (no vertical or roll inertia), the normal loads from the contact angle.
//
// With Fz, Mx, Fy the vertical force, roll moment (about the wheelset centre)
// and lateral force of everything except the contacts (suspension, gravity,
// inertial frame loads), and a_L, a_R the lateral contact positions:
//   Q_L + Q_R = -Fz                                  (vertical equilibrium)
//   a_L Q_L - a_R Q_R = -Mx + r0 Fy                   (roll equilibrium, with the
//                                                    contact lateral forces taken
//                                                    as -Fy: lateral inertia neglected)
//   N = Q / cos(delta)
// Contact forces per wheel (side = +1 left, -1 right), contact-frame creep
// forces (Fx, Fy, Mz) from wheel_rail_coupling, resolved in track axes:
//   Y  = Fy cos(delta) - side N sin(delta) + Fx psi - side F_flange
//   X  = Fx - Fy psi cos(delta)
//   yaw moment  -side a (X + Y psi) + Mz cos(delta)
// (DYTSI's resolution, cooperrider-car.md §7.6) with theta = delta + side phi
// in place of delta when the roll is kinematic. Kinematic roll (Model::
// kinematic_roll): the rigid wheelset's roll from the geometry when it knows
// it (ContactGeometry::rigid_roll: profiles), else the rolling-radius
// difference on knife-edge rails, phi = (r_L - r_R) / (a_L + a_R) (tables,
// cones); phidot = dphi/dy ydot (set
// before the force elements act, so the suspension sees it; it also enters
// the lateral creepage through r phidot). The lateral components
// -side N sin(theta) give the gravitational stiffness (contact angle varying
// with y, and roll). The spin speed is V/r0 (no spin perturbation).
// Relative lateral motion: y - y_track, y_track = mean of the rails' lateral
// irregularities. Stops (Data::fail) on wheel lift-off (Q < 0) and when |y|
// leaves the geometry's range.
// Several contact points per wheel (profiles geometry, multi-point tables with
// N0, q0 per point): the wheel's load Q is shared by a common vertical
// approach change dw, N_k = N0_k (1 + (dw cos(delta_k) - gap_k)/q0_k)^{3/2}
// (the full model's load law, wheelset_full.cpp), with dw solved from
// sum N_k cos(theta_k) = Q (monotone; Newton from above, bisection guard). The
// split of Q between the wheels uses the main points' lateral positions.
#pragma once

#include "engine/data.hpp"
#include "engine/model.hpp"

namespace railsim::engine {

// Sets the quasi-static roll (and roll rate) of wheelset w in data.motion
// from its lateral motion (before the force elements are evaluated).
void wheelset_lateral_kinematics(const Model& model, Data& data, int w);

// Adds the contact forces of wheelset w to data.force; false on failure.
bool wheelset_lateral_forces(const Model& model, Data& data, int w);

}  // namespace railsim::engine
