// Creepages of one wheel from the wheelset motion, the track and the contact
// geometry (Kalker's definition: rigid slip velocity of the wheel at the
// contact point relative to the rail, divided by the speed V).
//
// side = +1 for the left wheel (y > 0), -1 for the right wheel. r, a, x,
// delta: rolling radius (height of the point below the axle), lateral contact
// position from the wheelset centre, lead of the point ahead of the axle under
// yaw, contact angle of that wheel's point (contact_geometry.hpp). y, z, phi, psi and rates: the
// wheelset's displacement relative to the rails (irregularities removed),
// roll and yaw relative to the track frame. Omega: wheelset spin speed
// (V/r0 nominal plus the spin perturbation beta). kappa: track curvature.
//   xi  = [V (1 - side a kappa) + psi ydot + r (psi phidot - Omega) - side a psidot] / V
//   eta = [(ydot + x psidot - V psi + phi zdot + r phidot) cos delta
//          + side (zdot - phi ydot + side a phidot - x Omega) sin delta] / V
//   phi_s = [(psidot + V kappa) cos delta - side (Omega - psi phidot) sin delta] / V   [1/m]
// For conical wheels (r = r0 + side lambda y, delta = 0) this reduces to the
// classical xi = -side (lambda y / r0 + a psidot / V), eta = ydot/V - psi
// (physics-reference §8.1). Straight-track terms after DYTSI
// (cooperrider-car.md §7.4); the curvature terms are the frame rotation
// V kappa (Wickens 2003, Fundamentals of Rail Vehicle Dynamics, ch. 2).
// The lead terms are the velocity of a point x ahead of the axle from the yaw
// rate (lateral, x psidot) and from the spin (vertical, -x Omega): in flange
// contact with an angle of attack the flange point leads by ~ r tan(delta)
// psi and the second term is the large lateral slip along the flange that
// drives flange climbing (e.g. Wickens 2003, ch. 8).
// Signs: positive xi = the wheel slides forward over the rail; positive eta =
// the wheel slides to the left (+y) in its contact plane; the creep forces
// (rail on wheel) oppose them (contact/types.hpp).
#pragma once

#include "contact/types.hpp"
#include "engine/wheel_rail/contact_geometry.hpp"

namespace railsim::engine {

struct WheelsetKinematics {
  double V = 0.0, Omega = 0.0, kappa = 0.0;
  double y = 0.0, ydot = 0.0, z = 0.0, zdot = 0.0;
  double phi = 0.0, phidot = 0.0, psi = 0.0, psidot = 0.0;
};

contact::Creepages wheel_creepages(const WheelsetKinematics& k, const ContactPointGeometry& c, int side);

}  // namespace railsim::engine
