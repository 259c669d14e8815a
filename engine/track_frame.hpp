// The track-following reference frame and the inertial loads of running in it.
//
// Bodies are described relative to a frame that follows the track centre line
// at the body's own distance s (x forward, y left, z up, rotated by the cant
// angle phi_c about x). For a body of mass m and inertia (Ixx, Izz) at speed V
// the inertial (d'Alembert) and gravity loads in that frame are
//   lateral   F_y = -m (V^2 kappa cos phi_c - g sin phi_c)           (centrifugal, gravity)
//   vertical  F_z = -m (g cos phi_c + V^2 kappa sin phi_c)
//   yaw       M_z = -Izz V^2 dkappa/ds        (frame yaw acceleration in transitions)
//   roll      M_x = -Ixx V^2 d2phi_c/ds2 ~ 0  (piecewise-linear cant: neglected)
// (Iwnicki (ed.) 2006, Handbook of Railway Vehicle Dynamics, ch. 8; the same
// resolution of gravity and centrifugal force as DYTSI, cooperrider-car.md §7.7).
// Signs: kappa > 0 is a curve turning to the left (centre on +y). The cant
// angle phi_c > 0 raises the outer (right) rail of such a curve (the frame is
// rolled by -phi_c about x). The centrifugal load points away from the centre
// (-y for kappa > 0), the gravity component toward the low (inner) rail, so to
// first order F_y = -m (V^2 kappa - g phi_c) = -m a_nc: cant balances
// curvature, and under cant deficiency the rails must push the vehicle toward
// the curve centre with m a_nc (a_nc = uncompensated lateral acceleration,
// physics-reference §10.1).
// Irregularities: lateral (alignment) and vertical positions of the left and
// right rails [m] and their derivatives in s [-].
//
// Frames of bodies at different distances: every body's states are relative to
// the frame at its own distance, so in a curve the frames of two bodies differ
// by the change of heading (yaw kappa dx), the versine of the curve (lateral
// ~ kappa dx^2 / 2) and, in transitions, the change of cant. Suspension
// elements between two bodies must see these differences, otherwise a bogie in
// a curve holds its wheelsets radial at no cost and the car body bends with the
// track. frame_offset() gives the pose of a body's frame relative to a common
// reference frame (the frame at the vehicle reference distance), written as a
// small displacement of the body's CoM (lateral, vertical, roll, yaw) and its
// rate; adding it to the body's own motion gives the motion in the reference
// frame (exact plane geometry of the centre line; roll and the projection on
// the canted reference plane to first order; the longitudinal chord
// shortening, ~ kappa^2 dx^3 / 6, is not represented: no longitudinal DOF).
#pragma once

#include <memory>
#include <string>

#include "engine/elements/rigid_body.hpp"

namespace railsim::engine {

inline constexpr double kGravity = 9.81;  // [m/s^2]

// Track quantities at one distance s.
struct TrackSample {
  double curvature = 0.0;       // kappa [1/m], > 0 turning left
  double curvature_rate = 0.0;  // dkappa/ds [1/m^2]
  double cant = 0.0;            // phi_c [rad], > 0 balances kappa > 0
  double lat_left = 0.0, lat_right = 0.0;      // rail lateral irregularity [m], + to the left
  double dlat_left = 0.0, dlat_right = 0.0;    // d/ds [-]
  double vert_left = 0.0, vert_right = 0.0;    // rail vertical irregularity [m], + up
  double dvert_left = 0.0, dvert_right = 0.0;  // d/ds [-]
  double cant_rate = 0.0;       // dphi_c/ds [rad/m]
  double heading = 0.0;         // centre-line tangent angle in the ground plane [rad], CCW
  double x = 0.0, y = 0.0;      // centre-line position in the ground plane [m]
};

// A track as seen by the engine: evaluated by distance, immutable.
class TrackReference {
 public:
  virtual ~TrackReference() = default;
  virtual void sample(double s, TrackSample& out) const = 0;
  // Alignment only (curvature, cant; irregularities left at zero): enough for
  // bodies without wheel-rail contact.
  virtual void sample_alignment(double s, TrackSample& out) const { sample(s, out); }
  virtual std::string describe() const = 0;
};

// Inertial and gravity loads on a body in the track frame (see top of file).
struct FrameLoads {
  double Fy = 0.0, Fz = 0.0, Mz = 0.0;
};
FrameLoads frame_loads(const TrackSample& t, double V, double mass, double Izz);

// Pose (q) and its rate (v, at speed V) of the frame sampled in `body` relative
// to the frame sampled in `ref`, as the displacement of a point at the body's
// nominal CoM height y_nom, z_nom above/beside the centre line (see top of file).
// Both samples must carry heading and ground position. Zero on straight track.
BodyMotion frame_offset(const TrackSample& ref, const TrackSample& body, double y_nom, double z_nom, double V);

}  // namespace railsim::engine
