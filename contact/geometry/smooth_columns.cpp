// Smooth C1 columns; see smooth_columns.hpp.
#include "contact/geometry/smooth_columns.hpp"

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"

namespace railsim::contact {

namespace {
void check_grid(std::size_t n, int cols, double h, const char* what) {
  if (n < 2 || cols < 1 || !(h > 0.0) || !std::isfinite(h))
    throw InputError(std::string("smooth table (") + what + "): need at least 2 rows, 1 column and a positive step");
}
}  // namespace

SmoothColumns SmoothColumns::from_data(std::vector<double> data, std::size_t nodes, int cols, double x0, double h) {
  check_grid(nodes, cols, h, "stored");
  if (data.size() != nodes * std::size_t(2 * cols)) throw InputError("smooth table (stored): size mismatch");
  SmoothColumns s;
  s.x0_ = x0;
  s.h_ = h;
  s.nodes_ = nodes;
  s.cols_ = cols;
  s.data_ = std::move(data);
  s.deviation_.assign(std::size_t(cols), Deviation{});
  return s;
}

SmoothColumns SmoothColumns::fit_noisy(const std::vector<double>& raw, std::size_t rows, int cols, double raw_x0,
                                       double raw_h, double node_step, double halfwidth) {
  check_grid(rows, cols, raw_h, "raw rows");
  if (raw.size() != rows * std::size_t(cols)) throw InputError("smooth table: raw size mismatch");
  if (!(node_step >= raw_h && halfwidth >= raw_h))
    throw InputError("smooth table: node step and fit half-width must be at least the raw row spacing");
  const double span = raw_h * double(rows - 1);
  const auto nodes = std::size_t(std::floor(span / node_step + 1e-9)) + 1;
  const double h = nodes > 1 ? span / double(nodes - 1) : span;  // nodes span the raw range exactly
  SmoothColumns s;
  s.x0_ = raw_x0;
  s.h_ = h;
  s.nodes_ = std::max<std::size_t>(nodes, 2);
  if (nodes < 2) s.h_ = span;
  s.cols_ = cols;
  s.data_.assign(s.nodes_ * std::size_t(2 * cols), 0.0);
  const long half = std::max(1L, std::lround(halfwidth / raw_h));
  for (std::size_t i = 0; i < s.nodes_; ++i) {
    const double xi = raw_x0 + double(i) * s.h_;
    const long c = std::lround((xi - raw_x0) / raw_h);
    // Window of rows, shifted inward at the ends so it keeps its width.
    long lo = c - half, hi = c + half;
    if (lo < 0) {
      hi -= lo;
      lo = 0;
    }
    if (hi > long(rows) - 1) {
      lo -= hi - (long(rows) - 1);
      hi = long(rows) - 1;
    }
    lo = std::max(lo, 0L);
    // Least-squares quadratic in u = (x - xi)/halfwidth: normal equations.
    double S[5] = {0, 0, 0, 0, 0};
    for (long r = lo; r <= hi; ++r) {
      const double u = (raw_x0 + double(r) * raw_h - xi) / halfwidth;
      double p = 1.0;
      for (double& sk : S) {
        sk += p;
        p *= u;
      }
    }
    // 3x3 system [S0 S1 S2; S1 S2 S3; S2 S3 S4] c = b, solved by Cramer (well conditioned: u in [-2, 2]).
    const double a00 = S[0], a01 = S[1], a02 = S[2], a11 = S[2], a12 = S[3], a22 = S[4];
    const double det = a00 * (a11 * a22 - a12 * a12) - a01 * (a01 * a22 - a12 * a02) + a02 * (a01 * a12 - a11 * a02);
    for (int k = 0; k < cols; ++k) {
      double b0 = 0, b1 = 0, b2 = 0;
      for (long r = lo; r <= hi; ++r) {
        const double u = (raw_x0 + double(r) * raw_h - xi) / halfwidth;
        const double v = raw[std::size_t(r) * std::size_t(cols) + std::size_t(k)];
        b0 += v;
        b1 += v * u;
        b2 += v * u * u;
      }
      const double c0 = (b0 * (a11 * a22 - a12 * a12) - a01 * (b1 * a22 - a12 * b2) + a02 * (b1 * a12 - a11 * b2)) / det;
      const double c1 = (a00 * (b1 * a22 - a12 * b2) - b0 * (a01 * a22 - a12 * a02) + a02 * (a01 * b2 - b1 * a02)) / det;
      s.data_[i * std::size_t(2 * cols) + std::size_t(k)] = c0;
      s.data_[i * std::size_t(2 * cols) + std::size_t(cols + k)] = c1 / halfwidth;
    }
  }
  s.limit_slopes();
  // Deviation from the raw rows.
  s.deviation_.assign(std::size_t(cols), Deviation{});
  std::vector<double> v(static_cast<std::size_t>(cols));
  for (std::size_t r = 0; r < rows; ++r) {
    const double x = raw_x0 + double(r) * raw_h;
    s.eval(x, v.data());
    for (int k = 0; k < cols; ++k) {
      const double d = std::abs(v[std::size_t(k)] - raw[r * std::size_t(cols) + std::size_t(k)]);
      if (d > s.deviation_[std::size_t(k)].max_abs) s.deviation_[std::size_t(k)] = {d, x};
    }
  }
  return s;
}

SmoothColumns SmoothColumns::interpolate(const std::vector<double>& values, std::size_t nodes, int cols, double x0,
                                         double h, bool monotone_limiter) {
  check_grid(nodes, cols, h, "nodes");
  if (values.size() != nodes * std::size_t(cols)) throw InputError("smooth table: node size mismatch");
  SmoothColumns s;
  s.x0_ = x0;
  s.h_ = h;
  s.nodes_ = nodes;
  s.cols_ = cols;
  s.data_.assign(nodes * std::size_t(2 * cols), 0.0);
  auto f = [&](std::size_t i, int k) { return values[i * std::size_t(cols) + std::size_t(k)]; };
  for (std::size_t i = 0; i < nodes; ++i)
    for (int k = 0; k < cols; ++k) {
      double m;
      if (nodes == 2) m = (f(1, k) - f(0, k)) / h;
      else if (i == 0) m = (-3.0 * f(0, k) + 4.0 * f(1, k) - f(2, k)) / (2.0 * h);
      else if (i == nodes - 1) m = (3.0 * f(i, k) - 4.0 * f(i - 1, k) + f(i - 2, k)) / (2.0 * h);
      else m = (f(i + 1, k) - f(i - 1, k)) / (2.0 * h);
      s.data_[i * std::size_t(2 * cols) + std::size_t(k)] = f(i, k);
      s.data_[i * std::size_t(2 * cols) + std::size_t(cols + k)] = m;
    }
  if (monotone_limiter) s.limit_slopes();
  s.deviation_.assign(std::size_t(cols), Deviation{});
  return s;
}

void SmoothColumns::limit_slopes() {
  // Fritsch & Carlson (1980): at a local extremum of the node values the slope
  // is zero; elsewhere |m| <= 3 min(|left secant|, |right secant|) and of
  // their sign, so each cell is monotone between monotone nodes (no overshoot).
  const std::size_t n2 = std::size_t(2 * cols_);
  for (int k = 0; k < cols_; ++k)
    for (std::size_t i = 0; i < nodes_; ++i) {
      double& m = data_[i * n2 + std::size_t(cols_ + k)];
      const double f = data_[i * n2 + std::size_t(k)];
      const double dl = i > 0 ? (f - data_[(i - 1) * n2 + std::size_t(k)]) / h_ : m;
      const double dr = i + 1 < nodes_ ? (data_[(i + 1) * n2 + std::size_t(k)] - f) / h_ : m;
      if (dl * dr <= 0.0) m = 0.0;
      else if (m * dl <= 0.0) m = 0.0;
      else m = std::copysign(std::min({std::abs(m), 3.0 * std::abs(dl), 3.0 * std::abs(dr)}), dl);
    }
}

void SmoothColumns::eval(double x, double* out, double* dout) const {
  const double u = (x - x0_) / h_;
  const double last = double(nodes_ - 1);
  const std::size_t n2 = std::size_t(2 * cols_);
  if (!(u > 0.0) || u >= last) {  // clamp (NaN goes to the first node)
    const std::size_t i = u >= last ? nodes_ - 1 : 0;
    const double* a = &data_[i * n2];
    for (int k = 0; k < cols_; ++k) {
      out[k] = a[k];
      if (dout) dout[k] = 0.0;
    }
    return;
  }
  const auto i = std::size_t(u);
  const double t = u - double(i);
  const double t2 = t * t, t3 = t2 * t;
  const double h00 = 2.0 * t3 - 3.0 * t2 + 1.0, h10 = (t3 - 2.0 * t2 + t) * h_;
  const double h01 = -2.0 * t3 + 3.0 * t2, h11 = (t3 - t2) * h_;
  const double* a = &data_[i * n2];
  const double* b = a + n2;
  for (int k = 0; k < cols_; ++k) out[k] = h00 * a[k] + h10 * a[cols_ + k] + h01 * b[k] + h11 * b[cols_ + k];
  if (dout) {
    const double d00 = (6.0 * t2 - 6.0 * t) / h_, d10 = 3.0 * t2 - 4.0 * t + 1.0;
    const double d01 = -d00, d11 = 3.0 * t2 - 2.0 * t;
    for (int k = 0; k < cols_; ++k) dout[k] = d00 * a[k] + d10 * a[cols_ + k] + d01 * b[k] + d11 * b[cols_ + k];
  }
}

double SmoothColumns::eval(double x, int col) const {
  const double u = std::clamp((x - x0_) / h_, 0.0, double(nodes_ - 1));
  const auto i = std::min(std::size_t(u), nodes_ - 2);
  const double t = u - double(i), t2 = t * t, t3 = t2 * t;
  const std::size_t n2 = std::size_t(2 * cols_);
  const double* a = &data_[i * n2];
  const double* b = a + n2;
  return (2.0 * t3 - 3.0 * t2 + 1.0) * a[col] + (t3 - 2.0 * t2 + t) * h_ * a[cols_ + col] +
         (-2.0 * t3 + 3.0 * t2) * b[col] + (t3 - t2) * h_ * b[cols_ + col];
}

double SmoothColumns::derivative(double x, int col) const {
  const double u = (x - x0_) / h_;
  if (!(u >= 0.0) || u > double(nodes_ - 1)) return 0.0;
  const auto i = std::min(std::size_t(u), nodes_ - 2);
  const double t = u - double(i), t2 = t * t;
  const std::size_t n2 = std::size_t(2 * cols_);
  const double* a = &data_[i * n2];
  const double* b = a + n2;
  const double d00 = (6.0 * t2 - 6.0 * t) / h_;
  return d00 * a[col] + (3.0 * t2 - 4.0 * t + 1.0) * a[cols_ + col] - d00 * b[col] + (3.0 * t2 - 2.0 * t) * b[cols_ + col];
}

}  // namespace railsim::contact
