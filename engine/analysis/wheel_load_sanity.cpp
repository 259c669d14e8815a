// Implausible wheel loads (above ten times static); see wheel_load_sanity.hpp.
#include "engine/analysis/wheel_load_sanity.hpp"

#include <cstdio>

namespace railsim::engine {

std::vector<std::string> wheel_load_warnings(const RunHistory& h) {
  std::vector<std::string> out;
  for (std::size_t w = 0; w < h.wheelsets.size(); ++w) {
    const WheelsetHistory& ws = h.wheelsets[w];
    const double q0 = ws.static_wheel_load;
    if (!(q0 > 0.0)) continue;
    for (int side = 0; side < 2; ++side) {
      const std::vector<double>& q = ws.wheel[side].Q;
      std::size_t at = q.size();
      for (std::size_t i = 0; i < q.size(); ++i)
        if (q[i] > kImplausibleLoadRatio * q0 && (at == q.size() || q[i] > q[at])) at = i;
      if (at == q.size()) continue;
      const double t = at < h.time.size() ? h.time[at] : 0.0;
      const double s = at < h.distance.size() ? h.wheelset_distance(w, at) : 0.0;
      char buf[400];
      std::snprintf(buf, sizeof buf,
                    "%s %s wheel: vertical load Q = %.1f kN at t = %.4g s, track distance %.1f m, %.1f times the "
                    "static load Q0 = %.1f kN: legal but implausible (usual dynamic loads below about 3 Q0; EN 14363 "
                    "Q_max 90 kN + Q0); check the contact stiffness, the masses and the irregularities' units",
                    ws.name.c_str(), side == 0 ? "left" : "right", q[at] / 1e3, t, s, q[at] / q0, q0 / 1e3);
      out.emplace_back(buf);
    }
  }
  return out;
}

}  // namespace railsim::engine
