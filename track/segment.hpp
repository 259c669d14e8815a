// One alignment segment (straight, clothoid transition, circular curve): the
// design curvature and cant as functions of the local distance u in [0, L]
// from the segment start, and the displacement of the centre line.
//
// Conventions (shared by every segment and by Alignment):
//   curvature kappa [1/m]: > 0 turning to the left (centre of the curve on +y)
//   cant E [m]: height of the right rail above the left rail, E = z_right - z_left,
//     measured between the rail centres a distance 2b apart (rail_spacing).
//     Raising the outer rail of a left-hand curve gives E > 0, so in a curve
//     with cant, E has the sign of kappa.
//   heading change dpsi(u) = integral_0^u kappa; offset(u) = integral_0^u
//     (cos dpsi, sin dpsi): the displacement in the frame of the segment start.
#pragma once

#include <array>

namespace railsim::track {

// Value and first two s-derivatives of a design quantity.
struct Derivs {
  double v = 0.0;    // value
  double d1 = 0.0;   // d/ds
  double d2 = 0.0;   // d2/ds2
};

class Segment {
 public:
  explicit Segment(double length) : length_(length) {}
  virtual ~Segment() = default;
  // "straight", "clothoid", "circular".
  virtual const char* kind() const = 0;
  double length() const { return length_; }

  // Curvature and cant at local distance u in [0, L].
  virtual Derivs curvature(double u) const = 0;
  virtual Derivs cant(double u) const = 0;
  // Heading change integral_0^u kappa [rad].
  virtual double heading_change(double u) const = 0;
  // Displacement of the centre line in the segment-start frame {x along the
  // start heading, y to its left} [m].
  virtual std::array<double, 2> offset(double u) const = 0;

  double curvature_start() const { return curvature(0.0).v; }
  double curvature_end() const { return curvature(length_).v; }
  double cant_start() const { return cant(0.0).v; }
  double cant_end() const { return cant(length_).v; }

 private:
  double length_;
};

}  // namespace railsim::track
