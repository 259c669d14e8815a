// Influence coefficients of rectangular elements; see influence.hpp for the
// equations (Love 1929; Boussinesq-Cerruti; Johnson 1985, sec. 3.2-3.6).
#include "contact/mim/influence.hpp"

#include <cmath>
#include <numbers>

namespace railsim::contact::mim {

namespace {

// x asinh(y/|x|): the part of x ln(y + r) that survives the corner sum.
double xasinh(double x, double y) {
  if (x == 0.0) return 0.0;
  return x * std::asinh(y / std::abs(x));
}

// Alternating corner sum of an antiderivative F(x, y) over the element
// [X - dx/2, X + dx/2] x [Y - dy/2, Y + dy/2].
template <class F>
double corner_sum(F f, double X, double Y, double dx, double dy) {
  const double x1 = X - 0.5 * dx, x2 = X + 0.5 * dx;
  const double y1 = Y - 0.5 * dy, y2 = Y + 0.5 * dy;
  return f(x2, y2) - f(x1, y2) - f(x2, y1) + f(x1, y1);
}

}  // namespace

ElasticPair ElasticPair::from_bodies(double G1, double nu1, double G2, double nu2) {
  ElasticPair m;
  m.G = 2.0 / (1.0 / G1 + 1.0 / G2);
  m.nu = 0.5 * m.G * (nu1 / G1 + nu2 / G2);
  m.K = 0.25 * m.G * ((1.0 - 2.0 * nu1) / G1 - (1.0 - 2.0 * nu2) / G2);
  return m;
}

double integral_inv_r(double X, double Y, double dx, double dy) {
  return corner_sum([](double x, double y) { return xasinh(x, y) + xasinh(y, x); }, X, Y, dx, dy);
}

double integral_x2_r3(double X, double Y, double dx, double dy) {
  return corner_sum([](double x, double y) { return xasinh(y, x); }, X, Y, dx, dy);
}

double integral_y2_r3(double X, double Y, double dx, double dy) {
  return corner_sum([](double x, double y) { return xasinh(x, y); }, X, Y, dx, dy);
}

double integral_xy_r3(double X, double Y, double dx, double dy) {
  return corner_sum([](double x, double y) { return -std::hypot(x, y); }, X, Y, dx, dy);
}

double integral_x_r2(double X, double Y, double dx, double dy) {
  // Antiderivative (y/2) ln(x^2 + y^2) + x atan(y/x); the linear term -y cancels.
  return corner_sum(
      [](double x, double y) {
        const double r2 = x * x + y * y;
        const double a = (y == 0.0 || r2 == 0.0) ? 0.0 : 0.5 * y * std::log(r2);
        const double b = (x == 0.0) ? 0.0 : x * std::atan(y / x);
        return a + b;
      },
      X, Y, dx, dy);
}

double influence_zz(const ElasticPair& m, double X, double Y, double dx, double dy) {
  return (1.0 - m.nu) / (std::numbers::pi * m.G) * integral_inv_r(X, Y, dx, dy);
}

double influence_xx(const ElasticPair& m, double X, double Y, double dx, double dy) {
  // (1 - nu) I_r + nu I_xx = (1 - nu) I_yy + I_xx
  return ((1.0 - m.nu) * integral_y2_r3(X, Y, dx, dy) + integral_x2_r3(X, Y, dx, dy)) /
         (std::numbers::pi * m.G);
}

double influence_yy(const ElasticPair& m, double X, double Y, double dx, double dy) {
  return ((1.0 - m.nu) * integral_x2_r3(X, Y, dx, dy) + integral_y2_r3(X, Y, dx, dy)) /
         (std::numbers::pi * m.G);
}

double influence_xy(const ElasticPair& m, double X, double Y, double dx, double dy) {
  return m.nu / (std::numbers::pi * m.G) * integral_xy_r3(X, Y, dx, dy);
}

double coupling_zx(const ElasticPair& m, double X, double Y, double dx, double dy) {
  if (m.K == 0.0) return 0.0;
  return -m.K / (std::numbers::pi * m.G) * integral_x_r2(X, Y, dx, dy);
}

double coupling_zy(const ElasticPair& m, double X, double Y, double dx, double dy) {
  if (m.K == 0.0) return 0.0;
  return -m.K / (std::numbers::pi * m.G) * integral_x_r2(Y, X, dy, dx);
}

}  // namespace railsim::contact::mim
