// Wheel-rail contact geometry as seen by the engine: for one wheel, the
// contact-point quantities as a function of the wheelset's lateral shift
// toward that wheel (s = +y for the left wheel, -y for the right wheel; the
// tables are used symmetrically, cooperrider-car.md §7.2).
//
//   rolling_radius r [m], contact_angle delta [rad] (> 0 tilts the normal
//   toward the track centre), lateral position a of the contact point from the
//   wheelset centre [m] (positive, along the wheel's own side), height of the
//   contact point below the nominal contact level [m], patch semi-axes a, b [m]
//   and Kalker coefficients C11, C22, C23 at the reference load N0 [N] with
//   normal approach q0 [m] (tables), or relative curvatures A, B [1/m] (Hertz).
#pragma once

#include <limits>
#include <memory>
#include <string>

namespace railsim::engine {

struct WheelContact {
  double rolling_radius = 0.0;
  double contact_angle = 0.0;
  double lateral = 0.0;
  double semi_a = 0.0, semi_b = 0.0;   // at N0; 0 when unknown
  double C11 = 0.0, C22 = 0.0, C23 = 0.0;  // 0 when unknown
  double N0 = 0.0, q0 = 0.0;           // reference load / approach; 0 when unknown
  double A = 0.0, B = 0.0;             // relative curvatures; 0 when unknown
  // Offset of the load law, N = N0 (1 + (dq - gap)/q0)^{3/2} while positive:
  // the normal approach at the reference state (z = 0) is q0 - gap (gap > q0:
  // the point is open there and closes when the wheel moves down by
  // (gap - q0)/cos(contact_angle)). 0 for tables whose reference state has
  // N = N0 at every shift (RSGEO); the profiles geometry sets it for every
  // point from one reference approach that is continuous in the shift.
  double gap = 0.0;
  double flange_force = 0.0;           // extra lateral force toward the track centre [N] (dead-band flange), >= 0
};

class ContactGeometry {
 public:
  virtual ~ContactGeometry() = default;
  // Contact quantities for a shift s toward this wheel [m]; no allocation.
  // This is the first (main) contact point.
  virtual void evaluate(double s, WheelContact& out) const = 0;
  // Several contact points per wheel (e.g. tread and flange): their number and
  // point k (0 <= k < points()). Only the full wheelset model uses k > 0.
  virtual int points() const { return 1; }
  virtual void evaluate_point(double s, int k, WheelContact& out) const {
    (void)k;
    evaluate(s, out);
  }
  // Roll of the rigid wheelset [rad, positive lifts the left side] at a shift y
  // toward the LEFT wheel, both wheels touching their rails, when the geometry
  // knows it (profiles: solved with the rail heads' shape); NaN otherwise, and
  // the lateral model uses (r_L - r_R)/(a_L + a_R), exact for cones on
  // knife-edge rails (for S1002/UIC60 1:40 it is 3-8 times the rigid roll
  // below the flange).
  virtual double rigid_roll(double y) const {
    (void)y;
    return std::numeric_limits<double>::quiet_NaN();
  }
  // Nominal rolling radius at zero shift [m] (sets the nominal spin speed V/r0).
  virtual double r0() const = 0;
  // Half distance between nominal contact points at zero shift [m].
  virtual double l0() const = 0;
  // Largest admissible |shift| [m] (table range); beyond it the run stops.
  virtual double max_shift() const = 0;
  virtual std::string describe() const = 0;
};

}  // namespace railsim::engine
