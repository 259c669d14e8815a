// Horizontal alignment of a track: a chain of segments (straight, clothoid,
// circular curve) evaluated by the distance s along the centre line.
//
// Position and heading follow from the curvature: psi(s) = psi0 + int kappa ds,
// x' = cos psi, y' = sin psi (planar track; no vertical gradient: z = 0).
// Segment start poses are accumulated once at construction; within a segment
// each segment evaluates its own closed form (or Gauss-Legendre quadrature for
// transitions), so at() costs one binary search plus a few flops and never
// allocates.
//
// Cant (see segment.hpp for signs): E = z_right - z_left [m]; cant angle
// phi = asin(E / 2b), 2b = rail_spacing (distance of the rail centres, 1.5 m
// for standard gauge, physics-reference §10.1). The track-following frame is
// the frame {x along the heading, y left, z up} rolled by -phi about x, i.e.
// phi > 0 raises the right rail: phi has the sign of kappa in a canted curve,
// and to first order the lateral load per unit mass in the track plane is
// V^2 kappa - g phi (balanced at the equilibrium cant).
//
// Outside [0, length] the alignment continues with the end curvature and
// cant (constant), so evaluation is defined (and continuous) everywhere.
#pragma once

#include <memory>
#include <vector>

#include "track/segment.hpp"

namespace railsim::track {

// The design quantities at one distance s.
struct AlignmentState {
  double s = 0.0;            // distance along the centre line [m]
  double x = 0.0, y = 0.0;   // centre-line position in the ground plane [m]
  double heading = 0.0;      // psi: angle of the tangent from the ground x axis [rad], CCW, unwrapped (continuous)
  double curvature = 0.0;    // kappa [1/m], > 0 turning left
  double dcurvature = 0.0;   // dkappa/ds [1/m^2]
  double d2curvature = 0.0;  // d2kappa/ds2 [1/m^3] (Bloss / cosine transitions)
  double cant = 0.0;         // E = z_right - z_left [m]
  double dcant = 0.0;        // dE/ds [-]
  double cant_angle = 0.0;   // phi = asin(E/2b) [rad], > 0 right rail higher
  double dcant_angle = 0.0;  // dphi/ds [rad/m]
  double d2cant_angle = 0.0; // d2phi/ds2 [rad/m^2]
  int segment = -1;          // index of the segment (-1 before the start, n past the end)
};

// Start pose of the centre line at s = 0.
struct Pose {
  double x = 0.0, y = 0.0, heading = 0.0;
};

class Alignment {
 public:
  // `rail_spacing` 2b [m]. Segments must join with continuous curvature and
  // cant (checked: InputError naming "segments[i] (kind)" otherwise).
  Alignment(std::vector<std::unique_ptr<Segment>> segments, double rail_spacing, Pose start = {});
  Alignment(Alignment&&) noexcept = default;
  Alignment& operator=(Alignment&&) noexcept = default;

  AlignmentState at(double s) const;

  double length() const { return length_; }
  double rail_spacing() const { return rail_spacing_; }
  int segment_count() const { return static_cast<int>(segments_.size()); }
  const Segment& segment(int i) const { return *segments_[static_cast<std::size_t>(i)]; }
  // Distance of the start of segment i (i = segment_count() gives length()).
  double segment_start(int i) const { return starts_[static_cast<std::size_t>(i)]; }

 private:
  void fill_cant(AlignmentState& st, const Derivs& E) const;
  std::vector<std::unique_ptr<Segment>> segments_;
  std::vector<double> starts_;  // size n + 1
  std::vector<Pose> poses_;     // size n + 1 (pose at each start and at the end)
  double rail_spacing_ = 1.5;
  double length_ = 0.0;
};

}  // namespace railsim::track
