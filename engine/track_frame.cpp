// Inertial loads of running along a curved, canted track; see track_frame.hpp.
#include "engine/track_frame.hpp"

#include <cmath>

namespace railsim::engine {

FrameLoads frame_loads(const TrackSample& t, double V, double mass, double Izz) {
  FrameLoads L;
  const double c = std::cos(t.cant), s = std::sin(t.cant);
  const double a_c = V * V * t.curvature;  // centripetal acceleration of the frame origin
  L.Fy = mass * (a_c * c - kGravity * s);
  L.Fz = -mass * (kGravity * c + a_c * s);
  L.Mz = -Izz * V * V * t.curvature_rate;
  return L;
}

}  // namespace railsim::engine
