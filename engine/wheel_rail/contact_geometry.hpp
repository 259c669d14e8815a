// Wheel-rail contact geometry as seen by the engine: for one wheel, every
// potential contact point as a function of the wheelset's lateral shift toward
// that wheel and its yaw as seen from that wheel (s = +y, yaw = +psi for the
// left wheel; s = -y, yaw = -psi for the right wheel: the right wheel is the
// mirror image of the left one across the track centre line, and a mirror
// image turns yaw around).
//
// Per point:
//   rolling_radius r [m]: height of the contact point below the axle (r cos
//     theta for a point at angle theta ahead of the lowest point of the wheel
//     circle, the convention CONTACT uses; the wheel circle's radius at zero
//     yaw), contact_angle delta [rad] (> 0 tilts the normal toward the track
//     centre), lateral position a of the contact point from the wheelset
//     centre [m] (positive, along the wheel's own side), lead x [m] (position
//     of the contact point along the track ahead of the axle's vertical plane:
//     nonzero under yaw), patch semi-axes a, b [m] and Kalker coefficients
//     C11, C22, C23 at the reference load N0 [N] with normal approach q0 [m]
//     (tables), or relative curvatures A, B [1/m] (Hertz).
//   Load law of the point: N = weight N0 (1 + (dq - gap)/q0)^{3/2} while
//     positive, dq the normal approach change of the wheel from its reference
//     state (wheel_rail_loads.hpp). gap = 0 for tables whose reference state
//     has N = N0 at every shift (RSGEO); the profiles geometry sets it for
//     every point from one reference approach continuous in the shift, and a
//     weight in [0, 1] that fades a point out smoothly where its basin of the
//     gap function vanishes (profile_geometry.hpp).
// The rigid wheelset pose (roll and height of the axle centre with both wheels
// touching) is known to geometries built from profiles; the lateral wheelset
// model takes its kinematic roll from it, the full model measures its normal
// approaches from it.
#pragma once

#include <limits>
#include <string>

#include "contact/geometry/strip_contact_table.hpp"

namespace railsim::engine {

struct ContactPointGeometry {
  double rolling_radius = 0.0;
  double contact_angle = 0.0;
  double lateral = 0.0;
  double lead = 0.0;                   // [m] along the track, ahead of the axle
  double semi_a = 0.0, semi_b = 0.0;   // at N0; 0 when unknown
  double C11 = 0.0, C22 = 0.0, C23 = 0.0;  // 0 when unknown
  double N0 = 0.0, q0 = 0.0;           // reference load / approach; 0 when unknown
  double A = 0.0, B = 0.0;             // relative curvatures; 0 when unknown
  double gap = 0.0;                    // offset of the load law [m] (see the header)
  double weight = 1.0;                 // load factor in [0, 1]
  double flange_force = 0.0;           // extra lateral force toward the track centre [N] (dead-band flange), >= 0
};

// All potential contact points of one wheel, main (most loaded at the
// reference state) first.
struct WheelGeometry {
  static constexpr int kMaxPoints = 4;
  int n = 0;
  ContactPointGeometry p[kMaxPoints];
};

// Rigid pose of the wheelset with both wheels touching, at shift y (toward the
// LEFT wheel) and yaw psi: roll [rad, positive lifts the left side], height of
// the axle centre above its centred position [m], and their derivatives by y.
struct RigidPose {
  double roll = 0.0, droll_dy = 0.0;
  double height = 0.0, dheight_dy = 0.0;
};

class ContactGeometry {
 public:
  virtual ~ContactGeometry() = default;
  // Every potential point of one wheel at shift s toward it and yaw as seen by
  // it (see the header); no allocation.
  virtual void evaluate(double s, double yaw, WheelGeometry& out) const = 0;
  // The main point alone at zero yaw (statics, reports).
  ContactPointGeometry main_point(double s) const {
    WheelGeometry g;
    evaluate(s, 0.0, g);
    return g.p[0];
  }
  // Rigid pose when the geometry knows it (profiles); false otherwise, and the
  // lateral model uses (r_L - r_R)/(a_L + a_R) (exact for cones on knife-edge
  // rails; for S1002/UIC60 1:40 it is 3-8 times the rigid roll below the flange).
  virtual bool rigid_pose(double y, double yaw, RigidPose& out) const {
    (void)y;
    (void)yaw;
    out = RigidPose{};
    return false;
  }
  // Distributed contact (profiles): the strips of one wheel at shift s toward
  // it and yaw as seen by it whose gap is below `cutoff` (and their
  // neighbours), for engine/wheel_rail/strip_patches.hpp; false for point geometries
  // (tables, cones), whose points carry Hertz laws.
  virtual bool strips(double s, double yaw, double cutoff, contact::StripSet& out) const {
    (void)s;
    (void)yaw;
    (void)cutoff;
    out.n = 0;
    return false;
  }
  virtual bool distributed() const { return false; }
  // True when the contact angles are those of the rail's normal in the track
  // frame (profiles: the wheelset's roll is already in them); false when they
  // are measured from the wheelset's axle (tables, cones: the force
  // resolution adds the roll, theta = delta + side phi).
  virtual bool angles_in_track_frame() const { return distributed(); }
  // Contact modulus E* = E / (2 (1 - nu^2)) of the strips [Pa] (distributed only).
  virtual double contact_modulus() const { return 0.0; }
  // True when the geometry's reference state (N = N0 at dq = 0) already
  // follows the shift (RSGEO tables, DYTSI's convention): the full model then
  // measures its approaches from z = phi = 0 instead of from the rigid pose.
  virtual bool reference_follows_shift() const { return false; }
  // Nominal rolling radius at zero shift [m] (sets the nominal spin speed V/r0).
  virtual double r0() const = 0;
  // Half distance between nominal contact points at zero shift [m].
  virtual double l0() const = 0;
  // Largest admissible |shift| [m] (table range); beyond it the run stops.
  virtual double max_shift() const = 0;
  // Largest |yaw| the geometry describes [rad]; beyond it evaluation clamps
  // (infinity when the geometry does not depend on yaw).
  virtual double max_yaw() const { return std::numeric_limits<double>::infinity(); }
  virtual std::string describe() const = 0;
};

}  // namespace railsim::engine
