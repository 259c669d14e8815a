// Wheelset-level contact for given poses: what `railsim wheelset-contact`
// computes, so that railsim's wheel-rail geometry and contact can be held
// against other tools (CONTACT's Manchester benchmark case ).
//
// Per position (lateral shift y toward the left wheel, yaw psi positive
// turning the leading end to the left, optional roll phi, vertical force Fz
// per wheel, rolling speed omega about the axle):
//  1. the rigid contact search (contact/geometry/wheel_rail_geometry.hpp) at
//     (y, psi, phi): with phi given each wheel is lowered onto its rail on its
//     own (as CONTACT's half-wheelset problems with prescribed roll); without,
//     phi is the rigid wheelset's roll with both wheels touching;
//  2. per wheel the strips of its profile (every `strip` of arc length, the
//     points of the contact locus) and the distributed normal contact of the
//     vehicle models (engine/wheel_rail/strip_patches.hpp): the wheel's vertical approach
//     that carries Fz, its patches (separate runs of loaded strips) with their
//     loads, positions, contact angles, rolling radii (height below the axle)
//     and equivalent ellipses;
//  3. per patch the steady-state creepages of the wheelset rolling at omega
//     with speed V (engine/wheel_rail/creepages.hpp: no rates), and the tangential model
//     chosen by name (contact/registry.hpp) on the patch; omega is given, or
//     V / r0, or (free_rolling) the speed at which the creep forces put no
//     torque on the axle;
//  4. the forces of the wheel on the rail, summed over the patches, in
//     railsim's track frame (x forward, y left, z up);
//  5. a patch the tangential model flags as outside its validity domain
//     (contact::ContactForces::valid) gives a warning naming the position,
//     the wheel, the patch and the model's reason;
//  6. a wheel shifted past its flange's steepest point (the largest contact
//     angle of the rigid contact over the shift at zero yaw, found once per
//     set-up) that touches at a flatter flange angle is flagged as climbing,
//     with a warning: the pose is one a running wheelset does not keep.
// Conventions of CONTACT's track frame (x forward, y to the right, z down:
// railsim's rotated by 180 degrees about x): y_C = -y, psi_C = -psi, phi_C =
// phi, omega_C = -omega, F_C = (Fx, -Fy, -Fz).
// Units SI.
#pragma once

#include <string>
#include <vector>

#include "contact/geometry/wheel_rail_geometry.hpp"
#include "contact/registry.hpp"
#include "contact/types.hpp"

namespace railsim::engine {

struct WheelsetContactSetup {
  std::string wheel = "S1002", rail = "UIC60";  // profile files or shipped names
  contact::TrackSetup track;                    // gauge (at gauge_depth), flange back, back face, r0, inclination
  contact::Material material;                   // E (or from G), nu, mu
  double speed = 1.0;                           // V [m/s]
  double strip = 0.25e-3;                       // strip width (arc length) [m]
  std::string model = "chopaya";                // tangential model
  contact::TangentialModelOptions model_options;
  // Where the set-up was given (the case file), prefixed to the messages of a
  // profile or track set-up that cannot be used; empty: none.
  std::string where;
};

struct WheelsetContactPosition {
  double y = 0.0, yaw = 0.0;     // [m], [rad]
  double Fz = 0.0;               // vertical force per wheel [N]
  double roll = 0.0;             // [rad], used when has_roll
  bool has_roll = false;
  double omega = 0.0;            // [rad/s], used when has_omega (else V / r0)
  bool has_omega = false;
  // A free axle (`omega: free`): Omega such that the creep forces put no
  // torque on the axle, sum over the patches of Fx r = 0 (the vehicle models'
  // free axle rotation). Without it and without omega the axle is driven at
  // V / r0, which carries whatever torque the rolling radii ask for (60 kN
  // per wheel, S1002/UIC60 1:40, shifted 5 mm: a net 12 kN traction).
  bool free_rolling = false;
  // Where the position was given ("FILE:LINE: key 'positions[i]'"), for the
  // messages of a position that cannot be solved; empty: "position i".
  std::string where;
};

struct WheelsetContactPatch {
  double N = 0.0;                 // normal load [N]
  double y_wheel = 0.0;  // wheel-profile lateral coordinate of the strip nearest the patch centre [m]
  double y_rail = 0.0;   // lateral coordinate of the patch centre on the placed (inclined) rail profile [m]
  double y_track = 0.0, x_track = 0.0; // position in the track frame [m] (x: ahead of the wheelset centre)
  double rolling_radius = 0.0;    // height below the axle [m]
  double contact_angle = 0.0;     // [rad], railsim's sign (left wheel flange > 0, right wheel flange < 0)
  double a = 0.0, b = 0.0;        // equivalent ellipse semi-axes [m]
  contact::Creepages creep;       // xi, eta, phi [-, -, 1/m]
  contact::ContactForces forces;  // of the rail on the wheel, contact frame (valid, reason: the model's flag)
};

struct WheelsetContactWheel {
  double Fx = 0.0, Fy = 0.0, Fz = 0.0;  // total force of the wheel on the rail, track frame [N]
  double approach = 0.0;                // vertical approach from the touching pose [m]
  // The wheel is shifted past the point where its flange is steepest (at zero
  // yaw) and touches the flange at a flatter angle: it is climbing its
  // flange, where a running wheelset derails (the forces are those of the
  // prescribed pose all the same).
  bool climbing = false;
  std::vector<WheelsetContactPatch> patches;
};

struct WheelsetContactResult {
  WheelsetContactPosition position;
  double roll = 0.0;   // roll used [rad]
  double omega = 0.0;  // rolling speed used [rad/s] (given, V / r0, or the free axle's)
  WheelsetContactWheel wheel[2];  // left, right
  // e.g. a wheel climbing its flange, a patch outside the model's validity domain, naming the position
  std::vector<std::string> warnings;
};

// Throws InputError for bad set-ups (naming `where`, the key and, when the
// centred wheelset cannot sit on the rails, the profiles and track set-up) or
// positions out of the profiles' range (naming the position's `where`).
std::vector<WheelsetContactResult> wheelset_contact(const WheelsetContactSetup& setup,
                                                    const std::vector<WheelsetContactPosition>& positions);

}  // namespace railsim::engine
