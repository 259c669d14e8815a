// Running safety of a recorded run; see run_safety.hpp.
#include "engine/analysis/run_safety.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace railsim::engine {

namespace {
constexpr double kDeg = 3.14159265358979323846 / 180.0;

// Time at track distance s of a strictly increasing distance series (linear interpolation).
double time_at(const std::vector<double>& dist, const std::vector<double>& time, double s) {
  const auto it = std::lower_bound(dist.begin(), dist.end(), s);
  if (it == dist.begin()) return time.front();
  if (it == dist.end()) return time.back();
  const std::size_t j = std::size_t(it - dist.begin());
  const double u = (s - dist[j - 1]) / (dist[j] - dist[j - 1]);
  return time[j - 1] + u * (time[j] - time[j - 1]);
}

bool strictly_increasing(const std::vector<double>& v) {
  for (std::size_t i = 1; i < v.size(); ++i)
    if (!(v[i] > v[i - 1])) return false;
  return v.size() >= 2;
}
}  // namespace

FlangeAngle flange_angle(const ContactGeometry& g, double fallback, double min_flank, int samples) {
  FlangeAngle f;
  const double lim = g.max_shift() * (1.0 - 1e-9);
  WheelContact c;
  for (int k = 0; k < samples; ++k) {
    const double s = -lim + 2.0 * lim * k / std::max(1, samples - 1);
    for (int p = 0; p < g.points(); ++p) {
      g.evaluate_point(s, p, c);
      if (p > 0 && !(c.N0 > 0)) continue;
      f.geometry_max = std::max(f.geometry_max, c.contact_angle);
    }
  }
  char buf[256];
  if (f.geometry_max >= min_flank) {
    f.angle = f.geometry_max;
    std::snprintf(buf, sizeof buf, "largest contact angle of the contact geometry over +-%.4g mm: %.2f deg",
                  g.max_shift() * 1e3, f.angle / kDeg);
  } else {
    f.angle = fallback;
    f.fallback = true;
    std::snprintf(buf, sizeof buf,
                  "fallback %.1f deg (S1002 maximum flank angle): the contact geometry has no flange flank "
                  "(largest contact angle %.2f deg over +-%.4g mm)",
                  fallback / kDeg, f.geometry_max / kDeg, g.max_shift() * 1e3);
  }
  f.source = buf;
  return f;
}

RunSafety evaluate_run_safety(const RunHistory& h, double flange_angle_rad, double mu, const SafetyLimits& limits) {
  if (h.size() == 0) throw std::invalid_argument("evaluate_run_safety: empty run history");
  RunSafety out;
  out.flange_angle = flange_angle_rad;
  out.mu = mu;
  out.nadal = nadal_limit(flange_angle_rad, mu);
  out.limits = limits;
  const std::size_t n = h.size();
  out.en14363_evaluated = strictly_increasing(h.distance) && h.distance.back() - h.distance.front() >= limits.window;
  if (!out.en14363_evaluated)
    out.notes.push_back("EN 14363 2 m windows not evaluated: the vehicle runs less than " +
                        std::to_string(limits.window) + " m (or does not advance)");
  std::vector<double> dist(n);
  for (std::size_t w = 0; w < h.wheelsets.size(); ++w) {
    const WheelsetHistory& wh = h.wheelsets[w];
    WheelsetSafety s;
    s.name = wh.name;
    s.static_wheel_load = wh.static_wheel_load;
    for (std::size_t i = 0; i < n; ++i) dist[i] = h.wheelset_distance(w, i);
    for (int side = 0; side < 2; ++side) {
      const WheelHistory& wl = wh.wheel[side];
      WheelSafety& ws = s.wheel[side];
      for (std::size_t i = 0; i < n; ++i) {
        const double yq = wl.Q[i] > 0.0 ? std::fabs(wl.Y[i] / wl.Q[i]) : 0.0;
        if (yq > ws.max_abs_yq.value) ws.max_abs_yq = {yq, dist[i], h.time[i]};
      }
      ws.nadal_pass = ws.max_abs_yq.value <= out.nadal;
    }
    s.pass = s.wheel[0].nadal_pass && s.wheel[1].nadal_pass;
    if (out.en14363_evaluated && wh.static_wheel_load > 0.0) {
      AxleForces f;
      f.name = wh.name;
      f.distance = dist;
      f.Y_left = wh.wheel[0].Y;
      f.Q_left = wh.wheel[0].Q;
      f.Y_right = wh.wheel[1].Y;
      f.Q_right = wh.wheel[1].Q;
      f.static_wheel_load = wh.static_wheel_load;
      s.en14363 = evaluate_axle(f, limits);
      s.wheel[0].yq_2m_time = time_at(dist, h.time, s.en14363.yq_left.at_distance);
      s.wheel[1].yq_2m_time = time_at(dist, h.time, s.en14363.yq_right.at_distance);
      s.sum_y_time = time_at(dist, h.time, s.en14363.sum_y.at_distance);
      s.unloading_time = time_at(dist, h.time, s.en14363.unloading_at);
      s.pass = s.pass && s.en14363.pass;
    }
    out.pass = out.pass && s.pass;
    out.wheelsets.push_back(std::move(s));
  }
  return out;
}

}  // namespace railsim::engine
