// Static / quasi-static equilibrium at the start of a run; see equilibrium.hpp.
#include "engine/equilibrium.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <vector>

#include "core/errors.hpp"
#include "engine/data.hpp"
#include "engine/system.hpp"

namespace railsim::engine {

EquilibriumResult static_equilibrium(const Model& model, double t0, int max_iterations, double tolerance) {
  EquilibriumResult r;
  const int n = model.n_states;
  // Unknowns: every state that is not a velocity; equations: the rows of the
  // velocities (accelerations) and of the other non-position states.
  std::vector<int> unknown, equation;
  std::vector<char> is_velocity(std::size_t(n), 0);
  for (const auto& b : model.bodies)
    for (int k = 0; k < kNumDof; ++k)
      if (b.v_index[k] >= 0) is_velocity[std::size_t(b.v_index[k])] = 1;
  for (const auto& b : model.bodies)
    for (int k = 0; k < kNumDof; ++k)
      if (b.q_index[k] >= 0) {
        unknown.push_back(b.q_index[k]);
        equation.push_back(b.v_index[k]);
      }
  for (int i = 0; i < n; ++i) {
    bool listed = is_velocity[std::size_t(i)] != 0;
    for (int u : unknown) listed = listed || u == i;
    if (!listed) {  // spin perturbations, damper elongations: their own rows
      unknown.push_back(i);
      equation.push_back(i);
    }
  }
  const int m = static_cast<int>(unknown.size());
  Data d(model);
  ModelOde ode(model, d);
  r.x = Eigen::VectorXd::Zero(n);
  Eigen::VectorXd f(n);
  std::vector<double> Jd(std::size_t(n) * std::size_t(n));
  auto residual = [&](const Eigen::VectorXd& x, Eigen::VectorXd& g) {
    if (!ode.rhs(t0, x.data(), f.data())) throw NumericalError("static equilibrium: " + ode.failure_message());
    g.resize(m);
    for (int k = 0; k < m; ++k) g[k] = f[equation[std::size_t(k)]];
    return g.cwiseAbs().maxCoeff();
  };
  Eigen::VectorXd g;
  double res = residual(r.x, g);
  for (int it = 0; it < max_iterations && res > tolerance; ++it) {
    if (!ode.jacobian(t0, r.x.data(), f.data(), Jd.data()))
      throw NumericalError("static equilibrium: " + ode.failure_message());
    Eigen::MatrixXd A(m, m);
    for (int a = 0; a < m; ++a)
      for (int b = 0; b < m; ++b)
        A(a, b) = Jd[std::size_t(equation[std::size_t(a)]) + std::size_t(unknown[std::size_t(b)]) * std::size_t(n)];
    const Eigen::VectorXd step = A.fullPivLu().solve(-g);
    // Damped Newton: halve until the residual falls.
    double lambda = 1.0;
    Eigen::VectorXd x = r.x;
    double next = res;
    for (int ls = 0; ls < 20; ++ls) {
      x = r.x;
      for (int k = 0; k < m; ++k) x[unknown[std::size_t(k)]] += lambda * step[k];
      Eigen::VectorXd gg;
      try {
        next = residual(x, gg);
      } catch (const NumericalError&) {
        next = INFINITY;
      }
      if (next < res) {
        g = gg;
        break;
      }
      lambda *= 0.5;
    }
    if (!(next < res)) {
      r.message = "no descent (residual " + std::to_string(res) + ")";
      break;
    }
    r.x = x;
    res = next;
    r.iterations = it + 1;
  }
  r.residual = res;
  r.converged = res <= tolerance;
  if (!r.converged && r.message.empty()) {
    char buf[128];
    std::snprintf(buf, sizeof buf, "residual %.3g after %d iterations", res, r.iterations);
    r.message = buf;
  }
  return r;
}

}  // namespace railsim::engine
