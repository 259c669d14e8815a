// The track-following reference frame and the inertial loads of running in it.
//
// Bodies are described relative to a frame that follows the track centre line
// at the body's own distance s (x forward, y left, z up, rotated by the cant
// angle phi_c about x). For a body of mass m and inertia (Ixx, Izz) at speed V:
//   lateral   F_y = m (V^2 kappa cos phi_c - g sin phi_c)            (centrifugal, gravity)
//   vertical  F_z = -m (g cos phi_c + V^2 kappa sin phi_c)
//   yaw       M_z = -Izz V^2 dkappa/ds        (frame yaw acceleration in transitions)
//   roll      M_x = -Ixx V^2 d2phi_c/ds2 ~ 0  (piecewise-linear cant: neglected)
// (Iwnicki (ed.) 2006, Handbook of Railway Vehicle Dynamics, ch. 8; the same
// resolution of gravity and centrifugal force as DYTSI, cooperrider-car.md §7.7).
// Signs: kappa > 0 is a curve turning to the left (centre on +y). The cant
// angle phi_c > 0 raises the outer (right) rail of such a curve, so that to
// first order F_y = m (V^2 kappa - g phi_c): cant balances curvature.
// Irregularities: lateral (alignment) and vertical positions of the left and
// right rails [m] and their derivatives in s [-].
#pragma once

#include <memory>
#include <string>

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

}  // namespace railsim::engine
