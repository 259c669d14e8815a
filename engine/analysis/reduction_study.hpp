// Critical speed against the reduction factors on Kalker's coefficients, in
// one resumable job (`railsim critical-speed SCENARIO --reductions LIST`).
//
// For every entry of the list (contact/reduction.hpp forms: presets, numbers,
// k11,k22,k23, third-body layers whose factors the exact solver computes for
// the scenario's nominal patch) the study runs the scenario's critical-speed
// analysis (critical_speed.hpp: bifurcation sweep, with continuation when
// asked, or ramping) and the linear critical speed (eigenvalues), and reports
// each against the unreduced contact (k = 1; added as the reference entry
// when the list has none): change in per cent, and the limit cycle at the fold
// (amplitude and frequency of the down branch at the critical speed; for
// ramping the envelope where the critical speed was read).
//
// Files under out_dir (every point written as it finishes, so a killed job
// started again computes only what is missing and ends with the same result
// files, byte for byte):
//   linear_critical_speeds.csv   one row per entry (sweep_runner.hpp format)
//   <folder>/bifurcation.csv     the entry's sweep (+ its resume files), or
//   ramping.csv (sweep file of the ramps) and <folder>/ramping_record.csv
// Entries run in parallel on the worker threads (one thread each when there
// are at least as many entries as threads); under mpirun the entries run one
// after the other, each spread over the ranks (without continuation).
// The result files of the study itself (reductions.csv, summary.json, charts)
// are written by the caller from the result (cli/cmd_critical_speed.cpp).
#pragma once

#include <string>
#include <vector>

#include "contact/reduction.hpp"
#include "engine/analysis/critical_speed.hpp"
#include "engine/io/scenario.hpp"
#include "results/chart.hpp"
#include "results/json_writer.hpp"

namespace railsim::engine {

struct ReductionStudyOptions {
  std::vector<contact::ReductionSpec> entries;  // parsed, layers unresolved
  std::string method = "bifurcation";           // "bifurcation" or "ramping"
  BifurcationOptions bifurcation;               // threads / use_mpi ignored: see threads below
  RampingOptions ramping;
  double linear_v_lo = 1.0, linear_v_hi = 150.0;  // bracket of the linear critical speed [m/s]
  std::string out_dir = "reductions";
  std::string cache_dir;                        // layer factors (empty: default cache folder)
  std::string tangential_model;                 // empty: the scenario's
  int threads = 0;                              // worker threads per process; 0 = all cores
  bool use_mpi = true;                          // spread over mpirun ranks when launched so
};

struct ReductionStudyEntry {
  std::string label;                 // contact::reduction_label of the entry
  std::string folder;                // sub-folder of out_dir with the entry's files
  bool added_reference = false;      // the k = 1 entry added because the list had none
  Scenario scenario;                 // the scenario with this entry's reduction (and model)
  double critical = 0.0;             // [m/s]; NaN none found
  double linear = 0.0;               // [m/s]; NaN stable over the bracket
  double change_percent = 0.0;       // against the reference entry; NaN when either is NaN
  double linear_change_percent = 0.0;
  double fold_amplitude = 0.0;       // [m]; NaN none
  double fold_frequency = 0.0;       // [Hz]; NaN none (ramping: NaN)
  // Bifurcation: what the down-branch run one step below the critical speed did
  // by its end ("centred": the branch ends there; "decaying": it was still
  // decaying, so the critical speed is an upper bound); empty when none.
  std::string below_state;
  BifurcationResult bifurcation;     // method bifurcation
  RampingResult ramping;             // method ramping
  // Ramping: why the entry has no critical speed when its ramp stopped
  // ("" it did not): a numerical failure (ramp_failed, no verdict) or a
  // derailment (a result).
  bool ramp_failed = false;
  std::string ramp_stop;
  double wall_time = 0.0;            // [s] spent on this entry in this call (0 when read back)
};

struct ReductionStudyResult {
  std::string method;
  std::vector<ReductionStudyEntry> entries;  // in the order of the list (added reference last)
  int reference = -1;                        // index of the k = 1 entry
  double wall_time = 0.0;                    // [s] of this call
};

// Run (or resume) the study. Throws InputError for an empty list, an unknown
// method or a layer without a patch; NumericalError from the analyses.
ReductionStudyResult reduction_study(const Scenario& scenario, const ReductionStudyOptions& options);

// summary.json of the study (no wall times: the same for a resumed job):
// the scenario record (scenario_record.hpp) with mu, geometry and conicity,
// wheelset model, saturation law; the settings (duration per point, speeds,
// disturbances, threshold, continuation or ramp) and the rule of the critical
// speed; per entry the reduction as given, k11, k22, k23 (a layer's
// parameters and patch), mu of the run, nonlinear and linear critical speed,
// change in per cent from k = 1, limit cycle at the fold, and the count of
// points by state (settled / growing / decaying / centred / stopped).
results::Json reduction_study_summary(const Scenario& scenario, const ReductionStudyOptions& options,
                                      const ReductionStudyResult& result);

// Wall times of the call (timing.json): total and per entry.
results::Json reduction_study_timing(const ReductionStudyResult& result);

// The down branches of every entry on one bifurcation diagram (bifurcation_chart.hpp).
results::Chart reductions_chart(const Scenario& scenario, const ReductionStudyOptions& options,
                                const ReductionStudyResult& result);

// Nonlinear and linear critical speed against the factors: uniform entries on
// lines against k, the others as labelled markers at their k22.
results::Chart critical_speed_vs_k_chart(const Scenario& scenario, const ReductionStudyResult& result);

// Colour of entry i on the study's charts.
std::string reduction_entry_color(std::size_t i);

}  // namespace railsim::engine
