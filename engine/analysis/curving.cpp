// Quasi-static curving results; see curving.hpp.
#include "engine/analysis/curving.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/track_frame.hpp"

namespace railsim::engine {

namespace {

class Accumulator {
 public:
  void add(double v) {
    sum_ += v;
    min_ = std::min(min_, v);
    max_ = std::max(max_, v);
    ++n_;
  }
  Stat stat() const { return n_ ? Stat{sum_ / double(n_), min_, max_} : Stat{}; }

 private:
  double sum_ = 0.0, min_ = std::numeric_limits<double>::infinity(), max_ = -std::numeric_limits<double>::infinity();
  std::size_t n_ = 0;
};

// All wheelsets on the same constant non-zero curvature at sample i.
bool in_circular_curve(const RunHistory& h, std::size_t i, double& kappa) {
  kappa = h.wheelsets.empty() ? 0.0 : h.wheelsets.front().curvature[i];
  if (kappa == 0.0) return false;
  for (const auto& w : h.wheelsets)
    if (w.curvature_rate[i] != 0.0 || std::fabs(w.curvature[i] - kappa) > 1e-9 * std::fabs(kappa)) return false;
  return true;
}

CurveResult evaluate_body(const RunHistory& h, std::size_t i0, std::size_t i1, double kappa) {
  CurveResult r;
  r.curvature = kappa;
  r.cant = h.wheelsets.front().cant[i0];
  r.start = h.distance[i0];
  r.end = h.distance[i1 - 1];
  r.samples = i1 - i0;
  const double sgn = kappa > 0 ? 1.0 : -1.0;
  Accumulator speed, anc, sumY;
  const std::size_t nw = h.wheelsets.size();
  std::vector<Accumulator> aoa(nw), shift(nw), Y(2 * nw), Q(2 * nw), yq(2 * nw), tg(2 * nw);
  for (std::size_t i = i0; i < i1; ++i) {
    const double V = h.speed[i];
    speed.add(V);
    const double phi = h.wheelsets.front().cant[i];
    anc.add(sgn * (V * V * kappa * std::cos(phi) - kGravity * std::sin(phi)));
    double sy = 0.0;
    for (std::size_t w = 0; w < nw; ++w) {
      const WheelsetHistory& wh = h.wheelsets[w];
      aoa[w].add(-sgn * wh.yaw[i]);
      shift[w].add(-sgn * wh.y[i]);
      for (int s = 0; s < 2; ++s) {
        const WheelHistory& wl = wh.wheel[s];
        Y[2 * w + s].add(wl.Y[i]);
        Q[2 * w + s].add(wl.Q[i]);
        yq[2 * w + s].add(wl.Q[i] > 0.0 ? wl.Y[i] / wl.Q[i] : 0.0);
        tg[2 * w + s].add(wl.Tgamma[i]);
        sy += wl.Y[i];
      }
    }
    sumY.add(sy);
  }
  r.mean_speed = speed.stat().mean;
  r.unbalanced_acceleration = anc.stat().mean;
  r.sum_Y = sumY.stat().mean;
  r.expected_sum_Y = h.total_mass * r.unbalanced_acceleration * sgn;
  for (std::size_t w = 0; w < nw; ++w) {
    WheelsetCurving c;
    c.name = h.wheelsets[w].name;
    c.angle_of_attack = aoa[w].stat();
    c.lateral_shift = shift[w].stat();
    for (int s = 0; s < 2; ++s) {
      WheelCurving& wc = c.wheel[s];
      wc.outer = (s == 1) == (kappa > 0);  // left curve: the right wheel is outer
      wc.Y = Y[2 * w + s].stat();
      wc.Q = Q[2 * w + s].stat();
      wc.yq = yq[2 * w + s].stat();
      wc.Tgamma = tg[2 * w + s].stat();
    }
    r.wheelsets.push_back(std::move(c));
  }
  return r;
}

}  // namespace

std::vector<CurveResult> evaluate_curving(const RunHistory& h, const CurvingOptions& opt) {
  std::vector<CurveResult> out;
  const std::size_t n = h.size();
  std::size_t i = 0;
  while (i < n) {
    double kappa = 0.0;
    if (!in_circular_curve(h, i, kappa)) {
      ++i;
      continue;
    }
    std::size_t j = i;
    double k2 = 0.0;
    while (j < n && in_circular_curve(h, j, k2) && k2 == kappa) ++j;
    // Settle: skip the first settle_distance of the stretch.
    std::size_t s0 = i;
    while (s0 < j && h.distance[s0] < h.distance[i] + opt.settle_distance) ++s0;
    if (s0 < j && h.distance[j - 1] - h.distance[s0] >= opt.min_length) out.push_back(evaluate_body(h, s0, j, kappa));
    i = j;
  }
  return out;
}

}  // namespace railsim::engine
