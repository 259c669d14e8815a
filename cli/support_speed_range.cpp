// Speed-range options of the sweep commands; see support_speed_range.hpp.
#include "cli/support_speed_range.hpp"

#include <cmath>
#include <string>

#include "config/yaml_input.hpp"
#include "core/errors.hpp"

namespace railsim::cli {

int check_speed_range(double v_min_kmh, double v_max_kmh, double v_step_kmh) {
  using config::format_number;
  if (!std::isfinite(v_min_kmh) || !std::isfinite(v_max_kmh) ||
      !(v_min_kmh > 0 && v_max_kmh > v_min_kmh && v_max_kmh <= kMaxSweepSpeedKmh))
    throw InputError("--v-min/--v-max: need 0 < v-min < v-max <= " + format_number(kMaxSweepSpeedKmh) +
                     " km/h (got " + format_number(v_min_kmh) + ", " + format_number(v_max_kmh) + ")");
  if (!std::isfinite(v_step_kmh) || !(v_step_kmh > 0))
    throw InputError("--v-step: expected a positive number [km/h] (got " + format_number(v_step_kmh) + ")");
  const double n = std::floor((v_max_kmh - v_min_kmh) / v_step_kmh + 1e-9) + 1.0;
  if (n > kMaxSweepPoints)
    throw InputError("--v-step " + format_number(v_step_kmh) + ": " + format_number(v_min_kmh) + ".." +
                     format_number(v_max_kmh) + " km/h would take " + format_number(n) +
                     " speeds, more than the limit of " + format_number(kMaxSweepPoints) +
                     "; use a step of at least " + format_number((v_max_kmh - v_min_kmh) / (kMaxSweepPoints - 1)) +
                     " km/h");
  return static_cast<int>(n);
}

}  // namespace railsim::cli
