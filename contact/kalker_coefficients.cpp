// Kalker's creep coefficients; see kalker_coefficients.hpp for sources and method.
#include "contact/kalker_coefficients.hpp"

#include <cmath>
// Boost 1.74's pchip.hpp calls isnan unqualified for double; make std::isnan visible.
using std::isnan;
#include <boost/math/interpolators/pchip.hpp>

#include <algorithm>
#include <array>
#include <cstdio>
#include <string>
#include <vector>

#include "core/errors.hpp"

namespace railsim::contact {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kNodes = 19;
constexpr int kSeries = 12;  // C11, C22, C23, C33 x nu = 0, 0.25, 0.5

struct Row {
  bool a_greater_b;  // false: g = a/b; true: g = b/a
  double g;
  double c[kSeries];  // C11(0, .25, .5), C22(...), C23(...), C33(...)
};

// Kalker (1990) Table E.3, rows ordered by increasing a/b (physics-reference.md sec. 2.2).
constexpr Row kTable[kNodes] = {
    {false, 0.1, {2.51, 3.31, 4.85, 2.51, 2.52, 2.53, 0.334, 0.473, 0.731, 6.42, 8.28, 11.7}},
    {false, 0.2, {2.59, 3.37, 4.81, 2.59, 2.63, 2.66, 0.483, 0.603, 0.809, 3.46, 4.27, 5.66}},
    {false, 0.3, {2.68, 3.44, 4.80, 2.68, 2.75, 2.81, 0.607, 0.715, 0.889, 2.49, 2.96, 3.72}},
    {false, 0.4, {2.78, 3.53, 4.82, 2.78, 2.88, 2.98, 0.720, 0.823, 0.977, 2.02, 2.32, 2.77}},
    {false, 0.5, {2.88, 3.62, 4.83, 2.88, 3.01, 3.14, 0.827, 0.929, 1.07, 1.74, 1.93, 2.22}},
    {false, 0.6, {2.98, 3.72, 4.91, 2.98, 3.14, 3.31, 0.930, 1.03, 1.18, 1.56, 1.68, 1.86}},
    {false, 0.7, {3.09, 3.81, 4.97, 3.09, 3.28, 3.48, 1.03, 1.14, 1.29, 1.43, 1.50, 1.60}},
    {false, 0.8, {3.19, 3.91, 5.05, 3.19, 3.41, 3.65, 1.13, 1.25, 1.40, 1.34, 1.37, 1.42}},
    {false, 0.9, {3.29, 4.01, 5.12, 3.29, 3.54, 3.82, 1.23, 1.36, 1.51, 1.27, 1.27, 1.27}},
    {false, 1.0, {3.40, 4.12, 5.20, 3.40, 3.67, 3.98, 1.33, 1.47, 1.63, 1.21, 1.19, 1.16}},
    {true, 0.9, {3.51, 4.22, 5.30, 3.51, 3.81, 4.16, 1.44, 1.59, 1.77, 1.16, 1.11, 1.06}},
    {true, 0.8, {3.65, 4.36, 5.42, 3.65, 3.99, 4.39, 1.58, 1.75, 1.94, 1.10, 1.04, 0.954}},
    {true, 0.7, {3.82, 4.54, 5.58, 3.82, 4.21, 4.67, 1.76, 1.95, 2.18, 1.05, 0.965, 0.852}},
    {true, 0.6, {4.06, 4.78, 5.80, 4.06, 4.50, 5.04, 2.01, 2.23, 2.50, 1.01, 0.892, 0.751}},
    {true, 0.5, {4.37, 5.10, 6.11, 4.37, 4.90, 5.56, 2.35, 2.62, 2.96, 0.958, 0.819, 0.650}},
    {true, 0.4, {4.84, 5.57, 6.57, 4.84, 5.48, 6.31, 2.88, 3.24, 3.70, 0.912, 0.747, 0.549}},
    {true, 0.3, {5.57, 6.34, 7.34, 5.57, 6.40, 7.51, 3.79, 4.32, 5.01, 0.868, 0.674, 0.446}},
    {true, 0.2, {6.96, 7.78, 8.82, 6.96, 8.14, 9.79, 5.72, 6.63, 7.89, 0.828, 0.601, 0.341}},
    {true, 0.1, {10.7, 11.7, 12.9, 10.7, 12.8, 16.0, 12.2, 14.6, 18.0, 0.795, 0.526, 0.228}},
};

// Node abscissae x = ln(a/b) and PCHIP slopes dC/dx, computed once.
class KalkerTable {
 public:
  KalkerTable() {
    for (int i = 0; i < kNodes; ++i) x_[i] = std::log(node_aspect(i));
    for (int s = 0; s < kSeries; ++s) {
      std::vector<double> x(x_.begin(), x_.end()), y(kNodes);
      for (int i = 0; i < kNodes; ++i) y[i] = kTable[i].c[s];
      const boost::math::interpolators::pchip<std::vector<double>> spline(std::move(x), std::move(y));
      for (int i = 0; i < kNodes; ++i) slope_[i][s] = spline.prime(x_[i]);
    }
  }

  // a/b of node i; the a > b rows are stored as b/a.
  static double node_aspect(int i) { return kTable[i].a_greater_b ? 1.0 / kTable[i].g : kTable[i].g; }

  double x_min() const { return x_[0]; }
  double x_max() const { return x_[kNodes - 1]; }

  // The 12 series at x = ln(a/b) (x_min <= x <= x_max): cubic Hermite on the
  // interval. The interval comes straight from the table's 0.1 steps in a/b
  // (a < b) or b/a (a > b), corrected by one where rounding puts it off.
  [[gnu::always_inline]] void evaluate(double a_over_b, double x, double out[kSeries]) const {
    int i = a_over_b <= 1.0 ? static_cast<int>(a_over_b * 10.0) - 1
                            : 9 + static_cast<int>((1.0 - 1.0 / a_over_b) * 10.0);
    i = std::clamp(i, 0, kNodes - 2);
    if (x < x_[i] && i > 0) --i;
    if (x > x_[i + 1] && i < kNodes - 2) ++i;
    const double h = x_[i + 1] - x_[i];
    const double t = (x - x_[i]) / h;
    const double t2 = t * t, t3 = t2 * t;
    const double h00 = 2.0 * t3 - 3.0 * t2 + 1.0;
    const double h10 = (t3 - 2.0 * t2 + t) * h;
    const double h01 = -2.0 * t3 + 3.0 * t2;
    const double h11 = (t3 - t2) * h;
    // Values and slopes of a node are contiguous over the 12 series (one
    // vector loop).
    const double* c0 = kTable[i].c;
    const double* c1 = kTable[i + 1].c;
    const double* m0 = slope_[i];
    const double* m1 = slope_[i + 1];
    for (int s = 0; s < kSeries; ++s) out[s] = h00 * c0[s] + h10 * m0[s] + h01 * c1[s] + h11 * m1[s];
  }

  static void node_values(int i, double out[kSeries]) {
    for (int s = 0; s < kSeries; ++s) out[s] = kTable[i].c[s];
  }

 private:
  std::array<double, kNodes> x_{};
  double slope_[kNodes][kSeries]{};  // PCHIP slope dC/dx of series s at node i: slope_[i][s]
};

const KalkerTable& table() {
  static const KalkerTable t;  // immutable after construction
  return t;
}

// 1/C quadratic in nu through nu = 0, 0.25, 0.5 (CONTACT, physics-reference.md
// sec. 2.4), for C11, C22, C23, C33 (three values each in v); the nodes nu =
// 0.25 and 0.5 are returned exactly. 1 / (w0/c0 + w1/c1 + w2/c2) with a
// single division per coefficient.
[[gnu::always_inline]] inline KalkerCoefficients combine(const double v[kSeries], double nu) {
  if (nu == 0.25) return {v[1], v[4], v[7], v[10]};
  if (nu == 0.5) return {v[2], v[5], v[8], v[11]};
  const double w0 = 8.0 * (nu - 0.25) * (nu - 0.5);
  const double w1 = -16.0 * nu * (nu - 0.5);
  const double w2 = 8.0 * nu * (nu - 0.25);
  const auto one = [&](const double* c) {
    return c[0] * c[1] * c[2] / (w0 * c[1] * c[2] + w1 * c[0] * c[2] + w2 * c[0] * c[1]);
  };
  return {one(v + 0), one(v + 3), one(v + 6), one(v + 9)};
}

// Kalker's asymptotes, a << b, g = a/b (physics-reference.md sec. 2.3).
KalkerCoefficients asymptote_a_small(double g, double nu) {
  return {kPi * kPi / (4.0 * (1.0 - nu)), kPi * kPi / 4.0,
          kPi * std::sqrt(g) / (3.0 * (1.0 - nu)) * (1.0 + nu * (std::log(16.0 / g) - 5.0)),
          kPi * kPi / (16.0 * (1.0 - nu) * g)};
}

// Kalker's asymptotes, a >> b, g = b/a; C33 has none (returned as NaN, not used).
KalkerCoefficients asymptote_a_large(double g, double nu) {
  const double L = std::log(16.0 / (g * g));
  const double c3 = 3.0 - std::log(4.0);
  const double d22 = (1.0 - nu) * L + 2.0 * nu;
  return {2.0 * kPi / (g * (L - 2.0 * nu)) * (1.0 + c3 / (L - 2.0 * nu)),
          2.0 * kPi / g * (1.0 + (1.0 - nu) * c3 / d22) / d22,
          2.0 * kPi / (3.0 * std::pow(g, 1.5) * ((1.0 - nu) * L - 2.0 + 4.0 * nu)),
          std::nan("")};
}

// C = C_asym(g) [1 + (r0 - 1) g / g_edge], r0 = C_table(edge) / C_asym(edge).
double blend(double asym_g, double asym_edge, double table_edge, double g) {
  const double r0 = table_edge / asym_edge;
  return asym_g * (1.0 + (r0 - 1.0) * g / kKalkerTableMinAspect);
}

}  // namespace

// One copy, without an AVX2 clone (target_clones, eacdef2): the clone ran fewer
// instructions, but the call is a chain of dependent operations (log, two
// divisions), and with the clone's indirect call, 32-byte stack alignment and
// 256-bit divide FASTSIM (Kalker) 5 x 5 took 5 ns longer a call.
KalkerCoefficients kalker_coefficients(double a_over_b, double nu) {
  if (!(std::isfinite(a_over_b) && a_over_b > 0.0)) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%g", a_over_b);
    throw InputError(std::string("Kalker coefficients: a/b expected a positive finite number (got ") + buf + ")");
  }
  if (!(std::isfinite(nu) && nu > 0.0 && nu <= 0.5)) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%g", nu);
    throw InputError(std::string("Kalker coefficients: Poisson's ratio nu expected a number in (0, 0.5] (got ") +
                     buf + ")");
  }
  const KalkerTable& t = table();
  const double x = std::log(a_over_b);
  double v[kSeries];
  if (x >= t.x_min() && x <= t.x_max()) {
    t.evaluate(a_over_b, x, v);
    return combine(v, nu);
  }
  if (x < t.x_min()) {  // a << b
    KalkerTable::node_values(0, v);
    const KalkerCoefficients edge = combine(v, nu);
    const KalkerCoefficients ae = asymptote_a_small(kKalkerTableMinAspect, nu);
    const KalkerCoefficients ag = asymptote_a_small(a_over_b, nu);
    const double g = a_over_b;
    return {blend(ag.C11, ae.C11, edge.C11, g), blend(ag.C22, ae.C22, edge.C22, g),
            blend(ag.C23, ae.C23, edge.C23, g), blend(ag.C33, ae.C33, edge.C33, g)};
  }
  // a >> b
  KalkerTable::node_values(kNodes - 1, v);
  const KalkerCoefficients edge = combine(v, nu);
  const double g = 1.0 / a_over_b;
  const KalkerCoefficients ae = asymptote_a_large(kKalkerTableMinAspect, nu);
  const KalkerCoefficients ag = asymptote_a_large(g, nu);
  return {blend(ag.C11, ae.C11, edge.C11, g), blend(ag.C22, ae.C22, edge.C22, g),
          blend(ag.C23, ae.C23, edge.C23, g), edge.C33};
}

}  // namespace railsim::contact
