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
  std::vector<double> weight;  // residual rows as generalised forces [N, N m]: bodies of any mass count alike
  for (const auto& b : model.bodies)
    for (int k = 0; k < kNumDof; ++k)
      if (b.q_index[k] >= 0) {
        unknown.push_back(b.q_index[k]);
        equation.push_back(b.v_index[k]);
        weight.push_back(b.generalised_mass(k));
      }
  for (int i = 0; i < n; ++i) {
    bool listed = is_velocity[std::size_t(i)] != 0;
    for (int u : unknown) listed = listed || u == i;
    if (!listed) {  // spin perturbations, damper elongations: their own rows
      unknown.push_back(i);
      equation.push_back(i);
      weight.push_back(1.0);
    }
  }
  const int m = static_cast<int>(unknown.size());
  // Trust region on the wheelsets' lateral shift and yaw (the contact forces
  // change over a fraction of a millimetre near the flange): a Newton step is
  // scaled so that none moves by more than 1 mm or 2 mrad.
  std::vector<double> limit(std::size_t(m), INFINITY);
  for (const auto& w : model.wheelsets) {
    const auto& b = model.bodies[std::size_t(w.body)];
    for (int k = 0; k < m; ++k) {
      if (unknown[std::size_t(k)] == b.q_index[kLat]) limit[std::size_t(k)] = 1e-3;
      if (unknown[std::size_t(k)] == b.q_index[kYaw]) limit[std::size_t(k)] = 2e-3;
    }
  }
  Data d(model);
  ModelOde ode(model, d);
  r.x = Eigen::VectorXd::Zero(n);
  Eigen::VectorXd f(n);
  std::vector<double> Jd(std::size_t(n) * std::size_t(n));
  double last_max = 0.0;  // max |acceleration| of the last evaluation
  auto residual = [&](const Eigen::VectorXd& x, Eigen::VectorXd& g) {
    if (!ode.rhs(t0, x.data(), f.data())) throw NumericalError("static equilibrium: " + ode.failure_message());
    g.resize(m);
    double merit = 0.0;
    for (int k = 0; k < m; ++k) {
      g[k] = f[equation[std::size_t(k)]];
      merit += (weight[std::size_t(k)] * g[k]) * (weight[std::size_t(k)] * g[k]);
    }
    last_max = g.cwiseAbs().maxCoeff();
    return std::sqrt(merit);
  };
  Eigen::VectorXd g;
  double res = residual(r.x, g);  // merit: norm of the generalised forces
  double acc = last_max;          // convergence: max |acceleration|
  for (int it = 0; it < max_iterations && acc > tolerance; ++it) {
    // f holds the model at r.x: the last evaluation was the accepted one
    // (the start, or the trial the line search kept).
    if (!ode.jacobian(t0, r.x.data(), f.data(), Jd.data())) {
      r.message = "the Jacobian failed after " + std::to_string(it) + " iterations (largest acceleration " +
                  std::to_string(acc) + "): " + ode.failure_message();
      break;
    }
    Eigen::MatrixXd A(m, m);
    for (int a = 0; a < m; ++a)
      for (int b = 0; b < m; ++b)
        A(a, b) = Jd[std::size_t(equation[std::size_t(a)]) + std::size_t(unknown[std::size_t(b)]) * std::size_t(n)];
    Eigen::VectorXd step = A.fullPivLu().solve(-g);
    double scale = 1.0;
    for (int k = 0; k < m; ++k)
      if (std::abs(step[k]) * scale > limit[std::size_t(k)]) scale = limit[std::size_t(k)] / std::abs(step[k]);
    step *= scale;
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
        acc = last_max;
        break;
      }
      lambda *= 0.5;
    }
    if (!(next < res)) {
      r.message = "no descent (largest acceleration " + std::to_string(acc) + ")";
      break;
    }
    r.x = x;
    res = next;
    r.iterations = it + 1;
  }
  r.residual = acc;
  r.converged = acc <= tolerance;
  if (!r.converged && r.message.empty()) {
    char buf[128];
    std::snprintf(buf, sizeof buf, "largest acceleration %.3g after %d iterations", acc, r.iterations);
    r.message = buf;
  }
  return r;
}

}  // namespace railsim::engine
