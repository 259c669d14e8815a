// Tests of contact/mim/influence.cpp and convolution.cpp: element integrals
// against numerical quadrature, and the FFT product against a direct sum;
// an FFTW plan that cannot be made is a NumericalError.
#include <catch2/catch.hpp>
#include <fftw3.h>

#include <cmath>
#include <mutex>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "contact/mim/convolution.hpp"
#include "contact/mim/influence.hpp"
#include "contact/mim/influence_operator.hpp"
#include "core/errors.hpp"
#include "core/fftw_planner_lock.hpp"

using namespace railsim::contact::mim;

namespace {
// Midpoint quadrature of f over the element centred at the origin, field at (X, Y).
template <class F>
double quad(F f, double X, double Y, double dx, double dy, int n = 400) {
  double s = 0.0;
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) {
      const double xs = -0.5 * dx + (a + 0.5) * dx / n, ys = -0.5 * dy + (b + 0.5) * dy / n;
      s += f(X - xs, Y - ys);
    }
  return s * dx * dy / (n * n);
}
}  // namespace

TEST_CASE("element integrals match quadrature away from the element", "[mim][influence]") {
  const double dx = 1.0, dy = 0.6;
  for (auto [X, Y] : {std::pair{2.0, 0.3}, {-3.1, 1.7}, {0.4, -2.2}, {5.0, 5.0}}) {
    auto r = [](double x, double y) { return std::hypot(x, y); };
    CHECK(integral_inv_r(X, Y, dx, dy) == Approx(quad([&](double x, double y) { return 1 / r(x, y); }, X, Y, dx, dy)).epsilon(1e-5));
    CHECK(integral_x2_r3(X, Y, dx, dy) == Approx(quad([&](double x, double y) { return x * x / std::pow(r(x, y), 3); }, X, Y, dx, dy)).epsilon(1e-5));
    CHECK(integral_y2_r3(X, Y, dx, dy) == Approx(quad([&](double x, double y) { return y * y / std::pow(r(x, y), 3); }, X, Y, dx, dy)).epsilon(1e-5));
    CHECK(integral_xy_r3(X, Y, dx, dy) == Approx(quad([&](double x, double y) { return x * y / std::pow(r(x, y), 3); }, X, Y, dx, dy)).epsilon(1e-4));
    CHECK(integral_x_r2(X, Y, dx, dy) == Approx(quad([&](double x, double y) { return x / (r(x, y) * r(x, y)); }, X, Y, dx, dy)).epsilon(1e-4));
  }
}

TEST_CASE("self-influence of a square element has the closed form 4 dx asinh(1)", "[mim][influence]") {
  // Integral of 1/r over a square of side d at its centre: 4 d asinh(1) (Love 1929).
  const double d = 0.3;
  CHECK(integral_inv_r(0, 0, d, d) == Approx(4.0 * d * std::asinh(1.0)).epsilon(1e-13));
  // Symmetry: I_xx + I_yy = I_r, I_xy = 0 on the axes.
  CHECK(integral_x2_r3(0, 0, d, d) + integral_y2_r3(0, 0, d, d) == Approx(integral_inv_r(0, 0, d, d)));
  CHECK(std::abs(integral_xy_r3(2 * d, 0, d, d)) < 1e-15);
  // Far field: integral of 1/r -> area / distance.
  CHECK(integral_inv_r(100 * d, 37 * d, d, d) == Approx(d * d / std::hypot(100 * d, 37 * d)).epsilon(1e-4));
}

TEST_CASE("combined constants of two bodies", "[mim][influence]") {
  const auto same = ElasticPair::from_bodies(80e9, 0.28, 80e9, 0.28);
  CHECK(same.G == Approx(80e9));
  CHECK(same.nu == Approx(0.28));
  CHECK(same.K == 0.0);
  const auto diff = ElasticPair::from_bodies(80e9, 0.3, 40e9, 0.25);
  CHECK(diff.G == Approx(2.0 / (1 / 80e9 + 1 / 40e9)));
  CHECK(diff.K != 0.0);
  CHECK(coupling_zx(same, 1.0, 0.2, 0.5, 0.5) == 0.0);
}

TEST_CASE("FFT convolution equals the direct sum", "[mim][convolution]") {
  CHECK(fft_friendly_size(127) == 128);
  CHECK(fft_friendly_size(121) == 125);
  const int mx = 13, my = 7;
  Convolution conv(mx, my, 2, 64u /* FFTW_ESTIMATE */);
  auto k0 = [](int i, int j) { return 1.0 / (1.0 + i * i + 2.0 * j * j) + 0.1 * i; };
  auto k1 = [](int i, int j) { return std::cos(0.3 * i) * std::exp(-0.1 * j * j); };
  conv.set_kernel(0, k0);
  conv.set_kernel(1, k1);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> U(-1, 1);
  std::vector<double> a(mx * my), b(mx * my), out(mx * my), ox(mx * my), oy(mx * my);
  for (auto& v : a) v = U(rng);
  for (auto& v : b) v = U(rng);
  conv.apply(0, a.data(), out.data());
  conv.apply_block(0, 1, 1, 0, a.data(), b.data(), ox.data(), oy.data());
  double err = 0, err2 = 0;
  for (int j = 0; j < my; ++j)
    for (int i = 0; i < mx; ++i) {
      double s = 0, sx = 0, sy = 0;
      for (int l = 0; l < my; ++l)
        for (int k = 0; k < mx; ++k) {
          s += k0(i - k, j - l) * a[k + mx * l];
          sx += k0(i - k, j - l) * a[k + mx * l] + k1(i - k, j - l) * b[k + mx * l];
          sy += k1(i - k, j - l) * a[k + mx * l] + k0(i - k, j - l) * b[k + mx * l];
        }
      err = std::max(err, std::abs(s - out[i + mx * j]));
      err2 = std::max({err2, std::abs(sx - ox[i + mx * j]), std::abs(sy - oy[i + mx * j])});
    }
  CHECK(err < 1e-12);
  CHECK(err2 < 1e-12);
}

TEST_CASE("rolling operator is the x-difference of the shift operator", "[mim][influence]") {
  ContactGrid g{9, 6, 0.2e-3, 0.3e-3, -0.9e-3, -0.9e-3};
  ElasticPair m;
  InfluenceOperator op(g, m, 0.0, 64u);
  std::vector<double> px(g.size(), 0.0), py(g.size(), 0.0), vx(g.size()), vy(g.size());
  px[g.index(4, 2)] = 1e6;  // a single loaded element
  op.rolling(px.data(), py.data(), vx.data(), vy.data());
  for (int i = 0; i < g.mx; ++i) {
    const double X = (i - 4) * g.dx, Y = (3 - 2) * g.dy;
    const double expect = 1e6 * (influence_xx(m, X, Y, g.dx, g.dy) - influence_xx(m, X + g.dx, Y, g.dx, g.dy)) / g.dx;
    CHECK(vx[g.index(i, 3)] == Approx(expect).epsilon(1e-9));
    const double expect_y = 1e6 * (influence_xy(m, X, Y, g.dx, g.dy) - influence_xy(m, X + g.dx, Y, g.dx, g.dy)) / g.dx;
    CHECK(vy[g.index(i, 3)] == Approx(expect_y).margin(1e-9 * std::abs(expect)));
  }
}

TEST_CASE("an FFTW plan that cannot be made is a NumericalError naming the transform, not a crash",
          "[mim][convolution][bad_input]") {
  // FFTW_WISDOM_ONLY: FFTW returns no plan (NULL) when it holds no wisdom for the size.
  {
    std::lock_guard<std::mutex> lock(railsim::fftw_planner_mutex());
    fftw_forget_wisdom();
  }
  std::string msg;
  try {
    Convolution conv(37, 23, 1, FFTW_ESTIMATE | FFTW_WISDOM_ONLY);
  } catch (const railsim::NumericalError& e) {
    msg = e.what();
  }
  INFO(msg);
  CHECK(msg.find("mim convolution: FFTW returned no plan (NULL) for the forward (r2c) 2-D transform of ") == 0);
  CHECK(msg.find(" points, flags ") != std::string::npos);
  // Planning normally afterwards works (nothing left half made).
  CHECK_NOTHROW(Convolution(37, 23, 1, FFTW_ESTIMATE));
}
