// Modes of the linearised vehicle versus speed; see mode_sweep.hpp.
#include "engine/analysis/mode_sweep.hpp"

#include "core/errors.hpp"
#include "engine/analysis/critical_speed.hpp"

namespace railsim::engine {

std::vector<std::vector<Mode>> modes_versus_speed(const Scenario& sc, const std::vector<double>& speeds, int count) {
  if (count < 1) throw InputError("modes: count " + std::to_string(count) + ": expected at least 1");
  std::vector<std::vector<Mode>> out;
  out.reserve(speeds.size());
  for (const double v : speeds) {
    Model m = sc.model;
    m.speed.v0 = v;
    m.speed.accel = 0.0;
    auto md = modes(m, Eigen::VectorXd::Zero(m.n_states), true);
    if (md.size() > static_cast<std::size_t>(count)) md.resize(static_cast<std::size_t>(count));
    out.push_back(std::move(md));
  }
  return out;
}

ModeSweep mode_sweep(const Scenario& sc, const std::vector<double>& speeds, int count, double v_lo, double v_hi) {
  ModeSweep r;
  r.modes = modes_versus_speed(sc, speeds, count);
  r.unstable_at_v_lo = linearly_unstable(sc, v_lo);
  r.linear_critical_speed = r.unstable_at_v_lo ? v_lo : linear_critical_speed(sc, v_lo, v_hi);
  return r;
}

}  // namespace railsim::engine
