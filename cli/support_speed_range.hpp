// Shared check of the --v-min/--v-max/--v-step options of the speed-sweep
// commands (`railsim critical-speed`, `railsim modes`), in km/h.
#pragma once

namespace railsim::cli {

// Highest speed of a sweep [km/h] and largest number of sweep points
// (README "Exit codes and limits").
inline constexpr double kMaxSweepSpeedKmh = 720.0;
inline constexpr double kMaxSweepPoints = 2000.0;

// Throws InputError naming the option and the allowed range unless every
// value is finite, 0 < v_min < v_max <= kMaxSweepSpeedKmh, v_step > 0 and the
// sweep has at most kMaxSweepPoints speeds (the message gives the estimate).
// Returns the number of speeds, floor((v_max - v_min) / v_step) + 1.
int check_speed_range(double v_min_kmh, double v_max_kmh, double v_step_kmh);

}  // namespace railsim::cli
