// Shared plumbing of the SUNDIALS integrators (CVODE, ARKODE): context,
// serial vector, dense/banded matrix and direct linear solver, the
// right-hand-side and Jacobian callbacks, bandwidth detection, error capture.
// Not a model: see cvode_integrator.cpp and arkode_integrator.cpp.
#pragma once

#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>

#include <Eigen/Core>
#include <string>
#include <vector>

#include "engine/integrators/integrator.hpp"

namespace railsim::engine {

struct SundialsCommon {
  SundialsCommon(OdeSystem& sys, const IntegratorOptions& opt);
  ~SundialsCommon();
  SundialsCommon(const SundialsCommon&) = delete;
  SundialsCommon& operator=(const SundialsCommon&) = delete;

  // Create matrix + linear solver (implicit methods), detecting the bandwidth
  // from the Jacobian pattern at x0 when a banded solver is asked for.
  void make_linear_solver(const Eigen::VectorXd& x0, double t0);
  void load(const Eigen::VectorXd& x);
  // Per-state absolute tolerances (OdeSystem::tolerances), created on first use.
  N_Vector abs_tolerances();
  void store(Eigen::VectorXd& x) const;

  OdeSystem& sys;
  IntegratorOptions opt;
  SUNContext ctx = nullptr;
  N_Vector y = nullptr;
  N_Vector atol_vec = nullptr;
  SUNMatrix A = nullptr;
  SUNLinearSolver LS = nullptr;
  int mu = 0, ml = 0;
  long jac_evals = 0;
  std::string last_error;       // message captured from SUNDIALS
  std::vector<double> J;        // dense scratch for assembled Jacobians
  std::vector<int> colptr, rowind;  // sparse pattern (klu)
  bool model_failed = false;

  static int rhs_cb(double t, N_Vector y, N_Vector ydot, void* user);
  static int jac_cb(double t, N_Vector y, N_Vector fy, SUNMatrix J, void* user, N_Vector, N_Vector, N_Vector);
  static void err_cb(int code, const char* module, const char* function, char* msg, void* user);
  // Failure text for a negative return flag.
  std::string failure(double t, const std::string& name, int flag, const char* flag_name, bool is_explicit) const;
  // The *GetReturnFlagName functions of SUNDIALS return a malloc'd string that
  // the caller frees: copy it and free it.
  static std::string take_flag_name(char* name);
  // A set-up call (CVodeSet*, ARKStepSet*, ...) returning `flag`: negative is
  // an error naming the call, the setting and SUNDIALS' flag name (from
  // `flag_name`, e.g. CVodeGetReturnFlagName) and SUNDIALS' own message:
  // InputError for *_ILL_INPUT (a setting the integrator refuses, such as
  // min_step above max_step), NumericalError otherwise (memory, solver set-up).
  using FlagNameFn = char* (*)(long int);
  void check_setup(int flag, const char* call, const std::string& setting, FlagNameFn flag_name) const;
  // A constructor of SUNDIALS (CVodeCreate, ...) that returned nullptr.
  static void check_created(const void* mem, const char* call);
};

// What every SUNDIALS integrator holds: the shared set-up above, the
// package's memory block (freed by the derived class's destructor, before
// the set-up it uses) and the time reached.
class SundialsIntegrator : public Integrator {
 protected:
  SundialsIntegrator(OdeSystem& sys, const IntegratorOptions& o) : c_(sys, o) {}
  SundialsCommon c_;
  void* mem_ = nullptr;
  double t_ = 0.0;
};

}  // namespace railsim::engine
