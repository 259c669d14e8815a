// Limits of the sweeps and the study settings; see sweep_limits.hpp.
#include "engine/analysis/sweep_limits.hpp"

#include <cmath>
#include <string>

#include "config/yaml_input.hpp"
#include "core/errors.hpp"

namespace railsim::engine {

int check_speed_range(double v_min_kmh, double v_max_kmh, double v_step_kmh, const SpeedRangeNames& names) {
  using config::format_number;
  const auto bare = [](const char* name) {  // "--v-min" -> "v-min" inside the inequality
    while (*name == '-') ++name;
    return std::string(name);
  };
  if (!std::isfinite(v_min_kmh) || !std::isfinite(v_max_kmh) ||
      !(v_min_kmh > 0 && v_max_kmh > v_min_kmh && v_max_kmh <= kMaxSweepSpeedKmh))
    throw InputError(std::string(names.v_min) + "/" + names.v_max + ": need 0 < " + bare(names.v_min) + " < " +
                     bare(names.v_max) + " <= " + format_number(kMaxSweepSpeedKmh) +
                     " km/h (got " + format_number(v_min_kmh) + ", " + format_number(v_max_kmh) + ")");
  if (!std::isfinite(v_step_kmh) || !(v_step_kmh > 0))
    throw InputError(std::string(names.v_step) + ": expected a positive number [km/h] (got " +
                     format_number(v_step_kmh) + ")");
  const double n = std::floor((v_max_kmh - v_min_kmh) / v_step_kmh + 1e-9) + 1.0;
  if (n > kMaxSweepPoints)
    throw InputError(std::string(names.v_step) + " " + format_number(v_step_kmh) + ": " + format_number(v_min_kmh) + ".." +
                     format_number(v_max_kmh) + " km/h would take " + format_number(n) +
                     " speeds, more than the limit of " + format_number(kMaxSweepPoints) +
                     "; use a step of at least " + format_number((v_max_kmh - v_min_kmh) / (kMaxSweepPoints - 1)) +
                     " km/h");
  return static_cast<int>(n);
}

void check_given_settings(const CriticalSpeedOverrides& g, int threads) {
  using config::format_number;
  const auto in = [](const char* name, double v, SettingRange r, const char* unit) {
    if (std::isnan(v)) return;  // not given
    if (!(v >= r.lo && v <= r.hi))
      throw InputError(std::string(name) + ": expected a number in [" + format_number(r.lo) + ", " +
                       format_number(r.hi) + "] " + unit + " (got " + format_number(v) + ")");
  };
  in("duration", g.duration, kDurationRange, "s");
  in("disturbance_mm", g.large_disturbance_mm, kDisturbanceRangeMm, "mm");
  in("small_disturbance_mm", g.small_disturbance_mm, kSmallDisturbanceRangeMm, "mm");
  in("threshold_mm", g.threshold_mm, kThresholdRangeMm, "mm");
  in("deceleration", g.deceleration, kDecelerationRange, "m/s^2");
  if (threads < 0 || threads > kMaxThreads)
    throw InputError("threads: expected a whole number in [0, " + std::to_string(kMaxThreads) + "] (0: all cores; got " +
                     std::to_string(threads) + ")");
}

}  // namespace railsim::engine
