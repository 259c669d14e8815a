// Parametric natural cubic spline in chord length (see profile_spline.hpp).
#include "contact/geometry/profile_spline.hpp"

#include <algorithm>
#include <cmath>

namespace railsim::contact {

namespace {
// Natural cubic spline second derivatives for values f at knots t (Thomas algorithm).
std::vector<double> second_derivatives(const std::vector<double>& t, const std::vector<double>& f) {
  const std::size_t n = t.size();
  std::vector<double> m(n, 0.0);
  if (n < 3) return m;
  std::vector<double> diag(n, 1.0), upper(n, 0.0), lower(n, 0.0), rhs(n, 0.0);
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const double h0 = t[i] - t[i - 1];
    const double h1 = t[i + 1] - t[i];
    lower[i] = h0;
    diag[i] = 2.0 * (h0 + h1);
    upper[i] = h1;
    rhs[i] = 6.0 * ((f[i + 1] - f[i]) / h1 - (f[i] - f[i - 1]) / h0);
  }
  // Forward elimination (rows 0 and n-1 are M = 0).
  for (std::size_t i = 1; i < n; ++i) {
    const double w = lower[i] / diag[i - 1];
    diag[i] -= w * upper[i - 1];
    rhs[i] -= w * rhs[i - 1];
  }
  m[n - 1] = rhs[n - 1] / diag[n - 1];
  for (std::size_t i = n - 1; i-- > 0;) m[i] = (rhs[i] - upper[i] * m[i + 1]) / diag[i];
  return m;
}
}  // namespace

ParametricSpline::ParametricSpline(const std::vector<double>& y, const std::vector<double>& z)
    : t_(y.size(), 0.0), y_(y), z_(z) {
  for (std::size_t i = 1; i < y.size(); ++i) t_[i] = t_[i - 1] + std::hypot(y[i] - y[i - 1], z[i] - z[i - 1]);
  my_ = second_derivatives(t_, y_);
  mz_ = second_derivatives(t_, z_);
}

CurvePoint ParametricSpline::eval(double t) const {
  CurvePoint p;
  if (t_.size() < 2) return p;
  t = std::clamp(t, 0.0, t_.back());
  std::size_t i = static_cast<std::size_t>(std::upper_bound(t_.begin(), t_.end(), t) - t_.begin());
  i = std::clamp<std::size_t>(i, 1, t_.size() - 1) - 1;
  const double h = t_[i + 1] - t_[i];
  const double a = (t_[i + 1] - t) / h;
  const double b = (t - t_[i]) / h;
  auto value = [&](const std::vector<double>& f, const std::vector<double>& m) {
    return a * f[i] + b * f[i + 1] + ((a * a * a - a) * m[i] + (b * b * b - b) * m[i + 1]) * h * h / 6.0;
  };
  auto slope = [&](const std::vector<double>& f, const std::vector<double>& m) {
    return (f[i + 1] - f[i]) / h - (3.0 * a * a - 1.0) * h / 6.0 * m[i] + (3.0 * b * b - 1.0) * h / 6.0 * m[i + 1];
  };
  auto curv = [&](const std::vector<double>& m) { return a * m[i] + b * m[i + 1]; };
  p.y = value(y_, my_);
  p.z = value(z_, mz_);
  p.dy = slope(y_, my_);
  p.dz = slope(z_, mz_);
  p.ddy = curv(my_);
  p.ddz = curv(mz_);
  return p;
}

}  // namespace railsim::contact
