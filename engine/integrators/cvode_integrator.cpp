// SUNDIALS CVODE, variable-order BDF with Newton iteration and a direct
// (dense or banded) linear solver (Hindmarsh et al. 2005, ACM TOMS 31(3);
// SUNDIALS 6 user guide). Jacobian: CVODE's difference quotients ("fd") or
// ours ("assembled", OdeSystem::jacobian). See integrator.hpp.
#include <cvode/cvode.h>
#include <cvode/cvode_ls.h>

#include <memory>
#include <string>

#include "core/errors.hpp"
#include "engine/integrators/sundials_support.hpp"

namespace railsim::engine {
namespace {

class CvodeIntegrator final : public SundialsIntegrator {
 public:
  CvodeIntegrator(OdeSystem& sys, const IntegratorOptions& o) : SundialsIntegrator(sys, o) {}
  ~CvodeIntegrator() override {
    if (mem_) CVodeFree(&mem_);
  }
  void init(double t0, const Eigen::VectorXd& x0) override {
    c_.load(x0);
    t_ = t0;
    mem_ = CVodeCreate(CV_BDF, c_.ctx);
    SundialsCommon::check_created(mem_, "CVodeCreate");
    // Every set-up call is checked: a refused setting (min_step above
    // max_step, say) would otherwise be ignored silently.
    const auto check = [this](int flag, const char* call, const std::string& setting = "") {
      c_.check_setup(flag, call, setting, &CVodeGetReturnFlagName);
    };
    const auto num = [](const char* key, double v) { return std::string(key) + " " + std::to_string(v); };
    check(CVodeInit(mem_, &SundialsCommon::rhs_cb, t0, c_.y), "CVodeInit");
    check(CVodeSetUserData(mem_, &c_), "CVodeSetUserData");
    check(CVodeSetErrHandlerFn(mem_, &SundialsCommon::err_cb, &c_), "CVodeSetErrHandlerFn");
    check(CVodeSVtolerances(mem_, c_.opt.rtol, c_.abs_tolerances()), "CVodeSVtolerances", num("rtol", c_.opt.rtol));
    if (c_.opt.max_step > 0) check(CVodeSetMaxStep(mem_, c_.opt.max_step), "CVodeSetMaxStep", num("max_step", c_.opt.max_step));
    if (c_.opt.initial_step > 0)
      check(CVodeSetInitStep(mem_, c_.opt.initial_step), "CVodeSetInitStep", num("initial_step", c_.opt.initial_step));
    check(CVodeSetMinStep(mem_, c_.opt.min_step), "CVodeSetMinStep", num("min_step", c_.opt.min_step));
    check(CVodeSetMaxNumSteps(mem_, c_.opt.max_steps), "CVodeSetMaxNumSteps", "max_steps " + std::to_string(c_.opt.max_steps));
    if (c_.opt.max_order > 0)
      check(CVodeSetMaxOrd(mem_, c_.opt.max_order), "CVodeSetMaxOrd", "max_order " + std::to_string(c_.opt.max_order));
    if (c_.opt.stability_limit_detection) check(CVodeSetStabLimDet(mem_, SUNTRUE), "CVodeSetStabLimDet");
    c_.make_linear_solver(x0, t0);
    c_.check_setup(CVodeSetLinearSolver(mem_, c_.LS, c_.A), "CVodeSetLinearSolver", c_.opt.linear_solver,
                   &CVodeGetLinReturnFlagName);
    if (c_.opt.jacobian == "assembled" || c_.opt.linear_solver == "klu")
      c_.check_setup(CVodeSetJacFn(mem_, &SundialsCommon::jac_cb), "CVodeSetJacFn", "", &CVodeGetLinReturnFlagName);
    c_.check_setup(CVodeSetJacEvalFrequency(mem_, c_.opt.jacobian_max_age), "CVodeSetJacEvalFrequency",
                   "jacobian_max_age " + std::to_string(c_.opt.jacobian_max_age), &CVodeGetLinReturnFlagName);
  }
  void advance(double t_out, Eigen::VectorXd& x) override {
    const int flag = CVode(mem_, t_out, c_.y, &t_, CV_NORMAL);
    if (flag < 0) {
      const std::string what = SundialsCommon::take_flag_name(CVodeGetReturnFlagName(flag));
      throw NumericalError(c_.failure(t_, name(), flag, what.c_str(), false));
    }
    c_.store(x);
  }
  IntegratorStats stats() const override {
    IntegratorStats s;
    long nfe = 0, nfels = 0, netf = 0, ncf = 0, nje = 0;
    CVodeGetNumSteps(mem_, &s.steps);
    CVodeGetNumRhsEvals(mem_, &nfe);
    CVodeGetNumLinRhsEvals(mem_, &nfels);
    CVodeGetNumErrTestFails(mem_, &netf);
    CVodeGetNumNonlinSolvConvFails(mem_, &ncf);
    CVodeGetNumJacEvals(mem_, &nje);
    CVodeGetLastStep(mem_, &s.last_step);
    s.rhs_calls = nfe + nfels;
    s.failed_steps = netf + ncf;
    s.jacobian_evals = nje;
    return s;
  }
  std::string name() const override {
    return "cvode_bdf (" + c_.opt.linear_solver + ", " + c_.opt.jacobian + " Jacobian)";
  }
  bool is_explicit() const override { return false; }
};

}  // namespace

std::unique_ptr<Integrator> make_cvode_integrator(OdeSystem& sys, const IntegratorOptions& o) {
  return std::make_unique<CvodeIntegrator>(sys, o);
}

}  // namespace railsim::engine
