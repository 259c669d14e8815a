// Settled amplitude of an oscillating signal; see limit_cycle.hpp.
#include "results/limit_cycle.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace railsim::results {

LimitCycle settled_amplitude(const std::vector<double>& t, const std::vector<double>& y, double tail_fraction) {
  if (t.size() != y.size() || t.size() < 4) throw std::invalid_argument("settled_amplitude: need >= 4 samples");
  if (!(tail_fraction > 0.0 && tail_fraction <= 1.0))
    throw std::invalid_argument("settled_amplitude: tail_fraction must be in (0, 1]");
  const double t_start = t.back() - tail_fraction * (t.back() - t.front());
  std::size_t i0 = 0;
  while (i0 < t.size() && t[i0] < t_start) ++i0;
  LimitCycle out;
  const std::size_t n = t.size() - i0;
  if (n < 4) return out;
  double mean = 0.0;
  for (std::size_t i = i0; i < t.size(); ++i) mean += y[i];
  mean /= static_cast<double>(n);
  out.mean = mean;

  // Extremum of each half-cycle between zero crossings of (y - mean).
  std::vector<double> peaks;      // |extremum - mean|
  std::vector<double> crossings;  // abscissa of zero crossings
  double extremum = 0.0;
  bool started = false;
  for (std::size_t i = i0 + 1; i < t.size(); ++i) {
    const double a = y[i - 1] - mean, b = y[i] - mean;
    if ((a < 0.0 && b >= 0.0) || (a > 0.0 && b <= 0.0)) {
      const double tc = t[i - 1] + (t[i] - t[i - 1]) * (a / (a - b));
      if (started) peaks.push_back(extremum);
      crossings.push_back(tc);
      started = true;
      extremum = 0.0;
    }
    if (started) extremum = std::max(extremum, std::fabs(b));
  }
  out.half_cycles = static_cast<int>(peaks.size());
  if (peaks.size() < 2) {
    // No oscillation in the tail: the amplitude is the residual spread.
    double lo = y[i0], hi = y[i0];
    for (std::size_t i = i0; i < t.size(); ++i) lo = std::min(lo, y[i]), hi = std::max(hi, y[i]);
    out.amplitude = 0.5 * (hi - lo);
    return out;
  }
  double sum = 0.0;
  for (double p : peaks) sum += p;
  out.amplitude = sum / static_cast<double>(peaks.size());
  out.frequency = 0.5 * static_cast<double>(crossings.size() - 1) / (crossings.back() - crossings.front());
  const std::size_t third = std::max<std::size_t>(1, peaks.size() / 3);
  double first = 0.0, last = 0.0;
  for (std::size_t i = 0; i < third; ++i) first += peaks[i], last += peaks[peaks.size() - 1 - i];
  out.growth = first > 0.0 ? (last - first) / first : 0.0;
  return out;
}

}  // namespace railsim::results
