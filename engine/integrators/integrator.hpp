// Time integrators behind one interface, chosen by name (registry):
//   cvode_bdf      SUNDIALS CVODE, variable-order BDF (stiff), Newton with a
//                  dense or banded direct solver, Jacobian by SUNDIALS'
//                  difference quotients ("fd") or assembled by us ("assembled":
//                  exact kinematic rows dq/dt = v, finite-difference force rows)
//   arkode_erk     SUNDIALS ARKODE ERKStep, Dormand-Prince 5(4) (explicit)
//   arkode_dirk    SUNDIALS ARKODE ARKStep, default 4th-order SDIRK (implicit)
//   odeint_dopri5  Boost.Odeint Dormand-Prince 5(4), dense output, error control
// All take relative/absolute tolerances and a maximum step; output times are
// reached exactly (interpolation by the integrator). Statistics: steps,
// right-hand-side calls, failed steps (error-test and convergence failures).
// Failures throw NumericalError naming the time, the integrator and the reason
// (the model's own failure message when the right-hand side stopped it: NaN,
// lift-off, derailment; step-size collapse; too much work, which for an
// explicit method on a stiff system is the usual symptom: the message says so).
#pragma once

#include <Eigen/Core>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace railsim::engine {

struct IntegratorOptions {
  std::string method = "cvode_bdf";
  double rtol = 1e-6;
  double atol = 1e-8;
  double max_step = 0.0;       // 0: unlimited
  double initial_step = 0.0;   // 0: integrator's choice
  double min_step = 1e-12;     // smaller steps = collapse -> NumericalError
  long max_steps = 100000;     // per output interval
  // cvode/arkode_dirk: "assembled" (ours: exact kinematic rows, coloured
  // differences over the model's sparsity; well scaled near equilibrium) or
  // "fd" (SUNDIALS' difference quotients, dense/band only).
  std::string jacobian = "assembled";
  // cvode/arkode_dirk: auto (klu when the system has a sparsity pattern, else
  // dense) | klu (SuiteSparse KLU) | dense | band.
  std::string linear_solver = "auto";
  int max_order = 0;           // cvode_bdf: highest BDF order (1..5; 0 = 5). 2 keeps BDF A-stable
                               // for undamped stiff modes (elastic contact without damping)
  bool stability_limit_detection = false;  // cvode_bdf: CVODE's BDF stability limit detection (orders 3-5)
  // cvode_bdf: most steps between Jacobian evaluations (CVODE's msbj; its own
  // default is 51). A Newton iteration that fails to converge with the kept
  // Jacobian makes CVODE evaluate it again at once, so a long interval costs
  // iterations only where the Jacobian really changes. At 400 the coach on
  // ERRI profiles takes 17 coloured Jacobians instead of 116 and 26 % fewer
  // right-hand sides, with the same steps and accuracy (README).
  long jacobian_max_age = 400;
  // Absolute tolerance of the states of the stiff wheel-rail contact modes
  // (the wheelsets' spin perturbations in both wheelset models, and in the
  // full model their vertical and roll velocities) [m/s, rad/s]; 0 = atol.
  // A looser tolerance lets the implicit methods step over these modes
  // (OdeSystem::tolerances): 1e-4 rad/s of spin is a longitudinal creepage of
  // r0 1e-4 / V (3.5e-7 at 120 m/s), but the bounce modes (~250 Hz on the
  // Hertz springs) carry the wheel load: on vertically irregular track 1e-4
  // m/s puts Q off by up to 19 % of its range (coach, ERRI, 200 km/h; README).
  double atol_contact_modes = 0.0;
};

struct IntegratorStats {
  long steps = 0;
  long rhs_calls = 0;
  long failed_steps = 0;
  long jacobian_evals = 0;
  double last_step = 0.0;
};

// The ODE x' = f(t, x) seen by an integrator.
class OdeSystem {
 public:
  virtual ~OdeSystem() = default;
  virtual int size() const = 0;
  // false: the model broke down (failure_message says why).
  virtual bool rhs(double t, const double* x, double* xdot) = 0;
  virtual std::string failure_message() const = 0;
  // Dense Jacobian (column-major n x n) at (t, x) with f(t, x) = fx given.
  // Default: forward differences of rhs.
  virtual bool jacobian(double t, const double* x, const double* fx, double* J);
  // Sparsity pattern of the Jacobian (CSC); false: dense (the default).
  virtual bool pattern(std::vector<int>& colptr, std::vector<int>& rowind) const {
    (void)colptr;
    (void)rowind;
    return false;
  }
  // Jacobian values in the CSC order of pattern().
  virtual bool sparse_jacobian(double t, const double* x, const double* fx, double* values) {
    (void)t;
    (void)x;
    (void)fx;
    (void)values;
    return false;
  }
  // Absolute tolerance per state (default: options.atol everywhere).
  virtual void tolerances(const IntegratorOptions& options, double* atol) const;
};

class Integrator {
 public:
  virtual ~Integrator() = default;
  virtual void init(double t0, const Eigen::VectorXd& x0) = 0;
  // Advance to t_out and return the state there (throws NumericalError).
  virtual void advance(double t_out, Eigen::VectorXd& x) = 0;
  virtual IntegratorStats stats() const = 0;
  virtual std::string name() const = 0;
  virtual bool is_explicit() const = 0;
};

using IntegratorFactory = std::unique_ptr<Integrator> (*)(OdeSystem&, const IntegratorOptions&);
struct IntegratorEntry {
  const char* name;
  const char* description;
  IntegratorFactory make;
};
const std::vector<IntegratorEntry>& integrators();
std::string integrator_names();
// Throws InputError for unknown names or bad options.
std::unique_ptr<Integrator> make_integrator(OdeSystem& sys, const IntegratorOptions& options);

// Factories (one file each).
std::unique_ptr<Integrator> make_cvode_integrator(OdeSystem&, const IntegratorOptions&);
std::unique_ptr<Integrator> make_arkode_erk_integrator(OdeSystem&, const IntegratorOptions&);
std::unique_ptr<Integrator> make_arkode_dirk_integrator(OdeSystem&, const IntegratorOptions&);
std::unique_ptr<Integrator> make_odeint_integrator(OdeSystem&, const IntegratorOptions&);

// Hint appended when an explicit method stops on a model failure.
extern const char* const kExplicitHint;

// Shared helper: the failure text "t = .. s: <integrator>: <what>".
std::string integrator_failure(double t, const std::string& integrator, const std::string& what);

}  // namespace railsim::engine
