// Tangential contact with Coulomb friction on the potential-contact grid, for
// two quasi-identical bodies (pressure given, e.g. from NormalSolver):
//   slip      s_i = w_i + (B p)_i,
//   adhesion  s_i = 0 and |p_i| <= g_i,
//   slip      p_i = -g_i s_i/|s_i|          (Coulomb; g_i = mu p_n,i, or a
//                                           limiting shear stress, see third_body.hpp),
// (Kalker 1990, ch. 2 and 5.) Two problems:
//   Shift (Cattaneo-Mindlin): B = A_t, w = rigid shift [m], s in m;
//   Steady rolling:           B = (u_i - u_{i+1})/dx operator of
//                             InfluenceOperator::rolling, w = (xi - phi y,
//                             eta + phi x) [-], s the relative slip velocity / V.
// p is the traction on body 1 (the wheel) exerted by body 2 (the rail), so a
// positive creepage gives a negative traction.
//
// Solver (our own design): the conditions above are a variational inequality
// with a monotone operator. We precondition it with the "simplified theory"
// operator B_L in which A_t is replaced by a local flexibility L (for rolling
// B_L p = L (p_i - p_{i+1})/dx, the FASTSIM-like marching of Kalker 1982; for
// shift B_L = L). One sweep solves exactly, element by element, the Coulomb
// conditions for s = w + B_L p_new + (B - B_L) p_old (leading edge to trailing
// edge for rolling, radial return for slip), with the far field (B p_old) from
// one FFT product. This fixed-point map is accelerated with Anderson mixing
// (Walker & Ni 2011, SIAM J. Numer. Anal. 49, 1715), which plays the role of
// a Krylov method for the elastic coupling while the sweep handles the
// stick/slip nonlinearity. Safeguards restart the mixing on divergence.
//
// Convergence: |G(p) - p| <= tol |G(p)| (2-norms); the result reports the
// iterations and the final residual. Non-convergence is reported in the
// result (converged = false), never silently.
#pragma once

#include <Eigen/Dense>
#include <cstdint>
#include <vector>

#include "contact/mim/influence_operator.hpp"

namespace railsim::contact::mim {

enum class TangentialProblem { Shift, SteadyRolling };

// Element state after a solve.
enum class ElementState : std::uint8_t { Exterior = 0, Adhesion = 1, Slip = 2 };

struct TangentialOptions {
  double tolerance = 1e-7;   // relative fixed-point residual
  int max_iterations = 500;
  int memory = 16;           // Anderson depth
  double flexibility = 0.0;  // local flexibility L [m/Pa]; 0 = automatic
  bool warm_start = false;   // start from the given p instead of zero
};

struct TangentialResult {
  bool converged = false;
  int iterations = 0;
  double residual = 0.0;  // final relative fixed-point residual
  int n_adhesion = 0;
  int n_slip = 0;
};

class TangentialSolver {
 public:
  explicit TangentialSolver(int n_elements, int memory = 16);
  // wx, wy: rigid slip per element; bound: traction bound g_i >= 0 [Pa]
  // (elements with g = 0 carry no traction); px, py: tractions [Pa] (input
  // when warm_start); state: element states (size n).
  TangentialResult solve(InfluenceOperator& op, TangentialProblem kind, const double* wx,
                         const double* wy, const double* bound, double* px, double* py,
                         ElementState* state, const TangentialOptions& opt = {});

 private:
  // One preconditioned sweep x -> G(x); x and g are (px | py) of size 2n.
  void sweep(InfluenceOperator& op, TangentialProblem kind, const double* wx, const double* wy,
             const double* bound, const double* x, double* g, ElementState* state, double L);

  int n_, m_;
  std::vector<double> x_, g_, f_, gprev_, fprev_, vx_, vy_;
  std::vector<double> dF_, dG_;  // m columns of size 2n (ring buffers)
  Eigen::MatrixXd gram_;
  Eigen::VectorXd rhs_, gamma_;
};

}  // namespace railsim::contact::mim
