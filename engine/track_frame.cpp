// Inertial loads of running along a curved, canted track; see track_frame.hpp.
#include "engine/track_frame.hpp"

#include <cmath>

namespace railsim::engine {

FrameLoads frame_loads(const TrackSample& t, double V, double mass, double Izz) {
  FrameLoads L;
  const double c = std::cos(t.cant), s = std::sin(t.cant);
  const double a_c = V * V * t.curvature;  // centripetal acceleration of the frame origin
  L.Fy = -mass * (a_c * c - kGravity * s);
  L.Fz = -mass * (kGravity * c + a_c * s);
  L.Mz = -Izz * V * V * t.curvature_rate;
  return L;
}

BodyMotion frame_offset(const TrackSample& ref, const TrackSample& b, double y_nom, double z_nom, double V) {
  BodyMotion m;
  const double ch = std::cos(ref.heading), sh = std::sin(ref.heading);
  const double dx = b.x - ref.x, dy = b.y - ref.y;
  const double Ox = ch * dx + sh * dy;   // origin of the body's frame in the reference axes (ground plane)
  const double Oy = -sh * dx + ch * dy;
  const double dh = b.heading - ref.heading;
  // Frames rolled by -phi_c: the ground-plane lateral Oy has y' = Oy cos(phi_r), z' = Oy sin(phi_r).
  const double cr = std::cos(ref.cant), sr = std::sin(ref.cant);
  const double droll = -(b.cant - ref.cant);
  const double Oy_dot = V * (std::sin(dh) - ref.curvature * Ox);
  const double droll_dot = -V * (b.cant_rate - ref.cant_rate);
  m.q[kLat] = Oy * cr - droll * z_nom;
  m.q[kVert] = Oy * sr + droll * y_nom;
  m.q[kRoll] = droll;
  m.q[kYaw] = dh;
  m.v[kLat] = Oy_dot * cr - droll_dot * z_nom;
  m.v[kVert] = Oy_dot * sr + droll_dot * y_nom;
  m.v[kRoll] = droll_dot;
  m.v[kYaw] = V * (b.curvature - ref.curvature);
  return m;
}

}  // namespace railsim::engine
