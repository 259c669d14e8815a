// Honest charts of critical-speed analyses (descriptions for results/chart.hpp).
//
// Bifurcation diagrams (settled lateral amplitude against speed) show what
// every run did by its end (critical_speed.hpp, PointState):
//   filled circles joined by a line   settled limit cycles (hunting branch);
//   hollow down-triangles             still decaying at the end of the run;
//   hollow up-triangles               still growing at the end of the run;
//   small dots joined by a line       back to the centred running (amplitude
//                                     at or below the threshold);
//   black crosses                     runs that derailed or stopped after their
//                                     motion grew (counted as hunting);
//   red X                             numerical failure, or a run too short to
//                                     show a cycle: no verdict.
// No line is drawn through an unsettled point. The fold of the down branch is
// drawn as a jump: a dashed drop at the critical speed from the limit cycle
// to the centred running. The rule the critical speed was read with is
// written on the chart (critical_speed_rule). Speeds in km/h, amplitudes in mm.
//
// Ramping charts: the envelope of the lateral motion against speed, the start
// speed of the ramp named, and a marker where the critical speed was read.
#pragma once

#include <string>
#include <vector>

#include "engine/analysis/critical_speed.hpp"
#include "results/chart.hpp"

namespace railsim::engine {

struct BifurcationCurve {
  std::string label;                    // legend text of this sweep (e.g. "k = 0.8")
  std::string color;                    // matplotlib colour
  const BifurcationResult* result = nullptr;
  double linear_critical_speed = 0.0;   // [m/s], NaN = unknown
};

// The rule of the nonlinear critical speed in words, with the settings of `o`.
std::string critical_speed_rule(const BifurcationOptions& o);

// One diagram: the down branch of every curve (and the up branch when
// `up_branch` and there is one curve), markers by point state, the fold as a
// jump, the rule in a note. With one curve also the linear and nonlinear
// critical speeds and the threshold as reference lines.
results::Chart bifurcation_chart(const std::vector<BifurcationCurve>& curves, const BifurcationOptions& o,
                                 const std::string& title, bool up_branch);

// Ramping: envelope (largest wheelset shift over 0.5 s windows) against speed,
// the ramp's start speed in the legend, the point where the critical speed was
// read, the linear critical speed (NaN: none).
results::Chart ramping_chart(const RampingResult& r, double linear_critical_speed, double threshold,
                             const std::string& title);

// Envelope of a ramping record: the largest max_lateral [mm] in consecutive
// windows of `window` seconds, at the speed [km/h] where it occurs.
void ramping_envelope(const RampingResult& r, std::vector<double>& speed_kmh, std::vector<double>& peak_mm,
                      double window = 0.5);

}  // namespace railsim::engine
