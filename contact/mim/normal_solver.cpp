// Normal contact solvers; see normal_solver.hpp (Polonsky & Keer 1999).
#include "contact/mim/normal_solver.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <string>

#include "core/errors.hpp"

namespace railsim::contact::mim {

NormalSolver::NormalSolver(int n) : u_(n), t_(n), r_(n), gap_(n), pold_(n) {}

NormalResult NormalSolver::solve_load(InfluenceOperator& op, const double* h, double F, double* p,
                                      const NormalOptions& opt) {
  if (!(F > 0.0) || !std::isfinite(F))
    throw InputError("mim normal solver: load must be positive and finite");
  return run(op, h, true, F, p, opt);
}

NormalResult NormalSolver::solve_approach(InfluenceOperator& op, const double* h, double delta,
                                          double* p, const NormalOptions& opt) {
  if (!std::isfinite(delta)) throw InputError("mim normal solver: approach must be finite");
  return run(op, h, false, delta, p, opt);
}

NormalResult NormalSolver::run(InfluenceOperator& op, const double* h, bool load_control,
                               double target, double* p, const NormalOptions& opt) {
  const ContactGrid& g = op.grid();
  const int n = g.size();
  if (static_cast<int>(u_.size()) != n) throw InputError("mim normal solver: workspace size mismatch");
  const double dA = g.element_area();
  NormalResult res;

  // Initial guess: a paraboloid-like pressure over the elements with the
  // smallest gaps (or uniform when the gap is flat).
  double hmin = h[0], hmax = h[0];
  for (int i = 0; i < n; ++i) hmin = std::min(hmin, h[i]), hmax = std::max(hmax, h[i]);
  double given = 0.0;
  if (opt.initial_guess && load_control)
    for (int i = 0; i < n; ++i) given += p[i] > 0.0 && std::isfinite(p[i]) ? p[i] : 0.0;
  if (given > 0.0) {
    const double scale = target / (given * dA);
    for (int i = 0; i < n; ++i) p[i] = p[i] > 0.0 && std::isfinite(p[i]) ? p[i] * scale : 0.0;
  } else {
    const double level = load_control ? hmin + 0.3 * (hmax - hmin) : target;
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
      p[i] = std::max(0.0, level - h[i]);
      sum += p[i];
    }
    if (!(sum > 0.0)) {
      for (int i = 0; i < n; ++i) p[i] = 1.0;
      sum = n;
    }
    const double scale = load_control ? target / (sum * dA) : op.material().G * 1e-3 / (sum / n);
    for (int i = 0; i < n; ++i) p[i] *= scale;
  }

  double Gold = 1.0, gbar = 0.0;
  bool conjugate = false;
  // u = A p is updated incrementally (u - tau A t) while no pressure is
  // clipped or added; otherwise, and every 25 iterations, recomputed.
  bool u_valid = false;
  std::fill(t_.begin(), t_.end(), 0.0);
  for (int it = 1; it <= opt.max_iterations; ++it) {
    res.iterations = it;
    if (!u_valid || it % 25 == 0) op.normal(p, u_.data());
    // Gap of the deformed surfaces (without the approach), mean over the contact.
    int nc = 0;
    double gsum = 0.0;
    for (int i = 0; i < n; ++i) {
      gap_[i] = u_[i] + h[i];
      if (p[i] > 0.0) gsum += gap_[i], ++nc;
    }
    if (nc == 0) throw NumericalError("mim normal solver: lost all contact");
    gbar = load_control ? gsum / nc : target;
    double G = 0.0;
    for (int i = 0; i < n; ++i) {
      gap_[i] -= gbar;
      if (p[i] > 0.0) G += gap_[i] * gap_[i];
    }
    for (int i = 0; i < n; ++i) t_[i] = (p[i] > 0.0) ? gap_[i] + (conjugate ? G / Gold * t_[i] : 0.0) : 0.0;
    Gold = G;
    op.normal(t_.data(), r_.data());
    double rbar = 0.0;
    if (load_control) {
      for (int i = 0; i < n; ++i)
        if (p[i] > 0.0) rbar += r_[i];
      rbar /= nc;
    }
    double num = 0.0, den = 0.0;
    for (int i = 0; i < n; ++i)
      if (p[i] > 0.0) num += gap_[i] * t_[i], den += (r_[i] - rbar) * t_[i];
    const double tau = (den != 0.0) ? num / den : 0.0;
    std::copy(p, p + n, pold_.begin());
    bool overlap = false, clipped = false;
    for (int i = 0; i < n; ++i) {
      if (pold_[i] > 0.0) {
        const double v = p[i] - tau * t_[i];
        clipped |= v < 0.0;
        p[i] = std::max(0.0, v);
      }
    }
    for (int i = 0; i < n; ++i)
      if (pold_[i] <= 0.0 && gap_[i] < 0.0) {
        p[i] = -tau * gap_[i];
        overlap = true;
      }
    conjugate = !overlap;
    u_valid = !overlap && !clipped;
    if (u_valid)
      for (int i = 0; i < n; ++i) u_[i] -= tau * r_[i];
    double load = 0.0;
    for (int i = 0; i < n; ++i) load += p[i];
    load *= dA;
    if (load_control) {
      if (!(load > 0.0)) throw NumericalError("mim normal solver: pressure vanished (no contact)");
      const double s = target / load;
      for (int i = 0; i < n; ++i) p[i] *= s;
      if (u_valid)
        for (int i = 0; i < n; ++i) u_[i] *= s;
      load = target;
    }
    double change = 0.0;
    for (int i = 0; i < n; ++i) change += std::abs(p[i] - pold_[i]);
    change *= dA / std::max(load, 1e-300);
    if (!std::isfinite(change))
      throw NumericalError("mim normal solver: non-finite pressure at iteration " + std::to_string(it));
    if (change < opt.tolerance) {
      res.converged = true;
      break;
    }
  }
  // Final state and complementarity residual.
  op.normal(p, u_.data());
  int nc = 0;
  double gsum = 0.0, load = 0.0, pmax = 0.0;
  for (int i = 0; i < n; ++i) {
    if (p[i] > 0.0) gsum += u_[i] + h[i], ++nc;
    load += p[i];
    pmax = std::max(pmax, p[i]);
  }
  res.approach = load_control ? (nc ? gsum / nc : 0.0) : target;
  double resid = 0.0;
  for (int i = 0; i < n; ++i) {
    const double e = u_[i] + h[i] - res.approach;
    resid = std::max(resid, p[i] > 0.0 ? std::abs(e) : std::max(0.0, -e));
  }
  res.residual = resid / std::max(std::abs(res.approach), 1e-300);
  res.load = load * dA;
  res.pmax = pmax;
  res.n_contact = nc;
  return res;
}

NormalResult solve_normal_dense(const ContactGrid& grid, const ElasticPair& material,
                                const std::vector<double>& h, double delta, std::vector<double>& p) {
  const int n = grid.size();
  if (n > 2500) throw InputError("mim dense normal solver: at most 2500 elements (got " + std::to_string(n) + ")");
  Eigen::MatrixXd A(n, n);
  for (int j1 = 0; j1 < grid.my; ++j1)
    for (int i1 = 0; i1 < grid.mx; ++i1)
      for (int j2 = 0; j2 < grid.my; ++j2)
        for (int i2 = 0; i2 < grid.mx; ++i2)
          A(grid.index(i1, j1), grid.index(i2, j2)) =
              influence_zz(material, (i1 - i2) * grid.dx, (j1 - j2) * grid.dy, grid.dx, grid.dy);
  std::vector<char> active(n);
  for (int i = 0; i < n; ++i) active[i] = h[i] < delta;
  p.assign(n, 0.0);
  NormalResult res;
  for (int it = 1; it <= 200; ++it) {
    res.iterations = it;
    std::vector<int> idx;
    for (int i = 0; i < n; ++i)
      if (active[i]) idx.push_back(i);
    const int m = static_cast<int>(idx.size());
    Eigen::MatrixXd Acc(m, m);
    Eigen::VectorXd rhs(m);
    for (int a = 0; a < m; ++a) {
      rhs(a) = delta - h[idx[a]];
      for (int b = 0; b < m; ++b) Acc(a, b) = A(idx[a], idx[b]);
    }
    const Eigen::VectorXd pc = Acc.llt().solve(rhs);
    std::fill(p.begin(), p.end(), 0.0);
    for (int a = 0; a < m; ++a) p[idx[a]] = pc(a);
    bool changed = false;
    for (int a = 0; a < m; ++a)
      if (pc(a) < 0.0) active[idx[a]] = 0, changed = true;
    if (!changed) {
      const Eigen::VectorXd u = A * Eigen::Map<Eigen::VectorXd>(p.data(), n);
      for (int i = 0; i < n; ++i)
        if (!active[i] && u(i) + h[i] - delta < -1e-14 * std::abs(delta)) active[i] = 1, changed = true;
    }
    if (!changed) {
      res.converged = true;
      break;
    }
    for (int i = 0; i < n; ++i) p[i] = std::max(0.0, p[i]);
  }
  res.approach = delta;
  double load = 0.0;
  for (int i = 0; i < n; ++i) {
    load += p[i];
    res.pmax = std::max(res.pmax, p[i]);
    res.n_contact += p[i] > 0.0;
  }
  res.load = load * grid.element_area();
  return res;
}

}  // namespace railsim::contact::mim
