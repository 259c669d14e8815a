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

// Sliding integrals by prefix sums: C[i] = integral from x[0] to x[i] of the
// linearly interpolated y (order 1) or of its square (order 2), exact for
// piecewise-linear signals; a window is the difference of two prefix values,
// each completed by the part of its segment up to the window edge. O(1) per
// window after one O(n) pass.
class PrefixIntegral {
 public:
  PrefixIntegral(const std::vector<double>& x, const std::vector<double>& y, int order)
      : x_(x), y_(y), order_(order), c_(x.size(), 0.0) {
    for (std::size_t i = 0; i + 1 < x.size(); ++i) c_[i + 1] = c_[i] + part(i, x[i + 1] - x[i]);
  }
  // Integral from x[0] to s (s clamped to the abscissa range); `j` is a
  // non-decreasing search hint (s must not decrease between calls with one hint).
  double at(double s, std::size_t& j) const {
    s = std::clamp(s, x_.front(), x_.back());
    while (j + 2 < x_.size() && x_[j + 1] <= s) ++j;
    return c_[j] + part(j, s - x_[j]);
  }

 private:
  // Integral over [x[i], x[i] + h] of segment i.
  double part(std::size_t i, double h) const {
    const double y0 = y_[i];
    const double m = (y_[i + 1] - y_[i]) / (x_[i + 1] - x_[i]);
    if (order_ == 1) return h * (y0 + 0.5 * m * h);
    return h * (y0 * y0 + h * (y0 * m + m * m * h / 3.0));
  }
  const std::vector<double>& x_;
  const std::vector<double>& y_;
  int order_;
  std::vector<double> c_;
};

WindowedSeries sliding(const std::vector<double>& x, const std::vector<double>& y, double window, double step,
                       int order) {
  check_input(x, y, window, step);
  WindowedSeries out;
  const PrefixIntegral F(x, y, order);
  std::size_t ja = 0, jb = 0;
  const double first = x.front() + 0.5 * window;
  const double last = x.back() - 0.5 * window;
  const double tol = 1e-12 * std::max(1.0, std::fabs(last));
  if (first <= last + tol) {
    const auto count = static_cast<std::size_t>(std::floor((last + tol - first) / step)) + 1;
    out.centre.reserve(count);
    out.value.reserve(count);
  }
  for (long k = 0;; ++k) {
    const double c = first + static_cast<double>(k) * step;
    if (c > last + tol) break;
    const double hi = F.at(c + 0.5 * window, jb);
    const double lo = F.at(c - 0.5 * window, ja);
    const double v = (hi - lo) / window;
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

namespace {
double sorted_percentile(const std::vector<double>& values, double p) {
  const double pos = std::clamp(p, 0.0, 100.0) / 100.0 * static_cast<double>(values.size() - 1);
  const auto lo = static_cast<std::size_t>(std::floor(pos));
  const auto hi = std::min(lo + 1, values.size() - 1);
  return values[lo] + (pos - static_cast<double>(lo)) * (values[hi] - values[lo]);
}
}  // namespace

double percentile(std::vector<double> values, double p) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(values.begin(), values.end());
  return sorted_percentile(values, p);
}

std::vector<double> percentiles(std::vector<double> values, const std::vector<double>& p) {
  // Selection instead of a sort: the two order statistics around each position (O(n) each).
  std::vector<double> out(p.size(), std::numeric_limits<double>::quiet_NaN());
  if (values.empty()) return out;
  const std::size_t n = values.size();
  for (std::size_t k = 0; k < p.size(); ++k) {
    const double pos = std::clamp(p[k], 0.0, 100.0) / 100.0 * static_cast<double>(n - 1);
    const auto lo = std::min(static_cast<std::size_t>(std::floor(pos)), n - 1);
    const auto nth = values.begin() + static_cast<std::ptrdiff_t>(lo);
    std::nth_element(values.begin(), nth, values.end());
    const double a = *nth;
    const double b = lo + 1 < n ? *std::min_element(nth + 1, values.end()) : a;
    out[k] = a + (pos - static_cast<double>(lo)) * (b - a);
  }
  return out;
}

}  // namespace railsim::results
