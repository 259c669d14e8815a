// One tangential-model call with its measured cost, for the contact-model
// commands and the model comparison (engine/analysis/contact_comparison.hpp).
// The call is repeated until one window lasts >= 40 us (at least once), the
// fastest of up to five windows is kept (a shared machine only adds time);
// time_ns = that window / repetitions (std::chrono::steady_clock).
#pragma once

#include "contact/tangential_model.hpp"
#include "contact/types.hpp"

namespace railsim::engine {

struct TimedForces {
  contact::ContactForces forces;
  double time_ns = 0.0;
};

TimedForces solve_timed(const contact::TangentialModel& model, const contact::ContactInput& in,
                        contact::TangentialWorkspace* ws);

// One call, timed once (for slow reference solvers, where one call suffices).
TimedForces solve_once_timed(const contact::TangentialModel& model, const contact::ContactInput& in,
                             contact::TangentialWorkspace* ws);

}  // namespace railsim::engine
