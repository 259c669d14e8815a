// Static / quasi-static equilibrium at the start of a run: Newton, Newton with
// the wheelsets held, pseudo-transient continuation; see equilibrium.hpp.
#include "engine/equilibrium.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "core/errors.hpp"
#include "engine/data.hpp"
#include "engine/system.hpp"

namespace railsim::engine {
namespace {

// Trust region on the wheelsets' lateral shift and yaw (the contact forces
// change over a fraction of a millimetre near the flange) [m, rad].
constexpr double kShiftLimit = 1e-3;
constexpr double kYawLimit = 2e-3;
// Pseudo-transient continuation: first pseudo-time step, its bounds and the
// time scale that turns a velocity residual into a force (m v / tau) [s].
constexpr double kPtcFirstStep = 1e-3;
constexpr double kPtcMinStep = 1e-7;
constexpr double kPtcMaxStep = 1e8;
constexpr double kPtcVelocityScale = 0.1;
// The pseudo-transient stage of static_equilibrium: at most this many steps,
// handing over to Newton at this largest acceleration [m/s^2, rad/s^2].
constexpr int kPseudoTransientSteps = 400;
constexpr double kPseudoTransientSwitch = 1e-4;

// The unknowns and equations of the equilibrium (see the header).
struct Problem {
  int n = 0, m = 0;
  std::vector<int> unknown, equation;  // m of each: state indices
  std::vector<double> weight;          // residual rows as generalised forces [N, N m]
  std::vector<double> limit;           // per unknown: largest move per step [m, rad] (inf: none)
  std::vector<double> state_weight;    // all n rows of x' = f: force scale of each row (pseudo-transient merit)
  std::vector<double> state_limit;     // all n states: largest move per step
  std::vector<int> position;           // the bodies' position states (their rows of f are the velocities)
};

// hold_wheelsets: the wheelsets' states (and spin perturbations) are held
// where they are; only the other bodies and the dampers are unknowns.
Problem make_problem(const Model& model, bool hold_wheelsets = false) {
  Problem p;
  p.n = model.n_states;
  // Unknowns: every state that is not a velocity; equations: the rows of the
  // velocities (accelerations) and of the other non-position states.
  std::vector<char> is_velocity(std::size_t(p.n), 0);
  for (const auto& b : model.bodies)
    for (int k = 0; k < kNumDof; ++k)
      if (b.v_index[k] >= 0) is_velocity[std::size_t(b.v_index[k])] = 1;
  p.state_weight.assign(std::size_t(p.n), 1.0);
  std::vector<char> held(std::size_t(p.n), 0);
  for (const auto& b : model.bodies)
    for (int k = 0; k < kNumDof; ++k)
      if (b.q_index[k] >= 0) {
        if (hold_wheelsets && b.wheelset >= 0) {
          held[std::size_t(b.q_index[k])] = 1;
          continue;
        }
        p.unknown.push_back(b.q_index[k]);
        p.equation.push_back(b.v_index[k]);
        p.position.push_back(b.q_index[k]);
        p.weight.push_back(b.generalised_mass(k));
        p.state_weight[std::size_t(b.v_index[k])] = b.generalised_mass(k);
        p.state_weight[std::size_t(b.q_index[k])] = b.generalised_mass(k) / kPtcVelocityScale;
      }
  // The flexible track under each wheelset (wheel_rail/track_flexibility.hpp):
  // positions with the rows of their rates, like the bodies; held with the
  // wheelsets.
  const TrackFlexibility& tf = model.track_flexibility;
  for (const auto& w : model.wheelsets) {
    const auto track = w.track_states();
    for (std::size_t k = 0; k < track.size(); ++k) {
      const int q = track[k];
      if (q < 0) continue;
      const double mass = k == 0 ? tf.lateral.mass : tf.vertical.mass;
      const std::size_t qi = std::size_t(q), vi = std::size_t(q) + 1;
      is_velocity[vi] = 1;
      if (hold_wheelsets) {
        held[qi] = 1;
        continue;
      }
      p.unknown.push_back(q);
      p.equation.push_back(q + 1);
      p.position.push_back(q);
      p.weight.push_back(mass);
      p.state_weight[vi] = mass;
      p.state_weight[qi] = mass / kPtcVelocityScale;
    }
  }
  for (int i = 0; i < p.n; ++i) {
    bool listed = is_velocity[std::size_t(i)] != 0;
    for (int u : p.unknown) listed = listed || u == i;
    if (hold_wheelsets)
      for (const auto& w : model.wheelsets) listed = listed || w.beta_state == i;
    if (!listed && !held[std::size_t(i)]) {  // spin perturbations, damper elongations: their own rows
      p.unknown.push_back(i);
      p.equation.push_back(i);
      p.weight.push_back(1.0);
    }
  }
  p.m = static_cast<int>(p.unknown.size());
  p.limit.assign(std::size_t(p.m), INFINITY);
  p.state_limit.assign(std::size_t(p.n), INFINITY);
  for (const auto& w : model.wheelsets) {
    const auto& b = model.bodies[std::size_t(w.body)];
    for (int k = 0; k < p.m; ++k) {
      if (p.unknown[std::size_t(k)] == b.q_index[kLat]) p.limit[std::size_t(k)] = kShiftLimit;
      if (p.unknown[std::size_t(k)] == b.q_index[kYaw]) p.limit[std::size_t(k)] = kYawLimit;
    }
    if (b.q_index[kLat] >= 0) p.state_limit[std::size_t(b.q_index[kLat])] = kShiftLimit;
    if (b.q_index[kYaw] >= 0) p.state_limit[std::size_t(b.q_index[kYaw])] = kYawLimit;
  }
  return p;
}

// Largest |f| over the equation rows (accelerations, spin and damper rates).
double largest_acceleration(const Problem& p, const Eigen::VectorXd& f) {
  double a = 0.0;
  for (int k = 0; k < p.m; ++k) a = std::max(a, std::abs(f[p.equation[std::size_t(k)]]));
  return a;
}

void finish(EquilibriumResult& r, double tolerance) {
  r.converged = r.residual <= tolerance;
  if (!r.converged && r.message.empty()) {
    char buf[128];
    std::snprintf(buf, sizeof buf, "largest acceleration %.3g after %d iterations", r.residual, r.iterations);
    r.message = buf;
  }
}

}  // namespace

EquilibriumResult newton_equilibrium(const Model& model, const Eigen::VectorXd& start, double t0, int max_iterations,
                                     double tolerance, bool hold_wheelsets) {
  EquilibriumResult r;
  const Problem p = make_problem(model, hold_wheelsets);
  const int n = p.n, m = p.m;
  Data d(model);
  d.warm_start = false;  // an equilibrium of the state alone, not of the evaluations before (Data::warm_start)
  ModelOde ode(model, d);
  r.x = start;
  for (const auto& b : model.bodies)  // at rest
    for (int k = 0; k < kNumDof; ++k)
      if (b.v_index[k] >= 0) r.x[b.v_index[k]] = 0.0;
  for (const auto& w : model.wheelsets)  // the flexible track too
    for (int q : w.track_states())
      if (q >= 0) r.x[q + 1] = 0.0;
  Eigen::VectorXd f(n);
  std::vector<double> Jd(std::size_t(n) * std::size_t(n));
  double last_max = 0.0;  // max |acceleration| of the last evaluation
  auto residual = [&](const Eigen::VectorXd& x, Eigen::VectorXd& g) {
    if (!ode.rhs(t0, x.data(), f.data())) throw NumericalError("static equilibrium: " + ode.failure_message());
    g.resize(m);
    double merit = 0.0;
    for (int k = 0; k < m; ++k) {
      g[k] = f[p.equation[std::size_t(k)]];
      merit += (p.weight[std::size_t(k)] * g[k]) * (p.weight[std::size_t(k)] * g[k]);
    }
    last_max = m > 0 ? g.cwiseAbs().maxCoeff() : 0.0;  // no unknowns (a wheelset held alone): nothing to balance
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
        A(a, b) = Jd[std::size_t(p.equation[std::size_t(a)]) +
                     std::size_t(p.unknown[std::size_t(b)]) * std::size_t(n)];
    Eigen::VectorXd step = A.fullPivLu().solve(-g);
    double scale = 1.0;
    for (int k = 0; k < m; ++k)
      if (std::abs(step[k]) * scale > p.limit[std::size_t(k)]) scale = p.limit[std::size_t(k)] / std::abs(step[k]);
    step *= scale;
    // Damped Newton: halve until the residual falls.
    double lambda = 1.0;
    Eigen::VectorXd x = r.x;
    double next = res;
    for (int ls = 0; ls < 20; ++ls) {
      x = r.x;
      for (int k = 0; k < m; ++k) x[p.unknown[std::size_t(k)]] += lambda * step[k];
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
  finish(r, tolerance);
  return r;
}

EquilibriumResult pseudo_transient_equilibrium(const Model& model, const Eigen::VectorXd& start, double t0,
                                               int max_steps, double tolerance) {
  EquilibriumResult r;
  const Problem p = make_problem(model);
  const int n = p.n;
  Data d(model);
  d.warm_start = false;  // as newton_equilibrium
  ModelOde ode(model, d);
  r.x = start;
  Eigen::VectorXd f(n), f_next(n), x_next(n);
  auto merit = [&](const Eigen::VectorXd& ff) {  // norm of the generalised forces and momenta / tau
    double s = 0.0;
    for (int i = 0; i < n; ++i) s += (p.state_weight[std::size_t(i)] * ff[i]) * (p.state_weight[std::size_t(i)] * ff[i]);
    return std::sqrt(s);
  };
  // Converged: every acceleration at the tolerance and every body at rest
  // (velocity below tolerance x 1 s).
  auto settled = [&](const Eigen::VectorXd& ff) {
    double v = 0.0;
    for (int q : p.position) v = std::max(v, std::abs(ff[q]));
    return std::max(largest_acceleration(p, ff), v);
  };
  if (!ode.rhs(t0, r.x.data(), f.data()))
    throw NumericalError("static equilibrium (pseudo-transient): " + ode.failure_message());
  double res = merit(f), dt = kPtcFirstStep;
  r.residual = settled(f);
  std::vector<double> Jd(std::size_t(n) * std::size_t(n));
  Eigen::MatrixXd A(n, n);
  int rejected = 0;
  for (int it = 0; it < max_steps && r.residual > tolerance; ++it) {
    if (!ode.jacobian(t0, r.x.data(), f.data(), Jd.data())) {
      r.message = "the Jacobian failed after " + std::to_string(it) + " pseudo-time steps: " + ode.failure_message();
      break;
    }
    // Linearly implicit Euler step of x' = f(t0, x): (I/dt - J) dx = f.
    bool accepted = false;
    while (!accepted && dt >= kPtcMinStep) {
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) A(i, j) = -Jd[std::size_t(i) + std::size_t(j) * std::size_t(n)];
      for (int i = 0; i < n; ++i) A(i, i) += 1.0 / dt;
      const Eigen::VectorXd dx = A.partialPivLu().solve(f);
      bool inside = dx.allFinite();
      for (int i = 0; i < n && inside; ++i) inside = std::abs(dx[i]) <= p.state_limit[std::size_t(i)];
      if (inside) {
        x_next = r.x + dx;
        inside = ode.rhs(t0, x_next.data(), f_next.data());
      }
      if (!inside) {  // a wheelset would move too far, or the model failed there: a shorter pseudo-time step
        dt *= 0.25;
        ++rejected;
        continue;
      }
      accepted = true;
    }
    if (!accepted) {
      r.message = "the pseudo-time step fell below " + std::to_string(kPtcMinStep) + " s after " +
                  std::to_string(it) + " steps";
      break;
    }
    const double next = merit(f_next);
    // Switched evolution relaxation: the step grows as the residual falls.
    dt = std::min(kPtcMaxStep, dt * std::clamp(res / next, 0.5, 4.0));
    r.x = x_next;
    f = f_next;
    res = next;
    r.residual = settled(f);
    r.iterations = it + 1;
  }
  finish(r, tolerance);
  if (!r.converged && rejected > 0) r.message += " (" + std::to_string(rejected) + " pseudo-time steps shortened)";
  return r;
}

EquilibriumResult static_equilibrium(const Model& model, double t0, int max_iterations, double tolerance) {
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(model.n_states);
  EquilibriumResult r = newton_equilibrium(model, zero, t0, max_iterations, tolerance);
  r.method = "newton";
  if (r.converged) return r;
  // Newton from the nominal state failed (in a curve: the nominal state puts
  // every body on its own track frame, and the suspension then carries the
  // curve's versines and heading changes between the bodies - tenths of a
  // metre at the car body). Stage 1: the suspension's bodies on the
  // wheelsets held nominal; stage 2: everything, from there.
  std::string why = "Newton from the nominal state: " + r.message;
  EquilibriumResult held;
  try {
    held = newton_equilibrium(model, zero, t0, max_iterations, tolerance, true);
  } catch (const NumericalError& e) {
    r.message = why + "; with the wheelsets held: " + e.what();
    return r;
  }
  if (!held.converged) {
    r.message = why + "; with the wheelsets held: " + held.message;
    return r;
  }
  EquilibriumResult all;
  try {
    all = newton_equilibrium(model, held.x, t0, max_iterations, tolerance);
  } catch (const NumericalError& e) {
    all.message = e.what();
  }
  all.held_iterations = held.iterations;
  all.newton_failure = r.message;
  all.method = "held wheelsets + newton";
  if (all.converged) return all;
  why += "; from the suspension's equilibrium: " + all.message;
  // Stage 3: the damped pseudo-time dynamics from the stage 1 state, polished by Newton.
  EquilibriumResult pt;
  try {
    pt = pseudo_transient_equilibrium(model, held.x, t0, kPseudoTransientSteps, kPseudoTransientSwitch);
  } catch (const NumericalError& e) {
    pt.message = e.what();
  }
  if (!pt.converged) {
    r.message = why + "; pseudo-transient: " + pt.message;
    r.residual = std::min({r.residual, all.residual, pt.residual});
    return r;
  }
  EquilibriumResult polish = newton_equilibrium(model, pt.x, t0, max_iterations, tolerance);
  polish.method = "held wheelsets + pseudo-transient + newton";
  polish.held_iterations = held.iterations;
  polish.pseudo_time_steps = pt.iterations;
  polish.newton_failure = why;
  if (!polish.converged)
    polish.message = why + "; pseudo-transient converged to " + std::to_string(pt.residual) +
                     ", Newton's polish did not: " + polish.message;
  return polish;
}

}  // namespace railsim::engine
