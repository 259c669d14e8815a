// Modes of the linearised vehicle versus speed: at each speed V [m/s] the
// eigenvalues s = sigma + i omega of the equations linearised about centred
// running on perfect track (engine/linearisation.hpp), the `count` least
// damped oscillatory ones (frequency f = omega / 2 pi [Hz], damping ratio
// zeta = -sigma / |s|), ranked per speed by decreasing real part (not tracked
// across speeds: where two modes cross, their ranks swap). What the Python
// module's railsim.modes() calls; `railsim modes` calls mode_sweep, which adds
// the linear critical speed over [v_lo, v_hi] (engine/analysis/critical_speed.hpp).
#pragma once

#include <vector>

#include "engine/linearisation.hpp"
#include "engine/io/scenario.hpp"

namespace railsim::engine {

// modes[i]: the least damped oscillatory modes at speeds[i] (at most `count`).
std::vector<std::vector<Mode>> modes_versus_speed(const Scenario& scenario, const std::vector<double>& speeds,
                                                  int count);

struct ModeSweep {
  std::vector<std::vector<Mode>> modes;  // per speed, as modes_versus_speed
  double linear_critical_speed = 0.0;    // [m/s]; NaN: stable over [v_lo, v_hi]; v_lo when unstable there
  bool unstable_at_v_lo = false;         // already unstable at v_lo: the critical speed is at or below it
};
ModeSweep mode_sweep(const Scenario& scenario, const std::vector<double>& speeds, int count, double v_lo,
                     double v_hi);

}  // namespace railsim::engine
