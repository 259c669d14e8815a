// Limits of the speed sweeps and the critical-speed study's settings, shared
// by the command line (`railsim critical-speed`, `railsim modes`) and the
// Python module, so that both refuse the same values naming their own option
// or argument (README "Exit codes and limits"). Speeds in km/h as typed.
#pragma once

#include "engine/analysis/critical_speed_study.hpp"

namespace railsim::engine {

// Highest speed of a sweep [km/h] and largest number of sweep points.
inline constexpr double kMaxSweepSpeedKmh = 720.0;
inline constexpr double kMaxSweepPoints = 2000.0;

// Admissible ranges of the study's settings, in the units typed.
struct SettingRange {
  double lo, hi;
};
inline constexpr SettingRange kDurationRange{0.5, 600.0};             // [s] per sweep point
inline constexpr SettingRange kDisturbanceRangeMm{0.01, 20.0};        // large disturbance [mm]
inline constexpr SettingRange kSmallDisturbanceRangeMm{0.001, 20.0};  // [mm]
inline constexpr SettingRange kThresholdRangeMm{0.001, 20.0};         // [mm]
inline constexpr SettingRange kDecelerationRange{0.001, 10.0};        // [m/s^2]
inline constexpr int kMaxThreads = 256;

// Names of the speed range's values in messages (options or arguments).
struct SpeedRangeNames {
  const char* v_min = "--v-min";
  const char* v_max = "--v-max";
  const char* v_step = "--v-step";
};

// Throws InputError naming the values and the allowed range unless every
// value is finite, 0 < v_min < v_max <= kMaxSweepSpeedKmh, v_step > 0 and the
// sweep has at most kMaxSweepPoints speeds (the message gives the estimate).
// Returns the number of speeds, floor((v_max - v_min) / v_step) + 1.
int check_speed_range(double v_min_kmh, double v_max_kmh, double v_step_kmh, const SpeedRangeNames& names = {});

// The given values of `g` (those not NaN) within the ranges above, and
// `threads` in [0, kMaxThreads]; InputError naming the Python argument
// (duration, disturbance_mm, small_disturbance_mm, threshold_mm,
// deceleration, threads) and its range otherwise. (The command line checks
// its options through CLI11 with the same ranges.)
void check_given_settings(const CriticalSpeedOverrides& g, int threads);

}  // namespace railsim::engine
