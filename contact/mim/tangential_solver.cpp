// Tangential contact solver (shift and steady rolling, Coulomb friction);
// see tangential_solver.hpp for the equations and the method.
#include "contact/mim/tangential_solver.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/errors.hpp"

namespace railsim::contact::mim {

namespace {
constexpr int kMaxMemory = 32;
using SmallMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxMemory, kMaxMemory>;
using SmallVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxMemory, 1>;

using ConstVec = Eigen::Map<const Eigen::VectorXd>;
using ConstMat = Eigen::Map<const Eigen::MatrixXd>;

// Vectorised dot product (Eigen uses several accumulators).
double dot(const double* a, const double* b, std::size_t n) {
  return ConstVec(a, static_cast<Eigen::Index>(n)).dot(ConstVec(b, static_cast<Eigen::Index>(n)));
}
}  // namespace

TangentialSolver::TangentialSolver(int n, int memory)
    : n_(n), m_(std::clamp(memory, 1, kMaxMemory)) {
  const std::size_t N = 2 * static_cast<std::size_t>(n);
  x_.assign(N, 0.0);
  g_.assign(N, 0.0);
  f_.assign(N, 0.0);
  gprev_.assign(N, 0.0);
  fprev_.assign(N, 0.0);
  vx_.assign(n, 0.0);
  vy_.assign(n, 0.0);
  dF_.assign(N * m_, 0.0);
  dG_.assign(N * m_, 0.0);
  gram_ = Eigen::MatrixXd::Zero(m_, m_);
  rhs_ = Eigen::VectorXd::Zero(m_);
  gamma_ = Eigen::VectorXd::Zero(m_);
}

void TangentialSolver::sweep(InfluenceOperator& op, TangentialProblem kind, const double* wx,
                             const double* wy, const double* bound, const double* x, double* g,
                             ElementState* state, double L) {
  const ContactGrid& grid = op.grid();
  const int n = n_;
  const double* px = x;
  const double* py = x + n;
  double* gx = g;
  double* gy = g + n;
  const bool rolling = kind == TangentialProblem::SteadyRolling;
  if (rolling)
    op.rolling(px, py, vx_.data(), vy_.data());
  else
    op.shift(px, py, vx_.data(), vy_.data());
  const double D = rolling ? L / grid.dx : L;
  for (int j = 0; j < grid.my; ++j) {
    for (int i = grid.mx - 1; i >= 0; --i) {
      const int q = grid.index(i, j);
      if (!(bound[q] > 0.0)) {
        gx[q] = gy[q] = 0.0;
        state[q] = ElementState::Exterior;
        continue;
      }
      double tx, ty;
      if (rolling) {
        const bool up = i + 1 < grid.mx;
        const double ux_old = up ? px[q + 1] : 0.0, uy_old = up ? py[q + 1] : 0.0;
        const double ux_new = up ? gx[q + 1] : 0.0, uy_new = up ? gy[q + 1] : 0.0;
        const double wtx = wx[q] + vx_[q] - D * (px[q] - ux_old);
        const double wty = wy[q] + vy_[q] - D * (py[q] - uy_old);
        tx = ux_new - wtx / D;
        ty = uy_new - wty / D;
      } else {
        tx = -(wx[q] + vx_[q] - D * px[q]) / D;
        ty = -(wy[q] + vy_[q] - D * py[q]) / D;
      }
      const double t = std::sqrt(tx * tx + ty * ty);
      if (t <= bound[q]) {
        gx[q] = tx;
        gy[q] = ty;
        state[q] = ElementState::Adhesion;
      } else {
        gx[q] = bound[q] * tx / t;
        gy[q] = bound[q] * ty / t;
        state[q] = ElementState::Slip;
      }
    }
  }
}

TangentialResult TangentialSolver::solve(InfluenceOperator& op, TangentialProblem kind,
                                         const double* wx, const double* wy, const double* bound,
                                         double* px, double* py, ElementState* state,
                                         const TangentialOptions& opt) {
  const ContactGrid& grid = op.grid();
  const int n = n_;
  if (grid.size() != n) throw InputError("mim tangential solver: workspace size mismatch");
  const std::size_t N = 2 * static_cast<std::size_t>(n);
  const int m = std::min(m_, std::max(1, opt.memory));

  // Local flexibility of the preconditioner: a fraction of the mean surface
  // displacement per unit uniform traction on a disc of the contact's size,
  // about (2 - nu) c / G (Johnson 1985, sec. 3.6), plus any interfacial layer.
  // The fraction 0.07 was chosen by measuring iteration counts (N = 60..200).
  double L = opt.flexibility;
  if (!(L > 0.0)) {
    int nc = 0;
    for (int q = 0; q < n; ++q) nc += bound[q] > 0.0;
    const double c = std::sqrt(std::max(1, nc) * grid.element_area() / std::numbers::pi);
    const ElasticPair& mat = op.material();
    L = 0.07 * (2.0 - mat.nu) * c / mat.G + op.layer_compliance();
  }

  for (int q = 0; q < n; ++q) {
    x_[q] = opt.warm_start ? px[q] : 0.0;
    x_[n + q] = opt.warm_start ? py[q] : 0.0;
  }
  TangentialResult res;
  int k = 0, head = 0;  // history count and next ring slot
  double best = HUGE_VAL;
  for (int it = 1; it <= opt.max_iterations; ++it) {
    res.iterations = it;
    sweep(op, kind, wx, wy, bound, x_.data(), g_.data(), state, L);
    for (std::size_t i = 0; i < N; ++i) f_[i] = g_[i] - x_[i];
    const double fn = std::sqrt(dot(f_.data(), f_.data(), N));
    const double gn = std::sqrt(dot(g_.data(), g_.data(), N));
    const double rel = gn > 0.0 ? fn / gn : (fn > 0.0 ? HUGE_VAL : 0.0);
    res.residual = rel;
    if (!std::isfinite(rel)) break;
    if (rel <= opt.tolerance) {
      res.converged = true;
      break;
    }
    if (rel > 1e3 * best) {  // diverging: restart the mixing from the plain sweep
      k = 0;
      head = 0;
      std::copy(g_.begin(), g_.end(), x_.begin());
      continue;
    }
    best = std::min(best, rel);
    if (it > 1) {
      double* dF = dF_.data() + head * N;
      double* dG = dG_.data() + head * N;
      for (std::size_t i = 0; i < N; ++i) {
        dF[i] = f_[i] - fprev_[i];
        dG[i] = g_[i] - gprev_[i];
      }
      k = std::min(k + 1, m);
      const ConstMat F(dF_.data(), static_cast<Eigen::Index>(N), k);
      const SmallVector col = F.transpose() * ConstVec(dF, static_cast<Eigen::Index>(N));
      for (int a = 0; a < k; ++a) gram_(head, a) = gram_(a, head) = col(a);
      head = (head + 1) % m;
    }
    std::copy(f_.begin(), f_.end(), fprev_.begin());
    std::copy(g_.begin(), g_.end(), gprev_.begin());
    std::copy(g_.begin(), g_.end(), x_.begin());
    if (k > 0) {
      SmallMatrix M = gram_.topLeftCorner(k, k);
      const Eigen::Index NN = static_cast<Eigen::Index>(N);
      const SmallVector r = ConstMat(dF_.data(), NN, k).transpose() * ConstVec(f_.data(), NN);
      M.diagonal().array() += 1e-12 * M.trace() / k;
      const SmallVector gam = M.ldlt().solve(r);
      Eigen::Map<Eigen::VectorXd>(x_.data(), NN).noalias() -= ConstMat(dG_.data(), NN, k) * gam;
    }
  }
  for (int q = 0; q < n; ++q) {
    px[q] = g_[q];
    py[q] = g_[n + q];
    res.n_adhesion += state[q] == ElementState::Adhesion;
    res.n_slip += state[q] == ElementState::Slip;
  }
  return res;
}

}  // namespace railsim::contact::mim
