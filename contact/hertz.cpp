// Hertz normal contact; see hertz.hpp for the equations and sources.
#include "contact/hertz.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "core/errors.hpp"

namespace railsim::contact {

namespace {

constexpr double kPi = 3.14159265358979323846;

std::string num(double v) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// The checks run on every call; the message is built out of line.
[[noreturn, gnu::cold, gnu::noinline]] void throw_not_positive(double v, const char* what, const char* unit) {
  throw InputError(std::string("Hertz contact: ") + what + " expected a positive finite number [" + unit +
                   "] (got " + num(v) + ")");
}

[[noreturn, gnu::cold, gnu::noinline]] void throw_bad_nu(double nu) {
  throw InputError("Hertz contact: Poisson's ratio nu expected a number in (0, 0.5] (got " + num(nu) + ")");
}

inline void require_positive(double v, const char* what, const char* unit) {
  if (!(v > 0.0 && v <= std::numeric_limits<double>::max())) [[unlikely]]
    throw_not_positive(v, what, unit);
}

inline void require_material(const Material& m) {
  require_positive(m.E, "Young's modulus E", "Pa");
  if (!(m.nu > 0.0 && m.nu <= 0.5)) [[unlikely]]
    throw_bad_nu(m.nu);
}

// Fill a patch whose major semi-axis lies along the direction of smaller curvature.
HertzPatch assemble(double A, double B, double Fz, double a_major, double b_minor, double approach) {
  HertzPatch p;
  p.A = A;
  p.B = B;
  if (A <= B) {
    p.a = a_major;
    p.b = b_minor;
  } else {
    p.a = b_minor;
    p.b = a_major;
  }
  p.Fz = Fz;
  p.p0 = 3.0 * Fz / (2.0 * kPi * p.a * p.b);
  p.approach = approach;
  return p;
}

HertzPatch patch_from_shape(double A, double B, const HertzShape& s, double Fz, const Material& m) {
  const double S = A + B;
  const double mc = s.g * s.g;
  const double a_major = std::cbrt(3.0 * Fz * s.E / (2.0 * kPi * m.combined_modulus() * S * mc));
  const double b_minor = a_major * s.g;
  return assemble(A, B, Fz, a_major, b_minor, S * b_minor * b_minor * s.K / s.E);
}

}  // namespace

HertzPatch hertz_from_load(double A, double B, double Fz, const Material& m) {
  require_positive(A, "curvature A", "1/m");
  require_positive(B, "curvature B", "1/m");
  require_positive(Fz, "normal load Fz", "N");
  require_material(m);
  return patch_from_shape(A, B, hertz_shape(std::min(A, B) / std::max(A, B)), Fz, m);
}

HertzPatch hertz_from_shape(double A, double B, const HertzShape& shape, double Fz, const Material& m) {
  require_positive(A, "curvature A", "1/m");
  require_positive(B, "curvature B", "1/m");
  require_positive(Fz, "normal load Fz", "N");
  require_material(m);
  if (!(shape.g > 0.0 && shape.g <= 1.0 && shape.K > 0.0 && shape.E > 0.0))
    throw InputError("Hertz contact: shape expected g in (0, 1] and K, E > 0 (from hertz_shape)");
  return patch_from_shape(A, B, shape, Fz, m);
}

HertzPatch hertz_from_approach(double A, double B, double approach, const Material& m) {
  require_positive(A, "curvature A", "1/m");
  require_positive(B, "curvature B", "1/m");
  require_positive(approach, "approach", "m");
  require_material(m);
  const HertzShape s = hertz_shape(std::min(A, B) / std::max(A, B));
  const double S = A + B;
  const double mc = s.g * s.g;
  const double b_minor = std::sqrt(approach * s.E / (S * s.K));
  const double a_major = b_minor / s.g;
  const double Fz = a_major * a_major * a_major * 2.0 * kPi * m.combined_modulus() * S * mc / (3.0 * s.E);
  return assemble(A, B, Fz, a_major, b_minor, approach);
}

HertzPatch hertz_from_semi_axes(double a, double b, double Fz, const Material& m) {
  require_positive(a, "semi-axis a", "m");
  require_positive(b, "semi-axis b", "m");
  require_positive(Fz, "normal load Fz", "N");
  require_material(m);
  const double a_major = std::max(a, b);
  const double b_minor = std::min(a, b);
  const double g = b_minor / a_major;
  if (g < 1.0e-5)
    throw InputError("Hertz contact: semi-axis ratio min(a,b)/max(a,b) expected a number in [1e-5, 1] (got " +
                     num(g) + ")");
  const HertzShapeAndRatio f = hertz_shape_from_axes(g);
  const double mc = g * g, K = f.shape.K, E = f.shape.E, rho = f.ratio;
  const double S = 3.0 * Fz * E / (2.0 * kPi * m.combined_modulus() * mc * a_major * a_major * a_major);
  const double c_small = S * rho / (1.0 + rho);  // curvature along the major axis
  const double c_large = S / (1.0 + rho);
  const double A = a >= b ? c_small : c_large;
  const double B = a >= b ? c_large : c_small;
  HertzPatch p;
  p.A = A;
  p.B = B;
  p.a = a;
  p.b = b;
  p.Fz = Fz;
  p.p0 = 3.0 * Fz / (2.0 * kPi * a * b);
  p.approach = S * b_minor * b_minor * K / E;
  return p;
}

HertzCoefficients hertz_coefficients(double A, double B) {
  require_positive(A, "curvature A", "1/m");
  require_positive(B, "curvature B", "1/m");
  const HertzShape s = hertz_shape(std::min(A, B) / std::max(A, B));
  const double m_major = std::cbrt(2.0 * s.E / (kPi * s.g * s.g));
  const double n_minor = m_major * s.g;
  const double r = 2.0 * s.K / (kPi * m_major);
  if (A <= B) return {m_major, n_minor, r};
  return {n_minor, m_major, r};
}

}  // namespace railsim::contact
