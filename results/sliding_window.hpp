// Sliding-window statistics over a signal sampled along distance (or time).
//
// EN 14363 / UIC 518 evaluate Y/Q and the sum of Y as a sliding mean over a
// 2 m window, sampled every 0.5 m (gensys course summary of UIC 518; see
// physics-reference.md section 9.3). The mean over a window [c - w/2, c + w/2]
// is the integral of the linearly interpolated signal divided by w (exact for
// piecewise-linear signals), so irregular sampling is handled correctly. The
// integrals are differences of one running (prefix) integral: O(1) per window.
#pragma once

#include <vector>

namespace railsim::results {

struct WindowedSeries {
  std::vector<double> centre;  // window centres (same unit as the abscissa)
  std::vector<double> value;   // statistic over the window
};

// Sliding mean of y(x) over windows of length `window`, centres every `step`,
// starting at x.front() + window/2 and ending at or before x.back() - window/2.
// x must be strictly increasing; throws std::invalid_argument otherwise.
WindowedSeries sliding_mean(const std::vector<double>& x, const std::vector<double>& y, double window,
                            double step);

// Sliding root-mean-square of y(x) (square of the interpolated signal integrated exactly).
WindowedSeries sliding_rms(const std::vector<double>& x, const std::vector<double>& y, double window,
                           double step);

// Percentile (0..100) by linear interpolation between order statistics (the
// "type 7" definition of Hyndman & Fan 1996). Empty input -> NaN.
double percentile(std::vector<double> values, double p);

// Several percentiles of the same values (one sort), same definition.
std::vector<double> percentiles(std::vector<double> values, const std::vector<double>& p);

}  // namespace railsim::results
