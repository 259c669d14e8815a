// SUNDIALS plumbing; see sundials_support.hpp.
#include "engine/integrators/sundials_support.hpp"

#include <cstdlib>

#include <sunlinsol/sunlinsol_band.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunlinsol/sunlinsol_klu.h>
#include <sunmatrix/sunmatrix_sparse.h>
#include <sunmatrix/sunmatrix_band.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"
#include "engine/integrators/serial_vector_ops.hpp"
#include "engine/integrators/sparse_matrix_ops.hpp"

namespace railsim::engine {

const char* const kExplicitHint =
    ". Note: an explicit integrator on a stiff system (elastic contact, creep damping at low speed) can go "
    "unstable and produce such a state; rerun with cvode_bdf or arkode_dirk";

SundialsCommon::SundialsCommon(OdeSystem& s, const IntegratorOptions& o) : sys(s), opt(o) {
  if (SUNContext_Create(nullptr, &ctx) != 0) throw NumericalError("SUNDIALS: cannot create a context");
  y = N_VNew_Serial(sys.size(), ctx);
  if (!y) throw NumericalError("SUNDIALS: cannot create the state vector");
  install_serial_vector_ops(y);  // CVODE's and ARKODE's work vectors are its clones
}

SundialsCommon::~SundialsCommon() {
  if (LS) SUNLinSolFree(LS);
  if (A) SUNMatDestroy(A);
  if (y) N_VDestroy(y);
  if (atol_vec) N_VDestroy(atol_vec);
  if (ctx) SUNContext_Free(&ctx);
}

void SundialsCommon::load(const Eigen::VectorXd& x) {
  double* d = N_VGetArrayPointer(y);
  for (int i = 0; i < sys.size(); ++i) d[i] = x[i];
}

N_Vector SundialsCommon::abs_tolerances() {
  if (!atol_vec) {
    atol_vec = N_VNew_Serial(sys.size(), ctx);
    if (!atol_vec) throw NumericalError("SUNDIALS: cannot create the tolerance vector");
    install_serial_vector_ops(atol_vec);
    sys.tolerances(opt, N_VGetArrayPointer(atol_vec));
  }
  return atol_vec;
}

void SundialsCommon::store(Eigen::VectorXd& x) const {
  const double* d = N_VGetArrayPointer(y);
  x.resize(sys.size());
  for (int i = 0; i < sys.size(); ++i) x[i] = d[i];
}

void SundialsCommon::make_linear_solver(const Eigen::VectorXd& x0, double t0) {
  const int n = sys.size();
  J.assign(std::size_t(n) * n, 0.0);
  if (opt.linear_solver == "auto") {
    std::vector<int> cp, ri;
    opt.linear_solver = sys.pattern(cp, ri) ? "klu" : "dense";
  }
  if (opt.linear_solver == "klu" && opt.jacobian == "fd")
    throw InputError("integrator: jacobian 'fd' works with the dense and band solvers only; 'klu' needs 'assembled'");
  if (opt.linear_solver == "klu") {
    // Sparse direct solver (KLU, Davis & Palamadai Natarajan 2010) on the
    // model's structural pattern, Jacobian by coloured differences.
    if (!sys.pattern(colptr, rowind))
      throw InputError("integrator: linear_solver 'klu' needs a model with a sparsity pattern");
    A = SUNSparseMatrix(n, n, sunindextype(rowind.size()), CSC_MAT, ctx);
    if (!A) throw NumericalError("SUNDIALS: cannot create the sparse matrix");
    install_sparse_matrix_ops(A);  // before the solver and CVODE clone it
    LS = SUNLinSol_KLU(y, A, ctx);
    if (!LS) throw NumericalError("SUNDIALS: cannot create the KLU sparse solver");
    // Fill-reducing ordering AMD (Amestoy, Davis & Duff 1996) in place of
    // SUNDIALS' default COLAMD: the Newton matrix I - gamma J has the
    // symmetric pattern of coupled bodies, where AMD gives less fill (the ERRI
    // profiles run: KLU 128 -> 77 M instructions, same steps and accuracy).
    if (SUNLinSol_KLUSetOrdering(LS, 0) != SUNLS_SUCCESS)
      throw NumericalError("SUNDIALS: cannot set the KLU ordering");
  } else if (opt.linear_solver == "band") {
    // Bandwidth from the Jacobian pattern at a slightly perturbed x0.
    Eigen::VectorXd xp = x0;
    for (int i = 0; i < n; ++i) xp[i] += 1e-6 * (1 + (i % 7)) / 7.0;
    std::vector<double> f(n);
    if (!sys.rhs(t0, xp.data(), f.data()) || !sys.jacobian(t0, xp.data(), f.data(), J.data()))
      throw NumericalError(integrator_failure(t0, "band set-up", sys.failure_message()));
    mu = ml = 0;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        if (J[i + std::size_t(j) * n] != 0.0) {
          mu = std::max(mu, j - i);
          ml = std::max(ml, i - j);
        }
    A = SUNBandMatrix(n, mu, ml, ctx);
    LS = SUNLinSol_Band(y, A, ctx);
  } else {
    A = SUNDenseMatrix(n, n, ctx);
    LS = SUNLinSol_Dense(y, A, ctx);
  }
}

int SundialsCommon::rhs_cb(double t, N_Vector yv, N_Vector ydot, void* user) {
  auto* self = static_cast<SundialsCommon*>(user);
  if (self->sys.rhs(t, N_VGetArrayPointer(yv), N_VGetArrayPointer(ydot))) {
    self->model_failed = false;
    return 0;
  }
  // Recoverable: the state was a trial of the integrator (a step too long
  // for the contact, a wheel far into its rail); CVODE / ARKode retry with a
  // shorter step and fail with the model's message when the failure persists.
  self->model_failed = true;
  return 1;
}

int SundialsCommon::jac_cb(double t, N_Vector yv, N_Vector fy, SUNMatrix Jm, void* user, N_Vector, N_Vector,
                           N_Vector) {
  auto* self = static_cast<SundialsCommon*>(user);
  ++self->jac_evals;
  const int n = self->sys.size();
  if (SUNMatGetID(Jm) == SUNMATRIX_SPARSE) {
    sunindextype* cp = SUNSparseMatrix_IndexPointers(Jm);
    sunindextype* ri = SUNSparseMatrix_IndexValues(Jm);
    for (std::size_t j = 0; j < self->colptr.size(); ++j) cp[j] = self->colptr[j];
    for (std::size_t k = 0; k < self->rowind.size(); ++k) ri[k] = self->rowind[k];
    if (!self->sys.sparse_jacobian(t, N_VGetArrayPointer(yv), N_VGetArrayPointer(fy), SUNSparseMatrix_Data(Jm))) {
      self->model_failed = true;
      return 1;  // recoverable, as in rhs_cb
    }
    return 0;
  }
  if (!self->sys.jacobian(t, N_VGetArrayPointer(yv), N_VGetArrayPointer(fy), self->J.data())) {
    self->model_failed = true;
    return 1;  // recoverable, as in rhs_cb
  }
  if (SUNMatGetID(Jm) == SUNMATRIX_BAND) {
    for (int j = 0; j < n; ++j)
      for (int i = std::max(0, j - self->mu); i <= std::min(n - 1, j + self->ml); ++i)
        SM_ELEMENT_B(Jm, i, j) = self->J[i + std::size_t(j) * n];
  } else {
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) SM_ELEMENT_D(Jm, i, j) = self->J[i + std::size_t(j) * n];
  }
  return 0;
}

void SundialsCommon::err_cb(int, const char* module, const char* function, char* msg, void* user) {
  auto* self = static_cast<SundialsCommon*>(user);
  self->last_error = std::string(module) + "/" + function + ": " + msg;
}

std::string SundialsCommon::take_flag_name(char* name) {
  std::string out = name ? name : "unknown flag";
  std::free(name);
  return out;
}

void SundialsCommon::check_setup(int flag, const char* call, const std::string& setting, FlagNameFn flag_name) const {
  if (flag >= 0) return;
  const std::string fname = take_flag_name(flag_name(flag));
  std::string msg = std::string("integrator set-up: ") + call + (setting.empty() ? "" : " (" + setting + ")") +
                    " failed with " + fname + " (flag " + std::to_string(flag) + ")";
  if (!last_error.empty()) msg += ": " + last_error;
  if (fname.find("ILL_INPUT") != std::string::npos)
    throw InputError(msg + "; check the scenario's integrator settings (min_step, max_step, initial_step, "
                           "max_order, tolerances)");
  throw NumericalError(msg);
}

void SundialsCommon::check_created(const void* mem, const char* call) {
  if (!mem) throw NumericalError(std::string("integrator set-up: ") + call + " returned no memory block");
}

std::string SundialsCommon::failure(double t, const std::string& name, int flag, const char* flag_name,
                                    bool is_explicit) const {
  if (model_failed)
    return integrator_failure(t, name, "model stopped: " + sys.failure_message() + (is_explicit ? kExplicitHint : ""));
  std::string what = std::string(flag_name) + " (flag " + std::to_string(flag) + ")";
  if (!last_error.empty()) what += ": " + last_error;
  // What to change, by flag (CV_* and ARK_* share these values).
  char num[64];
  const auto g = [&](double v) {
    std::snprintf(num, sizeof num, "%g", v);
    return std::string(num);
  };
  switch (flag) {
    case -1:  // TOO_MUCH_WORK
      what += "; more than integrator.max_steps steps in one output interval: raise integrator.max_steps (now " +
              std::to_string(opt.max_steps) + ", default 100000)";
      what += is_explicit ? "; the system may be stiff for an explicit method (e.g. elastic contact or creep damping "
                            "at low speed): use cvode_bdf or arkode_dirk"
                          : "; if more steps do not help, the model is stiff or discontinuous here";
      break;
    case -2:  // TOO_MUCH_ACC
      what += "; the tolerances ask for more accuracy than double precision gives: raise integrator.rtol (now " +
              g(opt.rtol) + ") or integrator.atol (now " + g(opt.atol) + ")";
      break;
    case -3:  // ERR_FAILURE
      if (opt.min_step > 1e-12)
        what += "; the step could not shrink below integrator.min_step (now " + g(opt.min_step) +
                " s): lower min_step or omit it";
      else
        what += "; the error test failed repeatedly: the model is discontinuous or stiff here; lower "
                "integrator.max_step (now " + (opt.max_step > 0 ? g(opt.max_step) + " s" : std::string("unlimited")) +
                ") or loosen integrator.rtol (now " + g(opt.rtol) + ")";
      break;
    case -4:  // CONV_FAILURE
      what += "; the Newton iteration did not converge: use integrator.jacobian: assembled (now " + opt.jacobian +
              ") or lower integrator.max_step (now " +
              (opt.max_step > 0 ? g(opt.max_step) + " s" : std::string("unlimited")) + ")";
      break;
    default:
      break;
  }
  return integrator_failure(t, name, what);
}

}  // namespace railsim::engine
