// Y/Q of the leading wheels of several runs of one scenario (e.g. with k = 1
// and k = 0.5) against Nadal's flange-climbing limit, from the files
// `railsim run` writes (DIR/channels.csv: distance of the vehicle reference
// and per wheel <ws>.L.YQ, <ws>.R.YQ; cli/cmd_run.cpp).
//
// The scenario gives what the channels do not carry: the wheelsets' offsets
// (the leading wheelset is the one furthest ahead, or the one named), the
// flange angle of its contact geometry (run_safety.hpp flange_angle) and the
// friction coefficient of its creep forces, hence Nadal's limit
// (safety_limits.hpp), the same the run's own running_safety evaluation uses.
// Per run and wheel: the largest |Y/Q|, the track distance and time where it
// occurs, whether |Y/Q| exceeds the limit, over how many metres and seconds
// (crossings interpolated linearly between samples), first and last place.
// Units: m, s; Y/Q dimensionless.
#pragma once

#include <string>
#include <vector>

#include "engine/io/scenario.hpp"
#include "results/chart.hpp"
#include "results/json_writer.hpp"

namespace railsim::engine {

struct YqWheelResult {
  double peak = 0.0;              // max |Y/Q|
  double peak_signed = 0.0;       // Y/Q at the peak
  double peak_distance = 0.0;     // track distance of the wheelset at the peak [m]
  double peak_time = 0.0;         // [s]
  bool exceeded = false;          // |Y/Q| > limit somewhere
  double exceed_length = 0.0;     // [m] of track with |Y/Q| > limit
  double exceed_time = 0.0;       // [s]
  double first_exceed = 0.0, last_exceed = 0.0;  // track distances [m] (0 when not exceeded)
};

struct YqRun {
  std::string label;
  std::string dir;
  std::vector<double> time, distance;  // distance: of the compared wheelset [m]
  std::vector<double> yq[2];           // left, right
  YqWheelResult wheel[2];
  std::string status;    // the run's summary.json status: ok, derailed
  std::string warning;   // e.g. a run of another scenario than the one compared against ("" none)
};

struct YqComparison {
  std::string scenario;
  std::string wheelset;         // compared wheelset (leading by default)
  double offset = 0.0;          // its position ahead of the vehicle reference [m]
  double flange_angle = 0.0;    // [rad]
  double mu = 0.0;
  double nadal = 0.0;           // limit on |Y/Q|
  std::vector<YqRun> runs;
};

// Read the runs in `dirs` (labels: same count, or empty = folder names, with
// their parent folders where names repeat: a/out and b/out are "a/out" and
// "b/out"; the same folder twice is an InputError).
// Throws InputError naming the file when channels.csv is missing or lacks the
// wheelset's columns, when a value of time, distance or Y/Q is not a finite
// number (naming the row and column), when the counts differ, or when the
// run's summary.json is missing (the run did not finish) or says it failed
// numerically (status "failed"): such a run's Y/Q has no verdict. A run of another scenario (summary.json's "scenario" differs)
// is compared with a warning (YqRun::warning, logged).
YqComparison compare_yq(const Scenario& sc, const std::vector<std::string>& dirs,
                        const std::vector<std::string>& labels, const std::string& wheelset = "");

// Y/Q of both wheels of every run against the track distance, Nadal's limit
// (+-), a marker at each run's peak with its value.
results::Chart yq_comparison_chart(const YqComparison& c);

// {"scenario", "wheelset", "nadal_limit", "flange_angle_deg", "mu", "runs": [{label, dir,
//  "wheels": {"left": {...}, "right": {...}}, "peak" (both wheels)}]}.
results::Json yq_comparison_summary(const YqComparison& c);

}  // namespace railsim::engine
