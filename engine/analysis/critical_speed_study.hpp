// Critical-speed studies of one scenario, as `railsim critical-speed` runs
// them (the command parses, calls one of these, writes and prints):
// - analyse_critical_speed: the linear critical speed (eigenvalues, bracket
//   [max(1, 0.25 v_min), 1.5 v_max]) and the nonlinear one by bifurcation sweep
//   or ramping (engine/analysis/critical_speed.hpp), with its wall time;
// - critical_speed_with_baseline: that analysis with the scenario's reduced
//   creep coefficients and, unless they are all 1, once more with the
//   unreduced contact (k = 1), with the relative change 100 (V - V_0) / V_0 [%];
// - critical_speed_per_model: the analysis once per tangential contact model.
// critical_speed_summary is the summary.json record of one analysis.
// Settings in SI (m/s, m, s, m/s^2); the record echoes them in km/h and mm,
// rounded to 12 significant digits so that a value given in km/h or mm (with
// up to 12 digits) is echoed as it was given.
#pragma once

#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "engine/analysis/critical_speed.hpp"
#include "engine/io/scenario.hpp"
#include "results/json_writer.hpp"

namespace railsim::engine {

enum class CriticalSpeedMethod { bifurcation, ramping };
// "bifurcation" or "ramping"; InputError naming `where` otherwise.
CriticalSpeedMethod parse_critical_speed_method(const std::string& name, const std::string& where);
const char* critical_speed_method_name(CriticalSpeedMethod m);

// A speed or length echoed in the unit it is given in (km/h, mm): si * factor
// rounded to 12 significant digits, so that the round trip km/h -> m/s -> km/h
// gives back the number as given (240 km/h, not 240.00000000000003). NaN stays NaN.
double as_given(double si, double factor);
inline double given_kmh(double v_m_s) { return as_given(v_m_s, 3.6); }
inline double given_mm(double x_m) { return as_given(x_m, 1e3); }

struct CriticalSpeedStudySettings {
  CriticalSpeedMethod method = CriticalSpeedMethod::bifurcation;
  double v_min = 80.0 / 3.6, v_max = 300.0 / 3.6, v_step = 20.0 / 3.6;  // [m/s]
  double duration = 6.0;               // simulated time per sweep point [s]
  double large_disturbance = 8e-3;     // down branch [m]
  double small_disturbance = 0.5e-3;   // up branch [m]
  double threshold = 0.5e-3;           // settled amplitude that counts as hunting [m]
  double deceleration = 0.5;           // ramping [m/s^2]
  bool up_branch = true;
  bool continuation = false;
  double ramp_start = 300.0 / 3.6;     // ramping start speed [m/s]
  double ramp_disturbance = 8e-3;      // ramping initial lateral shift [m]
  std::string ramp_start_source;       // where the start speed came from (for the record)
  int threads = 0;                     // worker threads per process; 0 = all cores
  StopRequest stop;                    // Ctrl-C / KeyboardInterrupt: InterruptedError (core/stop_request.hpp)
};

// A scenario's critical_speed section (engine/io/scenario.hpp) as study
// settings: what the command line leaves to the scenario. The ramp starts at
// its ramping.v_start_kmh, else v_max, with its ramping.disturbance_mm, else
// the large disturbance.
CriticalSpeedStudySettings study_settings(const CriticalSpeedSettings& scenario_section);

// What a user gives on top of a scenario's critical_speed section (the
// command line, the Python call), in the units typed: km/h, mm, s, m/s^2;
// NaN (or no value) = not given.
struct CriticalSpeedOverrides {
  double v_min_kmh = NAN, v_max_kmh = NAN, v_step_kmh = NAN;
  double duration = NAN;  // [s]
  double large_disturbance_mm = NAN, small_disturbance_mm = NAN, threshold_mm = NAN;
  double deceleration = NAN;  // [m/s^2]
  std::optional<bool> continuation;
  std::string v_max_name = "--v-max";  // the given v_max as the ramp start's source, for the record
};

// The given values, converted to SI, replace the settings'; a given v_max is
// also the ramp's start speed, a given large disturbance also its initial shift.
void apply_overrides(CriticalSpeedStudySettings& settings, const CriticalSpeedOverrides& given);

// The settings as the engine's sweep options (MPI on: ranks share the points).
BifurcationOptions bifurcation_options(const CriticalSpeedStudySettings& s);
RampingOptions ramping_options(const CriticalSpeedStudySettings& s);
// Bracket of the linear critical speed [m/s]: [max(1, 0.25 v_min), 1.5 v_max].
double linear_bracket_low(const CriticalSpeedStudySettings& s);
double linear_bracket_high(const CriticalSpeedStudySettings& s);

struct CriticalSpeedOutcome {
  double critical = 0.0;        // [m/s]; NaN none found
  double linear = 0.0;          // [m/s]; NaN stable over the bracket
  double fold_amplitude = 0.0;  // [m] bifurcation: at the fold; ramping: envelope where read; NaN none
  double fold_frequency = 0.0;  // [Hz] bifurcation only; NaN otherwise
  double wall = 0.0;            // [s]
  BifurcationResult bifurcation;  // method bifurcation
  RampingResult ramping;          // method ramping
};

// One analysis; a bifurcation sweep keeps its points in dir/bifurcation.csv
// (resumable; engine/analysis/critical_speed.hpp).
CriticalSpeedOutcome analyse_critical_speed(const Scenario& scenario, const CriticalSpeedStudySettings& settings,
                                            const std::string& dir);

// summary.json of one analysis: method results, scenario record, settings, wall time.
results::Json critical_speed_summary(const Scenario& scenario, const CriticalSpeedStudySettings& settings,
                                     const CriticalSpeedOutcome& outcome);

struct CriticalSpeedWithBaseline {
  Scenario scenario;                  // the analysed scenario (reduction, model)
  CriticalSpeedOutcome outcome;
  bool with_baseline = false;         // the unreduced run was made
  Scenario unreduced_scenario;        // the same with k = 1 (when with_baseline)
  CriticalSpeedOutcome unreduced;     // its analysis (files in out_dir/unreduced)
  double change_percent = 0.0;        // 100 (V_NL - V_NL0) / V_NL0; NaN when either is NaN
  double linear_change_percent = 0.0; // the same for V_L
  results::Json summary;              // summary.json, with the "unreduced" block
};

// `scenario` carries its reduction already (with_reduction); the baseline runs
// when `reduction_given` and `baseline` and the factors are not all 1.
// tangential_model: empty keeps the scenario's.
CriticalSpeedWithBaseline critical_speed_with_baseline(const Scenario& scenario, const std::string& tangential_model,
                                                       const CriticalSpeedStudySettings& settings, bool reduction_given,
                                                       bool baseline, const std::string& out_dir);

struct ModelCriticalSpeed {
  std::string model;
  Scenario scenario;
  CriticalSpeedOutcome outcome;
  results::Json summary;  // summary.json of this model's analysis (out_dir/<model>/)
};

// The analysis once per tangential model name, each in out_dir/<model>;
// `finished` (optional) is called with each model's result as soon as it is
// done, so a caller can write it before the next model runs (or fails).
std::vector<ModelCriticalSpeed> critical_speed_per_model(
    const Scenario& scenario, const std::vector<std::string>& models, const CriticalSpeedStudySettings& settings,
    const std::string& out_dir, const std::function<void(const ModelCriticalSpeed&)>& finished = {});

}  // namespace railsim::engine
