// Shared check of the --v-min/--v-max/--v-step options of the speed-sweep
// commands (`railsim critical-speed`, `railsim modes`), in km/h.
#pragma once

namespace railsim::cli {

// Throws InputError naming the option and the allowed range unless
// 0 < v_min < v_max and v_step > 0.
void check_speed_range(double v_min_kmh, double v_max_kmh, double v_step_kmh);

}  // namespace railsim::cli
