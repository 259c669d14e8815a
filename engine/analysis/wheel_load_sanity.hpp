// Physics sanity of a run's wheel loads: a vertical wheel load Q above ten
// times the wheel's static load Q0 is legal output but implausible (measured
// dynamic wheel loads stay below about 3 Q0, even over dipped joints and
// wheel flats: EN 14363's Q_max limit is 90 kN + Q0, about 2.3 Q0 for a 70 kN
// wheel), and points to a fault of the input (contact stiffness, masses, an
// irregularity in the wrong unit) rather than to the vehicle.
//
// One warning per wheel that exceeds it, at its largest load: the value, the
// ratio to Q0, the time and track distance, and the usual range. The warnings
// go into summary.json 'warnings' (engine/analysis/scenario_run.cpp).
// Units: N, s, m.
#pragma once

#include <string>
#include <vector>

#include "engine/analysis/run_history.hpp"

namespace railsim::engine {

// Ratio Q / Q0 above which a wheel load is reported.
inline constexpr double kImplausibleLoadRatio = 10.0;

std::vector<std::string> wheel_load_warnings(const RunHistory& history);

}  // namespace railsim::engine
