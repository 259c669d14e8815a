// Hertz ellipse shape from the curvature ratio; see hertz_shape.hpp for the
// equations, their sources and the accuracy of the fast path.
#include "contact/hertz_shape.hpp"

#include <boost/math/special_functions/ellint_rd.hpp>
#include <boost/math/special_functions/ellint_rf.hpp>
#include <boost/math/tools/roots.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <string>
#include <tuple>
#include <vector>

#include "core/errors.hpp"

namespace railsim::contact {

namespace {

constexpr double kPi = std::numbers::pi;
// Boost.Math without promotion to long double: double precision is what we need
// and the promotion triples the cost.
using FastPolicy = boost::math::policies::policy<boost::math::policies::promote_double<false>>;

// Most elongated patch accepted: min(A,B)/max(A,B) >= 1e-10 (a/b up to ~3e4).
constexpr double kMinRatio = 1.0e-10;
// Treated as the exact circle (K = E = pi/2, g = 1) above this ratio.
constexpr double kCircle = 1.0 - 1.0e-15;

[[noreturn, gnu::noinline, gnu::cold]] void reject_ratio(double ratio) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%g", ratio);
  if (std::isfinite(ratio) && ratio > 0.0 && ratio < kMinRatio)
    throw InputError(std::string("Hertz contact: curvature ratio min(A,B)/max(A,B) expected a number in "
                                 "[1e-10, 1] (got ") +
                     buf + "); such a patch is not Hertzian, use a semi-Hertzian model");
  throw InputError(std::string("Hertz contact: curvature ratio min(A,B)/max(A,B) expected a number in (0, 1] (got ") +
                   buf + ")");
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

// h(v) = ln(rho(mc)) - ln(ratio) and dh/dv for the unknown v = ln(a/b) + 1 >= 1,
// mc = (b/a)^2 = exp(-2 (v - 1)), rho(mc) = mc Dk / Bf (shape equation, Carlson
// form). h decreases with v (rho falls as a/b grows). Derivatives from
// dK/dm = Bf/(2 mc), dE/dm = -Dk/2, with series limits for small m to avoid 0/0.
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

// Piecewise Chebyshev interpolants of g, K, E in L = ln(B/A) on [0, ln 1e4]:
// kPieces pieces of degree kDegree, each interpolating hertz_shape_exact at the
// Chebyshev points of its piece, stored as monomials in the local t in [-1, 1]
// (Horner). Interpolation error ~ 2 (h/4)^8 / 8! max|f^(8)| < 1e-16 for
// h = ln(1e4)/64; what is measured (tests/contact/test_hertz.cpp) is < 1e-14.
class ShapeTable {
 public:
  static constexpr double kLmax = 9.210340371976184;  // ln(1e4)
  static constexpr int kPieces = 64;
  static constexpr int kDegree = 7;
  static constexpr int kNodes = kDegree + 1;

  ShapeTable() {
    const double h = kLmax / kPieces;
    for (int i = 0; i < kPieces; ++i) {
      std::array<std::array<double, kNodes>, 3> f{};  // g, K, E at the nodes
      std::array<double, kNodes> t{};
      for (int k = 0; k < kNodes; ++k) {
        t[k] = std::cos(kPi * (k + 0.5) / kNodes);
        const HertzShape s = hertz_shape_exact(std::exp(-(h * (i + 0.5 * (1.0 + t[k])))));
        f[0][k] = s.g;
        f[1][k] = s.K;
        f[2][k] = s.E;
      }
      for (int q = 0; q < 3; ++q) piece_[i][q] = monomials(chebyshev(f[q], t));
    }
  }

  HertzShape operator()(double L) const {
    const double u = L * (kPieces / kLmax);
    const int i = std::min(static_cast<int>(u), kPieces - 1);
    const double t = 2.0 * (u - i) - 1.0;
    const auto& p = piece_[static_cast<std::size_t>(i)];
    double g = p[0][kDegree], K = p[1][kDegree], E = p[2][kDegree];
    for (int j = kDegree - 1; j >= 0; --j) {
      g = g * t + p[0][static_cast<std::size_t>(j)];
      K = K * t + p[1][static_cast<std::size_t>(j)];
      E = E * t + p[2][static_cast<std::size_t>(j)];
    }
    return {std::min(g, 1.0), K, E};
  }

 private:
  using Coeffs = std::array<double, kNodes>;

  // Chebyshev coefficients c_j of the interpolant sum c_j T_j(t) through the
  // values at the Chebyshev points t_k (discrete orthogonality).
  static Coeffs chebyshev(const Coeffs& f, const Coeffs& t) {
    Coeffs c{};
    for (int j = 0; j < kNodes; ++j) {
      double s = 0.0;
      for (int k = 0; k < kNodes; ++k) s += f[k] * std::cos(j * std::acos(t[k]));
      c[j] = (j == 0 ? 1.0 : 2.0) * s / kNodes;
    }
    return c;
  }

  // sum c_j T_j(t) as sum a_j t^j, with T_{j+1} = 2 t T_j - T_{j-1}.
  static Coeffs monomials(const Coeffs& c) {
    Coeffs a{}, Tm{}, T{};  // T_{j-1}, T_j as monomial coefficients
    Tm[0] = 1.0;            // T_0
    T[1] = 1.0;             // T_1
    a[0] = c[0];
    for (int j = 1; j < kNodes; ++j) {
      for (int q = 0; q < kNodes; ++q) a[q] += c[j] * T[q];
      Coeffs Tn{};
      for (int q = 0; q + 1 < kNodes; ++q) Tn[q + 1] = 2.0 * T[q];
      for (int q = 0; q < kNodes; ++q) Tn[q] -= Tm[q];
      Tm = T;
      T = Tn;
    }
    return a;
  }

  std::array<std::array<Coeffs, 3>, kPieces> piece_{};
};

const ShapeTable& shape_table() {
  static const ShapeTable table;  // immutable after construction
  return table;
}

}  // namespace

HertzShape hertz_shape_exact(double ratio) {
  if (!(ratio >= kMinRatio && ratio <= 1.0)) reject_ratio(ratio);
  if (ratio >= kCircle) return {1.0, kPi / 2.0, kPi / 2.0};
  // The +1 in v makes Boost's relative step criterion an absolute one on ln(a/b).
  const double log_target = std::log(ratio);
  auto h = [&](double v) {
    const ShapeResidual r = shape_residual(v, log_target);
    return std::make_tuple(r.f, r.df);
  };
  // Bracket: mc <= rho (since Dk >= Bf) and mc >= rho / e^10 (valid for rho >= 1e-10).
  const double vmin = 1.0 - 0.5 * log_target;
  const double vmax = vmin + 5.0;
  std::uintmax_t max_iter = 60;
  const double v = boost::math::tools::newton_raphson_iterate(h, std::clamp(log_aspect_start(ratio) + 1.0, vmin, vmax),
                                                              vmin, vmax, 42, max_iter);
  if (max_iter >= 60) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%g", ratio);
    throw NumericalError(std::string("Hertz contact: eccentricity root-find did not converge for curvature ratio ") +
                         buf);
  }
  // The iteration stops after a step below 2^-42; Newton's quadratic convergence
  // puts the returned v within ~1e-25 of the root. Evaluate there so that g, K
  // and E belong to the same point.
  const ShapeResidual r = shape_residual(v, log_target);
  return {std::sqrt(r.mc), r.s.K, r.s.E};
}

HertzShape hertz_shape(double ratio) {
  if (!(ratio >= kMinRatio && ratio <= 1.0)) reject_ratio(ratio);
  if (ratio >= kCircle) return {1.0, kPi / 2.0, kPi / 2.0};
  const double L = -std::log(ratio);
  if (L > ShapeTable::kLmax) return hertz_shape_exact(ratio);
  return shape_table()(L);
}

HertzShapeAndRatio hertz_shape_from_axes(double g) {
  if (!(g > 0.0 && g <= 1.0)) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%g", g);
    throw InputError(std::string("Hertz contact: semi-axis ratio expected a number in (0, 1] (got ") + buf + ")");
  }
  if (g >= 1.0) return {{1.0, kPi / 2.0, kPi / 2.0}, 1.0};
  const double mc = g * g;
  const Associate s = associate(mc);
  return {{g, s.K, s.E}, mc * s.Dk / s.Bf};
}

}  // namespace railsim::contact
