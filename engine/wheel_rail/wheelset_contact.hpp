// Wheel-rail forces of one wheelset, for both wheelset models (one loop: the
// models differ only in how the normal loads are found).
//
// Per wheel (side = +1 left, -1 right) the contact geometry is evaluated once
// at the wheelset's shift relative to the rails, s = side y, and yaw as seen
// by the wheel, side psi (contact_geometry.hpp); every potential point k gets
// a normal load from its own approach through its own Hertz law
//   N_k = weight_k N0_k (1 + (dq_k - gap_k)/q0_k)^{3/2}  (0 when the bracket is negative),
//   dq_k = (w - dz_k) cos(delta_k),
// with w the wheel's vertical approach (positive presses the wheel into the
// rail) and dz_k the vertical motion of the point relative to the geometry's
// reference pose:
//  - "full": y, z, roll phi, yaw psi (with rates) and the spin perturbation
//    beta are states; dz_k = (z - z_rail) - h_ref + side a_k (phi - phi_ref),
//    w = w_s (the static approach that carries the static load at x = 0,
//    Wheelset::static_approach), (h_ref, phi_ref) the rigid pose
//    (ContactGeometry::rigid_pose) for geometries whose reference state is the
//    touching wheelset (profiles, cones), zero for tables whose reference state
//    already follows the shift (RSGEO, DYTSI's convention,
//    cooperrider-car.md §7.3).
//  - "lateral": y and psi are states, the roll follows the rigid pose
//    (kinematic roll; wheelset_kinematics), there is no vertical or roll
//    inertia: the vertical wheel loads Q_L, Q_R follow from the quasi-static
//    equilibrium of the wheelset,
//      Q_L + Q_R = -Fz,   a_L Q_L - a_R Q_R = -Mx + r0 Fy
//    (Fz, Mx, Fy: vertical force, roll moment and lateral force of everything
//    else; the contact lateral forces taken as -Fy: lateral inertia
//    neglected), with a_L, a_R the load-weighted lateral positions of each
//    wheel's points, and each wheel's Q is shared between its points by one
//    vertical approach w solved from sum_k N_k cos(theta_k) = Q (monotone;
//    Newton with a bisection guard).
// Creepages per point (creepages.hpp), creep forces (wheel_rail_coupling),
// resolved in track axes with theta = delta + side phi (DYTSI's resolution,
// cooperrider-car.md §7.6, with the point's lead x under yaw):
//   X = Fx - Fy psi cos(delta),  Y = Fx psi + Fy cos(theta) - side N sin(theta) - side F_flange,
//   Z = side Fy sin(theta) + N cos(theta),
//   roll  M_x = side a Z + r Y,  yaw  M_z = -side a (X + Y psi) + x Y + Mz cos(theta),
//   spin  M_y = -r (X + Y psi)  (the normal force passes through the axle).
// Gyroscopic moments of the spinning axle (full model): Ixx phi'' += Iyy Omega
// (psi' + V kappa), Izz psi'' -= Iyy Omega phi' (Resal frame).
// Stops (Data::fail) when |y| leaves the geometry's range and, in the lateral
// model, on wheel lift-off (Q < 0).
#pragma once

#include "engine/data.hpp"
#include "engine/model.hpp"

namespace railsim::engine {

// Lateral model: sets the kinematic roll (and roll rate) of wheelset w in
// data.motion from its lateral motion (before the force elements act).
void wheelset_kinematics(const Model& model, Data& data, int w);

// Adds the contact forces of wheelset w to data.force (full model: and the
// gyroscopic moments, and writes the spin-perturbation derivative into xdot);
// false on failure (data.failure says why).
bool wheelset_forces(const Model& model, Data& data, int w, const double* x, double* xdot);

// Normal loads of the points of one wheel carrying the vertical load Q, and the
// common vertical approach w that does it (the lateral model's load sharing;
// finalize_model uses it for the static approach). phi_side = side * roll.
// Points without a reference state use (N0_default, q0_default).
double share_wheel_load(const WheelGeometry& g, double Q, double phi_side, double N0_default,
                        double q0_default, double* N);

}  // namespace railsim::engine
