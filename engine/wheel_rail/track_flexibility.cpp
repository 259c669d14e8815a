// Flexible track under each wheelset; see track_flexibility.hpp.
#include "engine/wheel_rail/track_flexibility.hpp"

#include <algorithm>
#include <cmath>

#include "engine/data.hpp"

namespace railsim::engine {

double rail_foundation_beta(double stiffness, double bending_stiffness) {
  return std::cbrt(stiffness / (8.0 * bending_stiffness));
}

SmoothedRailGeometry::SmoothedRailGeometry(const TrackReference& track, double length, double beta, double step)
    : beta_(beta), h_(step), length_(length) {
  const int n = std::max(2, int(std::floor(length / step)) + 1);  // a cell at least
  std::vector<double> raw[2], raw_slope[2];
  TrackSample T;
  for (int i = 0; i < 2; ++i) {
    raw[i].resize(std::size_t(n));
    raw_slope[i].resize(std::size_t(n));
  }
  for (int j = 0; j < n; ++j) {
    track.sample(std::min(j * step, length), T);
    raw[0][std::size_t(j)] = T.vert_left;
    raw[1][std::size_t(j)] = T.vert_right;
    raw_slope[0][std::size_t(j)] = T.dvert_left;
    raw_slope[1][std::size_t(j)] = T.dvert_right;
  }
  // Influence line on the grid, |x| <= 8 / beta (e^{-8}: 3e-4 of its peak), normalised.
  const int m = int(std::ceil(8.0 / (beta * step)));
  std::vector<double> g(std::size_t(2 * m + 1));
  double sum = 0.0;
  for (int k = -m; k <= m; ++k) {
    const double x = std::abs(k * step);
    const double v = 0.5 * beta * std::exp(-beta * x) * (std::cos(beta * x) + std::sin(beta * x));
    g[std::size_t(k + m)] = v;
    sum += v;
  }
  for (double& v : g) v /= sum;
  for (int i = 0; i < 2; ++i) {
    z_[i].assign(std::size_t(n), 0.0);
    dz_[i].assign(std::size_t(n), 0.0);
    for (int j = 0; j < n; ++j) {
      double a = 0.0, b = 0.0;
      for (int k = -m; k <= m; ++k) {
        const int u = std::clamp(j + k, 0, n - 1);  // the geometry held beyond the ends
        const double w = g[std::size_t(k + m)];
        a += w * raw[i][std::size_t(u)];
        b += (j + k >= 0 && j + k < n) ? w * raw_slope[i][std::size_t(u)] : 0.0;
      }
      z_[i][std::size_t(j)] = a;
      dz_[i][std::size_t(j)] = b;
    }
  }
}

void SmoothedRailGeometry::at(double s, double z[2], double dz[2]) const {
  const int n = int(z_[0].size());
  const double u = std::clamp(s, 0.0, length_) / h_;
  const int j = std::clamp(int(u), 0, n - 2);
  const double t = u - j, t2 = t * t, t3 = t2 * t;
  const double h00 = 2 * t3 - 3 * t2 + 1, h10 = (t3 - 2 * t2 + t) * h_, h01 = -2 * t3 + 3 * t2, h11 = (t3 - t2) * h_;
  const double d00 = (6 * t2 - 6 * t) / h_, d10 = 3 * t2 - 4 * t + 1, d11 = 3 * t2 - 2 * t;
  for (int i = 0; i < 2; ++i) {
    const double* a = z_[i].data() + j;
    const double* b = dz_[i].data() + j;
    z[i] = h00 * a[0] + h10 * b[0] + h01 * a[1] + h11 * b[1];
    dz[i] = d00 * a[0] + d10 * b[0] - d00 * a[1] + d11 * b[1];
  }
}

namespace {
// Height and its d/ds of the support under both rails of wheelset w (left,
// right): the rails' smoothed geometry, or the track sample of its body.
inline void support_heights(const Model& model, const Data& d, const Wheelset& ws, double z[2], double dz[2]) {
  if (const auto& g = model.track_flexibility.vertical_geometry) {
    g->at(d.s + model.bodies[std::size_t(ws.body)].position.x(), z, dz);
    return;
  }
  const TrackSample& T = d.track[std::size_t(ws.body)];
  z[0] = T.vert_left;
  z[1] = T.vert_right;
  dz[0] = T.dvert_left;
  dz[1] = T.dvert_right;
}
}  // namespace

void rail_positions(const Model& model, Data& d, const double* x) {
  for (std::size_t w = 0; w < model.wheelsets.size(); ++w) {
    const Wheelset& ws = model.wheelsets[w];
    const TrackSample& T = d.track[std::size_t(ws.body)];
    RailPosition& r = d.rail[w];
    r.support_lateral = 0.5 * (T.lat_left + T.lat_right);
    r.support_lateral_rate = d.V * 0.5 * (T.dlat_left + T.dlat_right);
    const bool lateral_state = ws.track_lateral_state >= 0;
    r.lateral = lateral_state ? x[ws.track_lateral_state] : r.support_lateral;
    r.lateral_rate = lateral_state ? x[ws.track_lateral_state + 1] : r.support_lateral_rate;
    double dz[2];
    support_heights(model, d, ws, r.support_vertical, dz);
    for (int i = 0; i < 2; ++i) {
      r.support_vertical_rate[i] = d.V * dz[i];
      const int s = ws.rail_vertical_state[i];
      r.vertical[i] = s >= 0 ? x[s] : r.support_vertical[i];
      r.vertical_rate[i] = s >= 0 ? x[s + 1] : r.support_vertical_rate[i];
    }
  }
}

void track_flexibility_rates(const Model& model, const Data& d, int w, const double* x, double* xdot) {
  const Wheelset& ws = model.wheelsets[std::size_t(w)];
  const TrackFlexibility& f = model.track_flexibility;
  const RailPosition& r = d.rail[std::size_t(w)];  // rail_positions of this evaluation
  const WheelOutput* wheel = &d.wheel[2 * std::size_t(w)];
  if (const int s = ws.track_lateral_state; s >= 0) {
    const TrackSupport& L = f.lateral;
    xdot[s] = x[s + 1];
    xdot[s + 1] = (-L.stiffness * (x[s] - r.support_lateral) - L.damping * (x[s + 1] - r.support_lateral_rate) -
                   (wheel[0].Y + wheel[1].Y)) /
                  L.mass;
  }
  const TrackSupport& V = f.vertical;
  for (int i = 0; i < 2; ++i) {
    const int s = ws.rail_vertical_state[i];
    if (s < 0) continue;
    xdot[s] = x[s + 1];
    xdot[s + 1] = (-V.stiffness * (x[s] - r.support_vertical[i]) - V.damping * (x[s + 1] - r.support_vertical_rate[i]) -
                   (wheel[i].Q - ws.static_vertical_load[i])) /
                  V.mass;
  }
}

}  // namespace railsim::engine
