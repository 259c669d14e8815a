// Settled amplitude of an oscillating signal (hunting limit cycles).
//
// For a bifurcation diagram the amplitude that counts is the one left after
// the transients have died out, not the first peak. settled_amplitude() looks
// at the last `tail_fraction` of the record, takes the extrema of each
// half-cycle there (between zero crossings of the signal minus its mean), and
// returns half the mean peak-to-peak value, together with a measure of whether
// the amplitude is still changing (decaying or growing) at the end.
#pragma once

#include <vector>

namespace railsim::results {

struct LimitCycle {
  double amplitude = 0.0;      // half of the mean peak-to-peak over the tail [signal units]
  double mean = 0.0;           // mean over the tail (offset of the cycle)
  double frequency = 0.0;      // from zero crossings in the tail [1/abscissa unit]; 0 if none
  double growth = 0.0;         // relative change of the peak-to-peak from first to last third of the tail
  int half_cycles = 0;         // number of half-cycles found in the tail
};

// t strictly increasing, y the signal. tail_fraction in (0, 1].
LimitCycle settled_amplitude(const std::vector<double>& t, const std::vector<double>& y,
                             double tail_fraction = 0.3);

}  // namespace railsim::results
