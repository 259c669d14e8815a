// Modes of the linearised vehicle versus speed: at each speed V [m/s] the
// eigenvalues s = sigma + i omega of the equations linearised about centred
// running on perfect track (engine/linearisation.hpp), the `count` least
// damped oscillatory ones (frequency f = omega / 2 pi [Hz], damping ratio
// zeta = -sigma / |s|), ranked per speed by decreasing real part (not tracked
// across speeds: where two modes cross, their ranks swap). What `railsim modes`
// and the Python module's railsim.modes() call.
#pragma once

#include <vector>

#include "engine/linearisation.hpp"
#include "engine/io/scenario.hpp"

namespace railsim::engine {

// modes[i]: the least damped oscillatory modes at speeds[i] (at most `count`).
std::vector<std::vector<Mode>> modes_versus_speed(const Scenario& scenario, const std::vector<double>& speeds,
                                                  int count);

}  // namespace railsim::engine
