// Settings of the EN 14363 running-safety evaluation of a run
// (run_safety.hpp), with the standard's processing as defaults, and their
// reading from a scenario's optional `running_safety:` section:
//
//   running_safety:
//     vehicle_category: passenger     # passenger | locomotive | multiple_unit | freight (k1 = 0.85)
//     hunting_frequency_hz: 4.5       # f0 of the instability band; default: from the run
//     body_ends_m: [13.0, -13.0]      # x of the car-body end measuring points (vehicle frame)
//     straight_min_radius: 5000       # curves at least this large count as straight track [m]
//
// Processing defaults and their sources (gensys.se UIC 518 / EN 14363 course
// page [V], physics-reference §9.3):
//   wheel-rail forces low-pass 20 Hz ("cut-off >= 20 Hz" for Y, Q, Sum Y, Y/Q);
//   car-body accelerations band-pass 0.4..10 Hz;
//   (Y/Q)_2m, (Sum Y)_2m: sliding mean over 2 m sampled every 0.5 m;
//   percentiles F1 = 0.15 %, F2 = 99.85 % per track section, F0 = 50 % for the
//   quasi-static values;
//   instability: band-pass f0 +- 2 Hz and sliding rms; the 100 m window sampled
//   every 10 m is our choice where the summary gives no step [K].
// Filter orders are ours (the standard fixes the cut-offs, not the design):
// 4th-order Butterworth low-pass, band-passes from a 2nd-order prototype
// (4 poles), all applied forward and backward (zero phase; results/iir_filter.hpp).
#pragma once

#include <optional>
#include <vector>

#include "config/yaml_input.hpp"
#include "engine/analysis/safety_limits.hpp"
#include "engine/analysis/track_zones.hpp"

namespace railsim::engine {

struct SafetySettings {
  VehicleCategory category = VehicleCategory::passenger;
  // Filters [Hz].
  double force_lowpass = 20.0;           // 0: off (for comparisons with unfiltered evaluations)
  int lowpass_order = 4;
  double accel_band_low = 0.4, accel_band_high = 10.0;
  int bandpass_order = 2;
  double hunting_frequency = 0.0;         // f0 [Hz]; 0: dominant frequency of the run's Sum Y
  double hunting_half_band = 2.0;         // f0 +- this [Hz]
  double hunting_search_min = 1.0, hunting_search_max = 15.0;  // where f0 is searched [Hz]
  // Windows [m].
  double window = 2.0, step = 0.5;
  double rms_window = 100.0, rms_step = 10.0;
  // Percentiles [%].
  double percentile_low = 0.15, percentile_high = 99.85, percentile_qst = 50.0;
  ZoneLimits zones;
  // x positions of the car-body end measuring points [m] (empty: above the outermost wheelsets).
  std::vector<double> body_ends;
};

// Read a `running_safety:` mapping (keys above); InputError naming file, line
// and key for unknown keys or values out of range.
SafetySettings load_safety_settings(const config::InputNode& node);

}  // namespace railsim::engine
