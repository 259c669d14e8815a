// Wheelset model "full": lateral y, vertical z, roll phi, yaw psi (with
// velocities) and the spin perturbation beta (Omega = V/r0 + beta) are states;
// pitch is not (it is the spin). Elastic normal contact by Hertz approach:
//   dq = [(r(s) - r0) - (z - z_rail) - side a phi] cos(delta)   (conical wheels)
//   dq = -[(z - z_rail) + side a phi] cos(delta)                 (tables, as DYTSI,
//                                                                 cooperrider-car.md §7.3)
//   N  = N0 (1 + dq/q0)^{3/2} for dq > -q0, else 0 (loss of contact: no force),
// with (N0, q0) the static load and its Hertz approach. Patch semi-axes scale
// with (N/N0)^{1/3} (wheel_rail_coupling). Contact forces resolved with the
// roll angle, theta = delta + side phi (DYTSI §7.6):
//   X = Fx - Fy psi cos(delta),  Y = Fx psi + Fy cos(theta) - side N sin(theta),
//   Z = side Fy sin(theta) + N cos(theta),
//   roll  M_x = side a Z + r Y,                    (DYTSI omits r Y; we keep it)
//   yaw   M_z = -side a (X + Y psi) + Mz cos(theta),
//   spin  M_y = -r (X + Y psi).
// Gyroscopic moments of the spinning axle in a non-spinning frame:
//   Ixx phi'' += Iyy Omega (psi' + V kappa),  Izz psi'' -= Iyy Omega phi'
// (psi' + V kappa: absolute yaw rate, the track frame turns at V kappa in a curve)
// (Resal frame; DYTSI uses the body-frame Euler form with (Iy - Iz), §7.7).
// Several contact points per wheel (one per table block, geometry_table.hpp):
// each point has its own approach, normal load and creep forces, all summed.
#pragma once

#include "engine/data.hpp"
#include "engine/model.hpp"

namespace railsim::engine {

// Adds contact and gyroscopic forces of wheelset w to data.force and writes
// the spin-perturbation derivative; false on failure.
bool wheelset_full_forces(const Model& model, Data& data, int w, const double* x, double* xdot);

}  // namespace railsim::engine
