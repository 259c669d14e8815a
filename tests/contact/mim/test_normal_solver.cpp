// Tests of contact/mim/normal_solver.cpp: Hertz (sphere, ellipses a/b 0.2..5)
// against the closed form and CONTACT's boundary-element results, Love's cone,
// and the dense active-set cross-check.
#include <catch2/catch.hpp>

#include <Eigen/Dense>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "contact/mim/grid.hpp"
#include "core/errors.hpp"
#include "contact/mim/normal_solver.hpp"
#include "results/csv_writer.hpp"
#include "test_support.hpp"

using namespace railsim::contact::mim;

namespace {

constexpr unsigned kEstimate = 64u;  // FFTW_ESTIMATE

// Steel as in the CONTACT reference: E = 210 GPa, nu = 0.28.
ElasticPair steel() { return ElasticPair{210e9 / (2 * 1.28), 0.28, 0.0}; }

// Hertz semi-axes and peak pressure estimated from a pressure field by a
// least-squares fit of p^2 = c0 - cx x^2 - cy y^2 over the loaded elements
// (the Hertz pressure squared is exactly this quadric).
struct FieldFit {
  double a, b, p0;
};
FieldFit fit_hertz(const ContactGrid& g, const std::vector<double>& p) {
  Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
  Eigen::Vector3d r = Eigen::Vector3d::Zero();
  for (int j = 0; j < g.my; ++j)
    for (int i = 0; i < g.mx; ++i) {
      const double v = p[g.index(i, j)];
      if (v <= 0) continue;
      Eigen::Vector3d f(1.0, -g.x(i) * g.x(i), -g.y(j) * g.y(j));
      M += f * f.transpose();
      r += f * v * v;
    }
  const Eigen::Vector3d c = M.ldlt().solve(r);
  return {std::sqrt(c(0) / c(1)), std::sqrt(c(0) / c(2)), std::sqrt(c(0))};
}

}  // namespace

TEST_CASE("Hertz sphere and ellipses on a 60x60 grid: a, b, p0, approach within 1 %", "[mim][normal]") {
  const auto tab = railsim::results::read_csv(railsim::test::reference_path("contact/hertz_normal_analytic.csv"));
  const ElasticPair m = steel();
  for (std::size_t row = 0; row < tab.rows.size(); ++row) {
    const std::string id = tab.rows[row][tab.column("case_id")];
    const double A = tab.number(row, "A1_per_mm") * 1e3, B = tab.number(row, "B1_per_mm") * 1e3;
    const double F = tab.number(row, "FN_N");
    const double a = tab.number(row, "a_mm") * 1e-3, b = tab.number(row, "b_mm") * 1e-3;
    const double p0 = tab.number(row, "pmax_MPa") * 1e6, delta = tab.number(row, "approach_mm") * 1e-3;
    const double s = 60.0 / 56.0;  // 60 x 60 elements, two unused rows each side
    const ContactGrid g = centred_grid(60, 60, s * a, s * b);
    const auto h = quadratic_gap(g, A, B);
    InfluenceOperator op(g, m, 0.0, kEstimate);
    NormalSolver solver(g.size());
    std::vector<double> p(g.size());
    const NormalResult res = solver.solve_load(op, h.data(), F, p.data());
    const FieldFit fit = fit_hertz(g, p);
    INFO(id << ": a " << fit.a / a - 1 << " b " << fit.b / b - 1 << " p0 " << fit.p0 / p0 - 1
            << " approach " << res.approach / delta - 1 << " iterations " << res.iterations
            << " residual " << res.residual);
    CHECK(res.converged);
    CHECK(res.residual < 1e-5);
    CHECK(res.load == Approx(F).epsilon(1e-12));
    CHECK(fit.a == Approx(a).epsilon(0.01));
    CHECK(fit.b == Approx(b).epsilon(0.01));
    CHECK(fit.p0 == Approx(p0).epsilon(0.01));
    CHECK(res.pmax == Approx(p0).epsilon(0.01));
    CHECK(res.approach == Approx(delta).epsilon(0.01));
    // The loaded area counts whole elements: within 2 % of pi a b.
    CHECK(res.n_contact * g.element_area() == Approx(std::numbers::pi * a * b).epsilon(0.02));
  }
}

TEST_CASE("same discretisation as CONTACT gives CONTACT's numerical Hertz results", "[mim][normal]") {
  const auto ana = railsim::results::read_csv(railsim::test::reference_path("contact/hertz_normal_analytic.csv"));
  const auto bem = railsim::results::read_csv(railsim::test::reference_path("contact/hertz_normal_bem.csv"));
  const ElasticPair m = steel();
  int compared = 0;
  for (std::size_t row = 0; row < bem.rows.size(); ++row) {
    const int N = static_cast<int>(bem.number(row, "N_minor"));
    if (N > 40) continue;  // keep the test fast
    const std::string id = bem.rows[row][bem.column("case_id")];
    std::size_t arow = 0;
    while (ana.rows[arow][ana.column("case_id")] != id) ++arow;
    const double A = ana.number(arow, "A1_per_mm") * 1e3, B = ana.number(arow, "B1_per_mm") * 1e3;
    const ContactGrid g = grid_for_patch(ana.number(arow, "a_mm") * 1e-3, ana.number(arow, "b_mm") * 1e-3, N);
    REQUIRE(g.mx == static_cast<int>(bem.number(row, "mx")));
    REQUIRE(g.my == static_cast<int>(bem.number(row, "my")));
    REQUIRE(g.dx == Approx(bem.number(row, "dx_mm") * 1e-3).epsilon(1e-7));
    const auto h = quadratic_gap(g, A, B);
    InfluenceOperator op(g, m, 0.0, kEstimate);
    NormalSolver solver(g.size());
    std::vector<double> p(g.size());
    const bool force = bem.rows[row][bem.column("prescribed")] == "force";
    const NormalResult res = force ? solver.solve_load(op, h.data(), bem.number(row, "FN_N"), p.data())
                                   : solver.solve_approach(op, h.data(), bem.number(row, "approach_mm") * 1e-3, p.data());
    INFO(id << " N=" << N << (force ? " force" : " approach"));
    CHECK(res.converged);
    CHECK(res.approach == Approx(bem.number(row, "approach_mm") * 1e-3).epsilon(2e-6));
    CHECK(res.load == Approx(bem.number(row, "FN_N")).epsilon(2e-6));
    CHECK(res.pmax == Approx(bem.number(row, "pmax_MPa") * 1e6).epsilon(2e-6));
    CHECK(res.n_contact == static_cast<int>(bem.number(row, "n_contact_el")));
    ++compared;
  }
  CHECK(compared >= 20);
}

TEST_CASE("Love's cone: contact radius and load within 1 %", "[mim][normal]") {
  // Rigid-cone-like gap h = k r on two steel half-spaces: a = 2 delta/(pi k),
  // F = (pi/2) a^2 E* k (Love 1939; Johnson 1985, sec. 5.2).
  const ElasticPair m = steel();
  const double Estar = m.G / (1.0 - m.nu);
  const double k = 0.01, delta = 10e-6;
  const double a = 2.0 * delta / (std::numbers::pi * k);
  const ContactGrid g = centred_grid(64, 64, 1.1 * a, 1.1 * a);
  std::vector<double> h(g.size());
  for (int j = 0; j < g.my; ++j)
    for (int i = 0; i < g.mx; ++i) h[g.index(i, j)] = k * std::hypot(g.x(i), g.y(j));
  InfluenceOperator op(g, m, 0.0, kEstimate);
  NormalSolver solver(g.size());
  std::vector<double> p(g.size());
  const NormalResult res = solver.solve_approach(op, h.data(), delta, p.data());
  const double a_num = std::sqrt(res.n_contact * g.element_area() / std::numbers::pi);
  const double F = 0.5 * std::numbers::pi * a * a * Estar * k;
  INFO("radius error " << a_num / a - 1 << ", load error " << res.load / F - 1);
  CHECK(res.converged);
  CHECK(a_num == Approx(a).epsilon(0.01));
  CHECK(res.load == Approx(F).epsilon(0.01));
  // Given the load instead, the approach follows within 1 %.
  const NormalResult r2 = solver.solve_load(op, h.data(), F, p.data());
  CHECK(r2.approach == Approx(delta).epsilon(0.01));
}

TEST_CASE("iterative and dense direct normal solvers agree", "[mim][normal]") {
  const ElasticPair m = steel();
  const ContactGrid g = centred_grid(18, 14, 1.2e-3, 0.8e-3);
  // A non-Hertzian gap: two lobes.
  std::vector<double> h(g.size());
  for (int j = 0; j < g.my; ++j)
    for (int i = 0; i < g.mx; ++i) {
      const double x = g.x(i), y = g.y(j);
      h[g.index(i, j)] = 2.0 * x * x + 40.0 * std::pow(std::abs(y) - 0.35e-3, 2);
    }
  const double delta = 5e-6;
  std::vector<double> pd;
  const NormalResult rd = solve_normal_dense(g, m, h, delta, pd);
  InfluenceOperator op(g, m, 0.0, kEstimate);
  NormalSolver solver(g.size());
  std::vector<double> p(g.size());
  const NormalResult ri = solver.solve_approach(op, h.data(), delta, p.data());
  REQUIRE(rd.converged);
  REQUIRE(ri.converged);
  CHECK(ri.n_contact == rd.n_contact);
  CHECK(ri.load == Approx(rd.load).epsilon(1e-7));
  double err = 0;
  for (int q = 0; q < g.size(); ++q) err = std::max(err, std::abs(p[q] - pd[q]));
  CHECK(err < 1e-6 * rd.pmax);
}

TEST_CASE("normal solver rejects bad input", "[mim][normal]") {
  const ContactGrid g = centred_grid(8, 8, 1e-3, 1e-3);
  InfluenceOperator op(g, steel(), 0.0, kEstimate);
  NormalSolver solver(g.size());
  std::vector<double> h(g.size(), 0.0), p(g.size());
  CHECK_THROWS_AS(solver.solve_load(op, h.data(), -1.0, p.data()), railsim::InputError);
  CHECK_THROWS_AS(solver.solve_load(op, h.data(), std::nan(""), p.data()), railsim::InputError);
  CHECK_THROWS_AS(grid_for_patch(1e-3, -1e-3, 20), railsim::InputError);
  CHECK_THROWS_AS(grid_for_patch(1e-3, 1e-3, 2), railsim::InputError);
  CHECK_THROWS_AS(centred_grid(0, 5, 1e-3, 1e-3), railsim::InputError);
}
