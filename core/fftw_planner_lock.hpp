// The one lock that serialises calls into FFTW's planner (plan creation and
// destruction) across the whole program.
//
// FFTW's planner keeps process-wide state and is not thread-safe; executing a
// plan is (FFTW 3 manual, sec. 5.4 "Thread safety"). Every module that plans
// (tracks/psd_synthesis, contact/mim/convolution, contact/mim_table) takes this
// lock around fftw_plan_* and fftw_destroy_plan, so planners in different
// modules running on different threads cannot race. It guards FFTW's state
// only: hold it just around planner calls, never around a solve.
#pragma once

#include <mutex>

namespace railsim {

// One instance per program (function-local static of an inline function).
inline std::mutex& fftw_planner_mutex() {
  static std::mutex m;
  return m;
}

}  // namespace railsim
