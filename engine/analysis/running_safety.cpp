// Running-safety criteria; see running_safety.hpp for the sources.
#include "engine/analysis/running_safety.hpp"

#include <cmath>
#include <stdexcept>

#include "results/sliding_window.hpp"

namespace railsim::engine {

double nadal_limit(double flange_angle, double mu) {
  const double t = std::tan(flange_angle);
  return (t - mu) / (1.0 + mu * t);
}

double weinstock_limit(double flange_angle, double mu) { return nadal_limit(flange_angle, mu) + mu; }

double prudhomme_limit(double axle_load, double alpha) {
  const double P0_kN = axle_load / 1000.0;
  return alpha * (10.0 + P0_kN / 3.0) * 1000.0;
}

namespace {

WindowedMaximum windowed_max(const std::vector<double>& x, const std::vector<double>& y, double limit,
                             const SafetyLimits& lim) {
  const auto m = results::sliding_mean(x, y, lim.window, lim.step);
  WindowedMaximum out;
  out.limit = limit;
  std::vector<double> absval;
  absval.reserve(m.value.size());
  for (std::size_t i = 0; i < m.value.size(); ++i) {
    const double a = std::fabs(m.value[i]);
    absval.push_back(a);
    if (a > out.max_abs) out.max_abs = a, out.at_distance = m.centre[i];
  }
  out.percentile = results::percentile(absval, lim.percentile);
  out.pass = out.max_abs <= limit;
  return out;
}

}  // namespace

AxleSafety evaluate_axle(const AxleForces& f, const SafetyLimits& lim) {
  const std::size_t n = f.distance.size();
  if (n < 2 || f.Y_left.size() != n || f.Q_left.size() != n || f.Y_right.size() != n || f.Q_right.size() != n)
    throw std::invalid_argument("evaluate_axle: force series must have equal length >= 2");
  if (!(f.static_wheel_load > 0.0)) throw std::invalid_argument("evaluate_axle: static wheel load must be > 0");
  std::vector<double> yq_l(n), yq_r(n), sum_y(n);
  AxleSafety out;
  out.name = f.name;
  for (std::size_t i = 0; i < n; ++i) {
    // A lifted wheel (Q <= 0) has no meaningful Y/Q; it is caught by the unloading criterion.
    yq_l[i] = f.Q_left[i] > 0.0 ? f.Y_left[i] / f.Q_left[i] : 0.0;
    yq_r[i] = f.Q_right[i] > 0.0 ? f.Y_right[i] / f.Q_right[i] : 0.0;
    sum_y[i] = f.Y_left[i] + f.Y_right[i];
    for (double q : {f.Q_left[i], f.Q_right[i]}) {
      const double unloading = (f.static_wheel_load - q) / f.static_wheel_load;
      if (unloading > out.max_unloading) out.max_unloading = unloading, out.unloading_at = f.distance[i];
    }
  }
  out.yq_left = windowed_max(f.distance, yq_l, lim.yq_limit, lim);
  out.yq_right = windowed_max(f.distance, yq_r, lim.yq_limit, lim);
  out.sum_y = windowed_max(f.distance, sum_y, prudhomme_limit(2.0 * f.static_wheel_load, lim.prudhomme_alpha), lim);
  out.unloading_pass = out.max_unloading <= lim.wheel_unloading;
  out.pass = out.yq_left.pass && out.yq_right.pass && out.sum_y.pass && out.unloading_pass;
  return out;
}

}  // namespace railsim::engine
