// Linear stability: the Jacobian of the right-hand side about a steady state
// (central differences, step 1e-7 max(1, |x_j|)) and its eigenvalues (Eigen
// EigenSolver). For each eigenvalue s = sigma + i omega:
//   frequency f = |omega| / 2 pi [Hz], damping ratio zeta = -sigma / |s|.
// The linear critical speed is where the largest real part of the
// oscillatory modes crosses zero (Hopf point; physics-reference §8.1, §8.4);
// found by bisection in speed. The linearisation point is x0 at t = 0, i.e.
// at the scenario's start distance: use a perfect (irregularity-free) track,
// or the full wheelset model sees its wheels off (or into) the rails there.
#pragma once

#include <Eigen/Core>
#include <complex>
#include <vector>

#include "engine/data.hpp"
#include "engine/model.hpp"

namespace railsim::engine {

struct Mode {
  std::complex<double> eigenvalue;
  double frequency = 0.0;      // [Hz]
  double damping_ratio = 0.0;  // [-]
};

Eigen::MatrixXd state_jacobian(const Model& model, const Eigen::VectorXd& x0, double t = 0.0);
// Modes sorted by decreasing real part; only oscillatory ones (omega > 0,
// one of each conjugate pair) when oscillatory_only.
std::vector<Mode> modes(const Model& model, const Eigen::VectorXd& x0, bool oscillatory_only = true);
// Largest real part of the oscillatory modes at speed V (x0 = 0).
double max_real_part(const Model& model, double V);
// Growth rate [1/s] above which a mode counts as unstable: undamped modes (a
// suspension without dampers, e.g. a bogie pitch mode) have real parts of the
// order of the differencing error (~1e-10 1/s).
constexpr double kUnstableGrowth = 1e-6;
// Bisection for the speed where max_real_part exceeds 1e-6 1/s in [v_lo, v_hi]
// (undamped modes with real parts at rounding level count as stable);
// throws NumericalError when it does not change sign there.
double critical_speed(const Model& model, double v_lo, double v_hi, double rel_tol = 1e-5);

}  // namespace railsim::engine
