// Linearisation and eigenvalues; see linearisation.hpp.
#include "engine/linearisation.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/errors.hpp"
#include "engine/system.hpp"

namespace railsim::engine {

Eigen::MatrixXd state_jacobian(const Model& model, const Eigen::VectorXd& x0, double t) {
  const int n = model.n_states;
  Data d(model);
  d.warm_start = false;  // central differences of history-free evaluations (Data::warm_start)
  Eigen::MatrixXd J(n, n);
  Eigen::VectorXd xp = x0, fp(n), fm(n);
  for (int j = 0; j < n; ++j) {
    const double h = 1e-7 * std::max(1.0, std::abs(x0[j]));
    xp[j] = x0[j] + h;
    rhs_or_throw(model, d, t, xp.data(), fp.data());
    xp[j] = x0[j] - h;
    rhs_or_throw(model, d, t, xp.data(), fm.data());
    xp[j] = x0[j];
    J.col(j) = (fp - fm) / (2 * h);
  }
  return J;
}

std::vector<Mode> modes(const Model& model, const Eigen::VectorXd& x0, bool oscillatory_only) {
  const Eigen::MatrixXd J = state_jacobian(model, x0);
  Eigen::EigenSolver<Eigen::MatrixXd> es(J, false);
  std::vector<Mode> out;
  for (int i = 0; i < es.eigenvalues().size(); ++i) {
    const std::complex<double> s = es.eigenvalues()[i];
    if (oscillatory_only && !(s.imag() > 1e-9)) continue;
    Mode m;
    m.eigenvalue = s;
    m.frequency = std::abs(s.imag()) / (2 * M_PI);
    m.damping_ratio = std::abs(s) > 0 ? -s.real() / std::abs(s) : 0.0;
    out.push_back(m);
  }
  std::sort(out.begin(), out.end(), [](const Mode& a, const Mode& b) { return a.eigenvalue.real() > b.eigenvalue.real(); });
  return out;
}

double max_real_part(const Model& model, double V) {
  Model m = model;
  m.speed.v0 = V;
  m.speed.accel = 0.0;
  const auto md = modes(m, Eigen::VectorXd::Zero(m.n_states), true);
  return md.empty() ? -1e300 : md.front().eigenvalue.real();
}

double critical_speed(const Model& model, double lo, double hi, double rel_tol) {
  constexpr double kZero = kUnstableGrowth;
  double flo = max_real_part(model, lo), fhi = max_real_part(model, hi);
  if (!(flo < kZero && fhi > kZero)) {
    char buf[200];
    std::snprintf(buf, sizeof buf,
                  "critical speed search: no loss of stability between %.4g and %.4g m/s (largest real parts %.4g, "
                  "%.4g 1/s)", lo, hi, flo, fhi);
    throw NumericalError(buf);
  }
  while (hi - lo > rel_tol * hi) {
    const double mid = 0.5 * (lo + hi);
    (max_real_part(model, mid) < kZero ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace railsim::engine
