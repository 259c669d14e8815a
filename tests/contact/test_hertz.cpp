// Hertz normal contact (contact/hertz.cpp) against closed forms, the classical
// m, n, r table, the worked vector of physics-reference.md sec. 1.6 and
// CONTACT's Hertz solutions (tests/data/reference/contact/hertz_normal_analytic.csv).
#include <catch2/catch.hpp>

#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/ellint_2.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include "contact/hertz.hpp"
#include "core/errors.hpp"
#include "results/csv_writer.hpp"
#include "test_support.hpp"

using namespace railsim::contact;
using railsim::InputError;

namespace {
constexpr double kPi = 3.14159265358979323846;
double rel(double x, double ref) { return std::abs(x - ref) / std::abs(ref); }
// Half a unit of the last printed digit of a table cell.
double half_ulp_printed(const std::string& cell) {
  const auto dot = cell.find('.');
  const int decimals = dot == std::string::npos ? 0 : static_cast<int>(cell.size() - dot - 1);
  return 0.5 * std::pow(10.0, -decimals) * (1.0 + 1e-9);
}
}  // namespace

TEST_CASE("sphere on a plane: closed form to 1e-9", "[hertz]") {
  const Material steel{210e9, 0.3, 0.3};
  const double R = 0.02, F = 1000.0;
  const double A = 1.0 / (2.0 * R);
  const auto p = hertz_from_load(A, A, F, steel);
  const double Es = steel.E / (2.0 * (1.0 - steel.nu * steel.nu));
  const double a = std::cbrt(3.0 * F * R / (4.0 * Es));
  CHECK(rel(p.a, a) < 1e-9);
  CHECK(rel(p.b, a) < 1e-9);
  CHECK(rel(p.p0, 3.0 * F / (2.0 * kPi * a * a)) < 1e-9);
  CHECK(rel(p.approach, a * a / R) < 1e-9);
  // Nearly circular (not the exact-circle branch) stays continuous.
  const auto q = hertz_from_load(A, A * (1.0 + 1e-9), F, steel);
  CHECK(rel(std::sqrt(q.a * q.b), a) < 1e-8);
}

TEST_CASE("elliptic integrals: parameter m = e^2 vs Boost's modulus k = e", "[hertz]") {
  for (double ratio : {0.9, 0.5, 0.1, 1e-3, 1e-6}) {
    const HertzShape s = hertz_shape(ratio);
    const double k = std::sqrt(1.0 - s.g * s.g);
    // The modulus form loses digits for k -> 1 (1 - k^2 rounds): 1e-12, 1e-9 there.
    const double tol = ratio >= 1e-3 ? 1e-12 : 1e-9;
    CHECK(rel(s.K, boost::math::ellint_1(k)) < tol);
    CHECK(rel(s.E, boost::math::ellint_2(k)) < tol);
    // Shape equation A/B = (K - E) / (E/(1-e^2) - K).
    CHECK(rel((s.K - s.E) / (s.E / (s.g * s.g) - s.K), ratio) < 1e-9);
  }
}

TEST_CASE("shape equation holds across the fast and the iterative paths", "[hertz]") {
  // B/A <= 1e4 takes the spline-start path, beyond it the safeguarded iteration;
  // both must satisfy A/B = (K - E) / (E/(1-e^2) - K) and join continuously.
  double last_g = 1.0;
  for (int i = 1; i <= 400; ++i) {
    const double ratio = std::pow(10.0, -9.5 * i / 400.0);
    const HertzShape s = hertz_shape(ratio);
    INFO("ratio " << ratio);
    const double mc = s.g * s.g;
    CHECK(rel((s.K - s.E) * mc / (s.E - mc * s.K), ratio) < 1e-10);
    CHECK(s.g < last_g);
    last_g = s.g;
  }
  const HertzShape in = hertz_shape(1e-4 * (1 + 1e-12)), out = hertz_shape(1e-4 * (1 - 1e-12));
  CHECK(rel(in.g, out.g) < 1e-11);
  CHECK(rel(in.K, out.K) < 1e-11);
  CHECK(rel(in.E, out.E) < 1e-11);
}

TEST_CASE("fast shape table equals the exact root-found shape to 1e-14", "[hertz]") {
  // hertz_shape reads g, K, E from Chebyshev pieces built from hertz_shape_exact
  // (Newton on the Carlson form); 4000 log-spaced ratios across the table
  // (B/A in [1, 1e4], many between the interpolation nodes) plus the piece edges.
  double worst = 0.0;
  auto compare = [&](double ratio) {
    const HertzShape f = hertz_shape(ratio), x = hertz_shape_exact(ratio);
    worst = std::max({worst, rel(f.g, x.g), rel(f.K, x.K), rel(f.E, x.E)});
  };
  for (int i = 0; i <= 4000; ++i) compare(std::pow(10.0, -4.0 * (i + 0.37) / 4000.5));
  for (int i = 1; i < 64; ++i) compare(std::exp(-std::log(1e4) * i / 64.0));
  INFO("worst relative difference " << worst);
  CHECK(worst < 1e-14);
  // The exact solution satisfies the shape equation to rounding.
  for (double ratio : {0.99, 0.5, 1e-2, 1e-4, 1e-7}) {
    const HertzShape s = hertz_shape_exact(ratio);
    const double mc = s.g * s.g;
    CHECK(rel((s.K - s.E) * mc / (s.E - mc * s.K), ratio) < 1e-12);
  }
}

TEST_CASE("classical m n r table (physics-reference 1.3) to printed precision", "[hertz]") {
  const auto t = railsim::results::read_csv(railsim::test::data_path("hertz_mnr_table.csv"));
  REQUIRE(t.rows.size() == 20);
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    const double theta = t.number(i, "theta_deg") * kPi / 180.0;
    const double B_over_A = (1.0 + std::cos(theta)) / (1.0 - std::cos(theta));
    const auto c = hertz_coefficients(1.0, B_over_A);  // A <= B: a is the major axis
    INFO("theta = " << t.rows[i][0]);
    CHECK(std::abs(c.m - t.number(i, "m")) <= half_ulp_printed(t.rows[i][t.column("m")]));
    CHECK(std::abs(c.n - t.number(i, "n")) <= half_ulp_printed(t.rows[i][t.column("n")]));
    CHECK(std::abs(c.r - t.number(i, "r")) <= half_ulp_printed(t.rows[i][t.column("r")]));
    // A > B: the roles swap, m stays with the semi-axis along x.
    const auto s = hertz_coefficients(B_over_A, 1.0);
    CHECK(s.m == Approx(c.n).epsilon(1e-12));
    CHECK(s.n == Approx(c.m).epsilon(1e-12));
  }
}

TEST_CASE("worked vector of physics-reference 1.6", "[hertz]") {
  const Material steel{210e9, 0.3, 0.3};
  const double A = 1.0 / (2.0 * 0.46), B = 1.0 / (2.0 * 0.30);
  const auto p = hertz_from_load(A, B, 100e3, steel);
  CHECK(std::abs(p.a * 1e3 - 7.1617) <= 0.5e-4);
  CHECK(std::abs(p.b * 1e3 - 5.3872) <= 0.5e-4);
  CHECK(std::abs(p.a / p.b - 1.3294) <= 0.5e-4);
  CHECK(std::abs(p.p0 / 1e6 - 1237.6) <= 0.05);
  CHECK(std::abs(p.approach * 1e6 - 104.12) <= 0.005);
  const auto back = hertz_from_approach(A, B, p.approach, steel);
  CHECK(std::abs(back.Fz - 100000.0) <= 0.05);
}

TEST_CASE("CONTACT Hertz references to 1 % (reached: 1e-6)", "[hertz][contact_ref]") {
  const auto t = railsim::results::read_csv(railsim::test::reference_path("contact/hertz_normal_analytic.csv"));
  REQUIRE(t.rows.size() >= 7);
  double worst = 0.0;
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    const Material m{t.number(i, "E_MPa") * 1e6, t.number(i, "nu"), 0.3};
    const double A = t.number(i, "A1_per_mm") * 1e3, B = t.number(i, "B1_per_mm") * 1e3;
    const auto p = hertz_from_load(A, B, t.number(i, "FN_N"), m);
    INFO(t.rows[i][0]);
    const double ea = rel(p.a * 1e3, t.number(i, "a_mm"));
    const double eb = rel(p.b * 1e3, t.number(i, "b_mm"));
    const double ep = rel(p.p0 / 1e6, t.number(i, "pmax_MPa"));
    const double ed = rel(p.approach * 1e3, t.number(i, "approach_mm"));
    CHECK(ea < 0.01);
    CHECK(eb < 0.01);
    CHECK(ep < 0.01);
    // Much tighter than the acceptance: the references carry 9 digits.
    CHECK(ea < 1e-6);
    CHECK(eb < 1e-6);
    CHECK(ep < 1e-6);
    CHECK(ed < 1e-6);
    worst = std::max({worst, ea, eb, ep, ed});
  }
  WARN("largest relative deviation from CONTACT: " << worst);
}

TEST_CASE("approach round trip and semi-axes inverse", "[hertz]") {
  const Material steel{210e9, 0.28, 0.3};
  for (double ratio : {1.0, 0.8, 0.3, 1e-2, 1e-4, 1e-8}) {
    for (bool swap : {false, true}) {
      const double A = swap ? 2.0 : 2.0 * ratio, B = swap ? 2.0 * ratio : 2.0;
      const auto p = hertz_from_load(A, B, 75e3, steel);
      INFO("ratio " << ratio << " swap " << swap);
      CHECK(rel(hertz_from_approach(A, B, p.approach, steel).Fz, 75e3) < 1e-10);
      const auto c = hertz_from_shape(A, B, hertz_shape(std::min(A, B) / std::max(A, B)), 75e3, steel);
      CHECK(c.a == p.a);
      CHECK(c.b == p.b);
      CHECK(c.approach == p.approach);
      CHECK(((p.a >= p.b) == (A <= B)));
      const auto q = hertz_from_semi_axes(p.a, p.b, 75e3, steel);
      CHECK(rel(q.A, A) < 1e-9);
      CHECK(rel(q.B, B) < 1e-9);
      CHECK(rel(q.approach, p.approach) < 1e-9);
    }
  }
}

TEST_CASE("Hertz refuses invalid input with the allowed range", "[hertz]") {
  const Material steel{210e9, 0.28, 0.3};
  CHECK_THROWS_WITH(hertz_from_load(-1.0, 1.0, 1e3, steel), Catch::Contains("curvature A") && Catch::Contains("positive"));
  CHECK_THROWS_AS(hertz_from_load(1.0, 0.0, 1e3, steel), InputError);
  CHECK_THROWS_WITH(hertz_from_load(1.0, 1.0, -3.0, steel), Catch::Contains("normal load Fz") && Catch::Contains("(got -3)"));
  CHECK_THROWS_AS(hertz_from_load(1.0, std::nan(""), 1e3, steel), InputError);
  CHECK_THROWS_AS(hertz_from_load(1.0, INFINITY, 1e3, steel), InputError);
  CHECK_THROWS_WITH(hertz_from_load(1.0, 1.0, 1e3, Material{210e9, 0.6, 0.3}), Catch::Contains("(0, 0.5]"));
  CHECK_THROWS_AS(hertz_from_approach(1.0, 1.0, 0.0, steel), InputError);
  CHECK_THROWS_WITH(hertz_from_load(1e-12, 1.0, 1e3, steel), Catch::Contains("[1e-10, 1]"));
}
