// Hertz normal contact; see hertz.hpp for the equations and sources.
#include "contact/hertz.hpp"

#include <boost/math/interpolators/cardinal_cubic_b_spline.hpp>
#include <boost/math/special_functions/ellint_rd.hpp>
#include <boost/math/special_functions/ellint_rf.hpp>
#include <boost/math/tools/roots.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <tuple>
#include <vector>

#include "core/errors.hpp"

namespace railsim::contact {

namespace {

constexpr double kPi = 3.14159265358979323846;
// Boost.Math without promotion to long double: double precision is what we need
// and the promotion triples the cost.
using FastPolicy = boost::math::policies::policy<boost::math::policies::promote_double<false>>;

// Most elongated patch accepted: min(A,B)/max(A,B) >= 1e-10 (a/b up to ~3e4).
constexpr double kMinRatio = 1.0e-10;

std::string num(double v) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

void require_positive(double v, const char* what, const char* unit) {
  if (!(std::isfinite(v) && v > 0.0))
    throw InputError(std::string("Hertz contact: ") + what + " expected a positive finite number [" + unit +
                     "] (got " + num(v) + ")");
}

void require_material(const Material& m) {
  require_positive(m.E, "Young's modulus E", "Pa");
  if (!(std::isfinite(m.nu) && m.nu > 0.0 && m.nu <= 0.5))
    throw InputError("Hertz contact: Poisson's ratio nu expected a number in (0, 0.5] (got " + num(m.nu) + ")");
}

// Elliptic integrals for the complementary parameter mc = 1 - e^2 = g^2 in the
// Carlson form: K = R_F, Dk = (K - E)/m = R_D/3, Bf = (E - mc K)/m = R_F - R_D/3.
struct Associate {
  double K, E, Dk, Bf;
};
Associate associate(double mc) {
  const double rf = boost::math::ellint_rf(0.0, mc, 1.0, FastPolicy());
  const double rd = boost::math::ellint_rd(0.0, mc, 1.0, FastPolicy());
  const double m = 1.0 - mc;
  return {rf, rf - m * rd / 3.0, rd / 3.0, rf - rd / 3.0};
}

// Start value of ln(a/b) >= 0 for the curvature ratio rho = min/max <= 1.
double log_aspect_start(double rho) {
  const double L = -std::log(rho);  // ln(B/A) >= 0
  if (L <= std::log(1.0e4)) {
    // Least-squares fit of the exact solution, physics-reference.md sec. 1.5 (0.1 %).
    return L * (0.66968778 + L * (-0.0036457736 + L * (-0.0022028801 + L * (0.00029939959 - 1.2107189e-5 * L))));
  }
  // Very elongated: rho ~ g^2 (ln(4/g) - 1) for g -> 0 (K ~ ln(4/g), E ~ 1).
  double g = std::sqrt(rho);
  for (int i = 0; i < 3; ++i) g = std::sqrt(rho / (std::log(4.0 / g) - 1.0));
  return -std::log(g);
}

}  // namespace

namespace {

// h(v) = ln(rho(mc)) - ln(ratio) and dh/dv for the unknown v = ln(a/b) + 1 >= 1,
// mc = (b/a)^2 = exp(-2 (v - 1)), rho(mc) = mc Dk / Bf (shape equation, Carlson
// form). h decreases with v (rho falls as a/b grows). Derivatives from
// K' = Bf/(2 mc), E' = -Dk/2 (d/dm), with series limits for small m to avoid 0/0.
struct ShapeResidual {
  double f, df, mc;
  Associate s;
};
ShapeResidual shape_residual(double v, double log_target) {
  ShapeResidual r;
  r.mc = std::exp(-2.0 * (v - 1.0));
  const double m = 1.0 - r.mc;
  r.s = associate(r.mc);
  double dDk, dBf;
  if (m > 1.0e-4) {
    dDk = (r.s.Bf / (2.0 * r.mc) - r.s.Dk / 2.0) / m;
    dBf = r.s.Bf / (2.0 * r.mc) - dDk;
  } else {
    dDk = 3.0 * kPi / 32.0;
    dBf = kPi / 32.0;
  }
  const double dlnrho_dmc = 1.0 / r.mc - dDk / r.s.Dk + dBf / r.s.Bf;
  r.f = std::log(r.mc * r.s.Dk / r.s.Bf) - log_target;
  r.df = -2.0 * r.mc * dlnrho_dmc;  // dmc/dv = -2 mc
  return r;
}

// Robust path: Boost's safeguarded Newton-Raphson (bisection fallback) inside the
// bracket mc <= rho (since Dk >= Bf) and mc >= rho / e^10 (valid for rho >= 1e-10).
HertzShape shape_iterative(double ratio, double v_start) {
  // The +1 in v makes Boost's relative step criterion an absolute one on ln(a/b).
  const double log_target = std::log(ratio);
  ShapeResidual last{};
  auto h = [&](double v) {
    last = shape_residual(v, log_target);
    return std::make_tuple(last.f, last.df);
  };
  const double vmin = 1.0 - 0.5 * log_target;
  const double vmax = vmin + 5.0;
  std::uintmax_t max_iter = 60;
  boost::math::tools::newton_raphson_iterate(h, std::clamp(v_start, vmin, vmax), vmin, vmax, 42, max_iter);
  if (max_iter >= 60)
    throw NumericalError("Hertz contact: eccentricity root-find did not converge for curvature ratio " +
                         num(ratio));
  // The last evaluated point is within the final Newton step (< 1e-12) of the
  // root; use it so that g, K and E are mutually consistent.
  return {std::sqrt(last.mc), last.s.K, last.s.E};
}

// Start values: g = b/a (minor/major) against L = ln(max/min curvature) on
// 0 <= L <= ln(1e4), a cubic B-spline (Boost.Math) through 1025 exact solutions
// computed once (end slopes: g'(0) = -2/3 from the small-eccentricity expansion
// rho = 1 - 3m/4 + O(m^2), and a central difference at the far end). Its error
// (< 1e-7 relative) lets a single Newton step reach full precision.
class ShapeStart {
 public:
  static constexpr double kLmax = 9.210340371976184;  // ln(1e4)
  static constexpr int kNodes = 1025;
  ShapeStart() {
    std::vector<double> y(kNodes);
    const double h = kLmax / (kNodes - 1);
    for (int i = 0; i < kNodes; ++i) y[i] = i == 0 ? 1.0 : g_exact(i * h);
    const double d = 1e-4;
    const double right = (g_exact(kLmax + d) - g_exact(kLmax - d)) / (2.0 * d);
    spline_ = boost::math::interpolators::cardinal_cubic_b_spline<double>(y.data(), y.size(), 0.0, h, -2.0 / 3.0,
                                                                          right);
  }
  double operator()(double L) const { return spline_(L); }

 private:
  static double g_exact(double L) {
    const double rho = std::exp(-L);
    return shape_iterative(rho, log_aspect_start(rho) + 1.0).g;
  }
  boost::math::interpolators::cardinal_cubic_b_spline<double> spline_;
};

const ShapeStart& shape_start() {
  static const ShapeStart s;  // immutable after construction
  return s;
}

}  // namespace

HertzShape hertz_shape(double ratio) {
  if (!(std::isfinite(ratio) && ratio > 0.0 && ratio <= 1.0))
    throw InputError("Hertz contact: curvature ratio min(A,B)/max(A,B) expected a number in (0, 1] (got " +
                     num(ratio) + ")");
  if (ratio < kMinRatio)
    throw InputError("Hertz contact: curvature ratio min(A,B)/max(A,B) expected a number in [1e-10, 1] (got " +
                     num(ratio) + "); such a patch is not Hertzian, use a semi-Hertzian model");
  if (ratio >= 1.0 - 1.0e-15) return {1.0, kPi / 2.0, kPi / 2.0};
  const double L = -std::log(ratio);
  if (L > ShapeStart::kLmax) return shape_iterative(ratio, log_aspect_start(ratio) + 1.0);
  // Fast path: spline start g0, one Newton step on rho(g^2) - ratio, and K, E
  // carried to the new point by their first derivatives (error O(step^2) ~ 1e-16).
  const double g0 = shape_start()(L);
  const double mc0 = g0 * g0;
  const double m0 = 1.0 - mc0;
  const Associate s = associate(mc0);
  double dDk, dBf;  // d/dm, series limits for small m
  if (m0 > 1.0e-4) {
    dDk = (s.Bf / (2.0 * mc0) - s.Dk / 2.0) / m0;
    dBf = s.Bf / (2.0 * mc0) - dDk;
  } else {
    dDk = 3.0 * kPi / 32.0;
    dBf = kPi / 32.0;
  }
  const double rho = mc0 * s.Dk / s.Bf;
  const double drho_dg = 2.0 * g0 * rho * (1.0 / mc0 - dDk / s.Dk + dBf / s.Bf);
  const double dg = -(rho - ratio) / drho_dg;
  if (!(std::abs(dg) < 1.0e-6 * g0)) return shape_iterative(ratio, 1.0 - std::log(g0 + dg));
  const double g = g0 + dg;
  const double dm = -(2.0 * g0 + dg) * dg;  // m - m0 = mc0 - g^2
  return {g, s.K + s.Bf / (2.0 * mc0) * dm, s.E - 0.5 * s.Dk * dm};
}

namespace {

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

}  // namespace

namespace {

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
  const double mc = g * g;
  double K = kPi / 2.0, E = kPi / 2.0, rho = 1.0;
  if (g < 1.0) {
    const Associate s = associate(mc);
    K = s.K;
    E = s.E;
    rho = mc * s.Dk / s.Bf;  // shape equation: min/max curvature
  }
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
