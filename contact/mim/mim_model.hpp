// The exact contact solver as a library call and as the tangential model
// "mim": Kalker's matrix inversion method (boundary elements, Kalker 1990,
// ch. 5) for two quasi-identical elastic half-spaces, FFT-accelerated:
//   1. normal problem with given load on the potential-contact grid
//      (NormalSolver, Polonsky-Keer CG);
//   2. tangential problem (TangentialSolver): steady rolling with creepages
//      xi, eta, phi (rigid slip w = (xi - phi y, eta + phi x), spin about the
//      grid origin) or a shift (Cattaneo-Mindlin), Coulomb friction, optional
//      third-body layer.
//      Spin discretisation: the rigid slip of element i is evaluated at
//      (x_i + dx/6, y_j), shifted from the element centre towards the
//      upstream neighbour i+1 that the rolling step couples it with
//      (influence_operator.hpp). CONTACT's user guide defines the rigid shift
//      in steady rolling with this offset, x_I + cos(chi) dq/6 (Vollebregt,
//      "User guide for CONTACT", section "Tangential quantities in case of
//      rolling"). Measured (circular patch of creep_curves_circ_exact.csv,
//      phi = 1 1/m, Fy/(mu Fz) at 30 / 60 / 120 elements): at the centre
//      -0.5459 / -0.5528 / -0.5559; offset dx/6 -0.5550 / -0.5573 / -0.5581,
//      CONTACT's figures to the 4th digit; offset dx/2 (the middle of the
//      step) overshoots, -0.5729 / -0.5662 / -0.5626. Grid 60 is within
//      0.49 % of mu Fz of grid 120 on the 764 states of
//      tests/data/contact/spin_reference (a/b 0.2 - 5); the registered model
//      "mim" extrapolates (Richardson, mim_model.cpp): within 0.23 %.
//      xi and eta are uniform, so only spin is affected.
// Outputs: pressure and traction fields, stick/slip map, total forces and
// spin moment. Sign conventions as contact/types.hpp: forces of the rail on
// the wheel, a positive creepage gives a negative force; Mz = sum (x py - y px) dA.
// Units SI (m, Pa, N, N m; phi in 1/m).
//
// Input either a Hertzian patch (gap A x^2 + B y^2, the grid from the
// semi-axes a, b with `grid` elements across the minor axis, see grid.hpp) or
// any undeformed gap on a grid (e.g. a non-Hertzian wheel-rail patch).
//
// Failures: bad input throws InputError; a solver that does not converge
// throws NumericalError naming the model, iterations and residual (or, with
// throw_on_failure = false, returns the result flagged converged = false).
#pragma once

#include <memory>
#include <vector>

#include "contact/mim/grid.hpp"
#include "contact/mim/influence_operator.hpp"
#include "contact/mim/normal_solver.hpp"
#include "contact/mim/tangential_solver.hpp"
#include "contact/mim/third_body.hpp"
#include "contact/registry.hpp"
#include "contact/types.hpp"

namespace railsim::contact::mim {

// Largest working memory of one solver (README "Exit codes and limits") and
// the estimate for a grid of mx x my elements [bytes]: the FFT convolution's
// padded real and complex arrays (3 real, 2 + 7 kernel complex) and about
// 700 bytes per element for the normal and tangential (Anderson) solvers.
inline constexpr double kMaxMimBytes = 4.0 * (1ull << 30);
double mim_memory_estimate(int mx, int my);

struct MimOptions {
  int grid = 40;                  // elements across the minor axis (Hertzian input)
  double tolerance = 1e-7;        // tangential solver, relative residual
  double normal_tolerance = 1e-9; // normal solver, relative pressure change
  int max_iterations = 500;       // tangential solver
  ThirdBodyLayer layer;           // interfacial layer (off by default)
  unsigned fftw_flags = 64u;      // FFTW_ESTIMATE (plans made instantly)
  bool throw_on_failure = true;
  // Start the tangential iteration from the previous solution (same grid and
  // problem kind): fewer iterations in sweeps over creepage; results agree
  // with a cold start to the tolerance.
  bool warm_start = false;

  // Throws InputError for grid outside [4, 4000], tolerances outside (0, 0.1].
  void check() const;
};

struct MimSolution {
  ContactGrid grid;
  std::vector<double> pn, px, py;     // pressure and tractions per element [Pa]
  std::vector<ElementState> state;    // exterior / adhesion / slip
  double Fz = 0.0, Fx = 0.0, Fy = 0.0, Mz = 0.0;  // [N], [N m]
  double approach = 0.0;              // [m]
  int n_contact = 0, n_adhesion = 0, n_slip = 0;
  NormalResult normal;
  TangentialResult tangential;
  bool converged() const { return normal.converged && tangential.converged; }
};

class MimSolver {
 public:
  explicit MimSolver(const MimOptions& options = {});
  const MimOptions& options() const { return opt_; }

  // Steady rolling on a Hertzian patch: patch.A, B, a, b, Fz must be positive.
  // `start`: a solution of the same problem on another (coarser) grid; its
  // pressure, interpolated at this grid's element centres, starts the normal
  // iteration (nested iteration: fewer iterations, the same converged result
  // to the tolerance).
  const MimSolution& solve_hertz(const HertzPatch& patch, const Creepages& creep,
                                 const Material& material, const MimSolution* start = nullptr);
  // Steady rolling with any undeformed gap h [m] on `grid` and load Fz [N].
  const MimSolution& solve_gap(const ContactGrid& grid, const std::vector<double>& gap, double Fz,
                               const Creepages& creep, const Material& material);
  // Shift (Cattaneo-Mindlin): tangential rigid shift (Wx, Wy) [m] of body 1
  // relative to body 2 from the unloaded tangential state, Hertzian patch.
  const MimSolution& solve_shift_hertz(const HertzPatch& patch, double Wx, double Wy,
                                       const Material& material);
  // Normal problem only (Hertzian gap or any gap).
  const MimSolution& solve_normal(const ContactGrid& grid, const std::vector<double>& gap, double Fz,
                                  const Material& material);

  const MimSolution& solution() const { return sol_; }

 private:
  void prepare(const ContactGrid& grid, const Material& material);
  // The normal problem; reused unchanged when the gap and the load are those
  // of the last solve on this grid (creepage sweeps on one patch), started
  // from `start`'s pressure sampled on this grid when given.
  void normal(const std::vector<double>& gap, double Fz, const MimSolution* start = nullptr);
  void tangential(TangentialProblem kind, double w1, double w2, double w3, double mu);
  void finish(const char* what);

  MimOptions opt_;
  std::unique_ptr<InfluenceOperator> op_;
  std::unique_ptr<NormalSolver> nsolver_;
  std::unique_ptr<TangentialSolver> tsolver_;
  std::vector<double> gap_, wx_, wy_, bound_;
  MimSolution sol_;
  bool have_previous_ = false;  // sol_.px, py hold a converged solution on this grid
  bool have_normal_ = false;    // sol_.pn solves (normal_gap_, normal_Fz_) on this grid
  std::vector<double> normal_gap_;
  double normal_Fz_ = 0.0;
  TangentialProblem previous_kind_ = TangentialProblem::SteadyRolling;
};

}  // namespace railsim::contact::mim

namespace railsim::contact {
// Factory of the registered tangential model "mim" (options grid, tolerance,
// extrapolation: Richardson from the grid and the half grid unless None,
// see mim_model.cpp; the MimSolver facade above never extrapolates).
std::unique_ptr<TangentialModel> make_mim(const TangentialModelOptions& options);
}  // namespace railsim::contact
