// Speed-range options of the sweep commands; see support_speed_range.hpp.
#include "cli/support_speed_range.hpp"

#include <string>

#include "core/errors.hpp"

namespace railsim::cli {

void check_speed_range(double v_min_kmh, double v_max_kmh, double v_step_kmh) {
  if (!(v_min_kmh > 0 && v_max_kmh > v_min_kmh))
    throw InputError("--v-min/--v-max: need 0 < v-min < v-max (got " + std::to_string(v_min_kmh) + ", " +
                     std::to_string(v_max_kmh) + ")");
  if (!(v_step_kmh > 0)) throw InputError("--v-step: expected a positive number");
}

}  // namespace railsim::cli
