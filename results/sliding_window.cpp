// Sliding-window statistics; see sliding_window.hpp.
#include "results/sliding_window.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace railsim::results {

namespace {

void check_input(const std::vector<double>& x, const std::vector<double>& y, double window, double step) {
  if (x.size() != y.size()) throw std::invalid_argument("sliding window: x and y differ in length");
  if (x.size() < 2) throw std::invalid_argument("sliding window: need at least two samples");
  if (!(window > 0.0) || !(step > 0.0)) throw std::invalid_argument("sliding window: window and step must be > 0");
  for (std::size_t i = 1; i < x.size(); ++i)
    if (!(x[i] > x[i - 1])) throw std::invalid_argument("sliding window: abscissa not strictly increasing");
}

// Integral over [a, b] of f(interpolated y), where `order` 1 integrates y and
// 2 integrates y^2 (exact for piecewise-linear y). `i0` is a search hint.
double integrate(const std::vector<double>& x, const std::vector<double>& y, double a, double b, int order,
                 std::size_t& i0) {
  while (i0 + 1 < x.size() && x[i0 + 1] <= a) ++i0;
  double sum = 0.0;
  for (std::size_t i = i0; i + 1 < x.size() && x[i] < b; ++i) {
    const double x0 = std::max(a, x[i]);
    const double x1 = std::min(b, x[i + 1]);
    if (x1 <= x0) continue;
    const double slope = (y[i + 1] - y[i]) / (x[i + 1] - x[i]);
    const double y0 = y[i] + slope * (x0 - x[i]);
    const double y1 = y[i] + slope * (x1 - x[i]);
    const double h = x1 - x0;
    if (order == 1)
      sum += 0.5 * (y0 + y1) * h;
    else
      sum += h * (y0 * y0 + y0 * y1 + y1 * y1) / 3.0;
  }
  return sum;
}

WindowedSeries sliding(const std::vector<double>& x, const std::vector<double>& y, double window, double step,
                       int order) {
  check_input(x, y, window, step);
  WindowedSeries out;
  std::size_t hint = 0;
  const double first = x.front() + 0.5 * window;
  const double last = x.back() - 0.5 * window;
  for (long k = 0;; ++k) {
    const double c = first + static_cast<double>(k) * step;
    if (c > last + 1e-12 * std::max(1.0, std::fabs(last))) break;
    const double v = integrate(x, y, c - 0.5 * window, c + 0.5 * window, order, hint) / window;
    out.centre.push_back(c);
    out.value.push_back(order == 1 ? v : std::sqrt(std::max(0.0, v)));
  }
  return out;
}

}  // namespace

WindowedSeries sliding_mean(const std::vector<double>& x, const std::vector<double>& y, double window,
                            double step) {
  return sliding(x, y, window, step, 1);
}

WindowedSeries sliding_rms(const std::vector<double>& x, const std::vector<double>& y, double window,
                           double step) {
  return sliding(x, y, window, step, 2);
}

double percentile(std::vector<double> values, double p) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(values.begin(), values.end());
  const double pos = std::clamp(p, 0.0, 100.0) / 100.0 * static_cast<double>(values.size() - 1);
  const auto lo = static_cast<std::size_t>(std::floor(pos));
  const auto hi = std::min(lo + 1, values.size() - 1);
  return values[lo] + (pos - static_cast<double>(lo)) * (values[hi] - values[lo]);
}

}  // namespace railsim::results
