// Frictionless normal contact of two quasi-identical elastic half-spaces on a
// grid of piecewise-constant pressure elements:
//   e_i = h_i - delta + (A_zz p)_i >= 0,  p_i >= 0,  e_i p_i = 0,
// with undeformed gap h [m], approach delta [m] and pressure p [Pa]; either
// the approach or the total load F = sum p_i dA [N] is given.
//
// Iterative solver: bound-constrained conjugate gradients of Polonsky & Keer
// (1999, Wear 231, 206-219, sec. 3) with FFT influence products; the
// approach is the mean gap over the contact when the load is given.
// Direct solver (small grids only, a cross-check): an active-set method on
// the dense influence matrix (Cholesky per active set).
//
// Convergence: relative pressure change dA sum|p_new - p_old| / F below the
// tolerance; the result reports iterations and the complementarity residual
// max|e_i| over contact and max(-e_i) elsewhere, relative to delta.
#pragma once

#include <vector>

#include "contact/mim/influence_operator.hpp"

namespace railsim::contact::mim {

struct NormalOptions {
  double tolerance = 1e-9;    // relative pressure change per iteration
  int max_iterations = 2000;
  // Start from the pressure given in p (scaled to the load) instead of the
  // paraboloid guess, e.g. a coarser grid's solution; ignored if p carries no load.
  bool initial_guess = false;
};

struct NormalResult {
  bool converged = false;
  int iterations = 0;
  double residual = 0.0;  // complementarity residual relative to the approach
  double approach = 0.0;  // [m]
  double load = 0.0;      // [N]
  double pmax = 0.0;      // largest element pressure [Pa]
  int n_contact = 0;      // elements with p > 0
};

class NormalSolver {
 public:
  explicit NormalSolver(int n_elements);
  // Given total load F [N] > 0. p (size n) receives the pressure [Pa].
  NormalResult solve_load(InfluenceOperator& op, const double* h, double F, double* p,
                          const NormalOptions& opt = {});
  // Given approach delta [m].
  NormalResult solve_approach(InfluenceOperator& op, const double* h, double delta, double* p,
                              const NormalOptions& opt = {});

 private:
  NormalResult run(InfluenceOperator& op, const double* h, bool load_control, double target,
                   double* p, const NormalOptions& opt);
  std::vector<double> u_, t_, r_, gap_, pold_;
};

// Dense active-set solution with given approach (cross-check; n <= 2500).
NormalResult solve_normal_dense(const ContactGrid& grid, const ElasticPair& material,
                                const std::vector<double>& h, double delta, std::vector<double>& p);

}  // namespace railsim::contact::mim
