// SUNDIALS ARKODE: ERKStep with the Dormand-Prince 5(4) table (explicit) and
// ARKStep with its default 4th-order SDIRK table (implicit, Newton with a
// direct linear solver). Reynolds et al. 2023, ARKODE user guide (v5/v6).
// See integrator.hpp.
#include <arkode/arkode_arkstep.h>
#include <arkode/arkode_erkstep.h>

#include <memory>
#include <string>

#include "core/errors.hpp"
#include "engine/integrators/sundials_support.hpp"

namespace railsim::engine {
namespace {

class ArkodeErk final : public SundialsIntegrator {
 public:
  ArkodeErk(OdeSystem& sys, const IntegratorOptions& o) : SundialsIntegrator(sys, o) {}
  ~ArkodeErk() override {
    if (mem_) ERKStepFree(&mem_);
  }
  void init(double t0, const Eigen::VectorXd& x0) override {
    c_.load(x0);
    t_ = t0;
    mem_ = ERKStepCreate(&SundialsCommon::rhs_cb, t0, c_.y, c_.ctx);
    SundialsCommon::check_created(mem_, "ERKStepCreate");
    const auto check = [this](int flag, const char* call, const std::string& setting = "") {
      c_.check_setup(flag, call, setting, &ERKStepGetReturnFlagName);
    };
    const auto num = [](const char* key, double v) { return std::string(key) + " " + std::to_string(v); };
    check(ERKStepSetUserData(mem_, &c_), "ERKStepSetUserData");
    check(ERKStepSetErrHandlerFn(mem_, &SundialsCommon::err_cb, &c_), "ERKStepSetErrHandlerFn");
    check(ERKStepSetTableNum(mem_, ARKODE_DORMAND_PRINCE_7_4_5), "ERKStepSetTableNum");
    check(ERKStepSVtolerances(mem_, c_.opt.rtol, c_.abs_tolerances()), "ERKStepSVtolerances", num("rtol", c_.opt.rtol));
    if (c_.opt.max_step > 0)
      check(ERKStepSetMaxStep(mem_, c_.opt.max_step), "ERKStepSetMaxStep", num("max_step", c_.opt.max_step));
    if (c_.opt.initial_step > 0)
      check(ERKStepSetInitStep(mem_, c_.opt.initial_step), "ERKStepSetInitStep", num("initial_step", c_.opt.initial_step));
    check(ERKStepSetMinStep(mem_, c_.opt.min_step), "ERKStepSetMinStep", num("min_step", c_.opt.min_step));
    check(ERKStepSetMaxNumSteps(mem_, c_.opt.max_steps), "ERKStepSetMaxNumSteps",
          "max_steps " + std::to_string(c_.opt.max_steps));
  }
  void advance(double t_out, Eigen::VectorXd& x) override {
    c_.check_setup(ERKStepSetStopTime(mem_, t_out), "ERKStepSetStopTime", "", &ERKStepGetReturnFlagName);
    const int flag = ERKStepEvolve(mem_, t_out, c_.y, &t_, ARK_NORMAL);
    if (flag < 0) {
      const std::string what = SundialsCommon::take_flag_name(ERKStepGetReturnFlagName(flag));
      throw NumericalError(c_.failure(t_, name(), flag, what.c_str(), true));
    }
    c_.store(x);
  }
  IntegratorStats stats() const override {
    IntegratorStats s;
    long nfe = 0, netf = 0;
    ERKStepGetNumSteps(mem_, &s.steps);
    ERKStepGetNumRhsEvals(mem_, &nfe);
    ERKStepGetNumErrTestFails(mem_, &netf);
    ERKStepGetLastStep(mem_, &s.last_step);
    s.rhs_calls = nfe;
    s.failed_steps = netf;
    return s;
  }
  std::string name() const override { return "arkode_erk (Dormand-Prince 5(4))"; }
  bool is_explicit() const override { return true; }
};

class ArkodeDirk final : public SundialsIntegrator {
 public:
  ArkodeDirk(OdeSystem& sys, const IntegratorOptions& o) : SundialsIntegrator(sys, o) {}
  ~ArkodeDirk() override {
    if (mem_) ARKStepFree(&mem_);
  }
  void init(double t0, const Eigen::VectorXd& x0) override {
    c_.load(x0);
    t_ = t0;
    mem_ = ARKStepCreate(nullptr, &SundialsCommon::rhs_cb, t0, c_.y, c_.ctx);
    SundialsCommon::check_created(mem_, "ARKStepCreate");
    const auto check = [this](int flag, const char* call, const std::string& setting = "") {
      c_.check_setup(flag, call, setting, &ARKStepGetReturnFlagName);
    };
    const auto num = [](const char* key, double v) { return std::string(key) + " " + std::to_string(v); };
    check(ARKStepSetUserData(mem_, &c_), "ARKStepSetUserData");
    check(ARKStepSetErrHandlerFn(mem_, &SundialsCommon::err_cb, &c_), "ARKStepSetErrHandlerFn");
    check(ARKStepSVtolerances(mem_, c_.opt.rtol, c_.abs_tolerances()), "ARKStepSVtolerances", num("rtol", c_.opt.rtol));
    if (c_.opt.max_step > 0)
      check(ARKStepSetMaxStep(mem_, c_.opt.max_step), "ARKStepSetMaxStep", num("max_step", c_.opt.max_step));
    if (c_.opt.initial_step > 0)
      check(ARKStepSetInitStep(mem_, c_.opt.initial_step), "ARKStepSetInitStep", num("initial_step", c_.opt.initial_step));
    check(ARKStepSetMinStep(mem_, c_.opt.min_step), "ARKStepSetMinStep", num("min_step", c_.opt.min_step));
    check(ARKStepSetMaxNumSteps(mem_, c_.opt.max_steps), "ARKStepSetMaxNumSteps",
          "max_steps " + std::to_string(c_.opt.max_steps));
    c_.make_linear_solver(x0, t0);
    c_.check_setup(ARKStepSetLinearSolver(mem_, c_.LS, c_.A), "ARKStepSetLinearSolver", c_.opt.linear_solver,
                   &ARKStepGetLinReturnFlagName);
    if (c_.opt.jacobian == "assembled" || c_.opt.linear_solver == "klu")
      c_.check_setup(ARKStepSetJacFn(mem_, &SundialsCommon::jac_cb), "ARKStepSetJacFn", "", &ARKStepGetLinReturnFlagName);
  }
  void advance(double t_out, Eigen::VectorXd& x) override {
    c_.check_setup(ARKStepSetStopTime(mem_, t_out), "ARKStepSetStopTime", "", &ARKStepGetReturnFlagName);
    const int flag = ARKStepEvolve(mem_, t_out, c_.y, &t_, ARK_NORMAL);
    if (flag < 0) {
      const std::string what = SundialsCommon::take_flag_name(ARKStepGetReturnFlagName(flag));
      throw NumericalError(c_.failure(t_, name(), flag, what.c_str(), false));
    }
    c_.store(x);
  }
  IntegratorStats stats() const override {
    IntegratorStats s;
    long nfe = 0, nfi = 0, nfels = 0, netf = 0, ncf = 0, nje = 0;
    ARKStepGetNumSteps(mem_, &s.steps);
    ARKStepGetNumRhsEvals(mem_, &nfe, &nfi);
    ARKStepGetNumLinRhsEvals(mem_, &nfels);
    ARKStepGetNumErrTestFails(mem_, &netf);
    ARKStepGetNumNonlinSolvConvFails(mem_, &ncf);
    ARKStepGetNumJacEvals(mem_, &nje);
    ARKStepGetLastStep(mem_, &s.last_step);
    s.rhs_calls = nfe + nfi + nfels;
    s.failed_steps = netf + ncf;
    s.jacobian_evals = nje;
    return s;
  }
  std::string name() const override { return "arkode_dirk (SDIRK, " + c_.opt.linear_solver + ")"; }
  bool is_explicit() const override { return false; }
};

}  // namespace

std::unique_ptr<Integrator> make_arkode_erk_integrator(OdeSystem& sys, const IntegratorOptions& o) {
  return std::make_unique<ArkodeErk>(sys, o);
}
std::unique_ptr<Integrator> make_arkode_dirk_integrator(OdeSystem& sys, const IntegratorOptions& o) {
  return std::make_unique<ArkodeDirk>(sys, o);
}

}  // namespace railsim::engine
