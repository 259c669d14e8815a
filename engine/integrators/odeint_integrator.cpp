// Boost.Odeint Dormand-Prince 5(4) (runge_kutta_dopri5) with error control
// and dense output (Ahnert & Mulansky 2011, AIP Conf. Proc. 1389). Output
// times are interpolated (dense output), never stepped to. Failed steps are
// derived from the call count: dopri5 is FSAL with 6 new stages per attempt,
// so attempts = (rhs calls - 1) / 6 and failed = attempts - accepted steps.
// See integrator.hpp.
#include <boost/numeric/odeint.hpp>

#include <cmath>
#include <memory>
#include <vector>

#include "core/errors.hpp"
#include "engine/integrators/integrator.hpp"

namespace railsim::engine {
namespace {

namespace odeint = boost::numeric::odeint;
using State = std::vector<double>;

class OdeintDopri5 final : public Integrator {
 public:
  OdeintDopri5(OdeSystem& sys, const IntegratorOptions& o)
      : sys_(sys),
        opt_(o),
        stepper_(odeint::make_dense_output(o.atol, o.rtol, o.max_step > 0 ? o.max_step : 1e300,
                                           odeint::runge_kutta_dopri5<State>())) {}
  void init(double t0, const Eigen::VectorXd& x0) override {
    State x(x0.data(), x0.data() + x0.size());
    const double h0 = opt_.initial_step > 0 ? opt_.initial_step : 1e-5;
    stepper_.initialize(x, t0, h0);
    t_ = t0;
  }
  void advance(double t_out, Eigen::VectorXd& x) override {
    auto f = [this](const State& xs, State& dx, double t) {
      ++calls_;
      if (!sys_.rhs(t, xs.data(), dx.data()))
        throw NumericalError(integrator_failure(t, name(), "model stopped: " + sys_.failure_message() + kExplicitHint));
    };
    long steps_here = 0;
    try {
      while (stepper_.current_time() < t_out) {
        const auto span = stepper_.do_step(f);
        ++steps_;
        last_step_ = span.second - span.first;
        if (last_step_ < opt_.min_step)
          throw NumericalError(integrator_failure(
              span.second, name(),
              "step size collapsed to " + std::to_string(last_step_) + " s (below integrator.min_step, now " +
                  std::to_string(opt_.min_step) + " s): the system is stiff or discontinuous here; use cvode_bdf, "
                  "or lower min_step"));
        if (++steps_here > opt_.max_steps)
          throw NumericalError(integrator_failure(
              span.second, name(),
              "more than integrator.max_steps steps in one output interval (last step " + std::to_string(last_step_) +
                  " s): raise integrator.max_steps (now " + std::to_string(opt_.max_steps) +
                  ", default 100000); the system may be stiff for an explicit method (e.g. elastic contact or creep "
                  "damping at low speed): use cvode_bdf or arkode_dirk"));
      }
    } catch (const odeint::step_adjustment_error& e) {
      throw NumericalError(integrator_failure(stepper_.current_time(), name(),
                                              std::string("step size adjustment failed: ") + e.what()));
    }
    State xs(sys_.size());
    stepper_.calc_state(t_out, xs);
    x = Eigen::Map<const Eigen::VectorXd>(xs.data(), long(xs.size()));
  }
  IntegratorStats stats() const override {
    IntegratorStats s;
    s.steps = steps_;
    s.rhs_calls = calls_;
    const long attempts = calls_ > 0 ? (calls_ - 1) / 6 : 0;
    s.failed_steps = attempts > steps_ ? attempts - steps_ : 0;
    s.last_step = last_step_;
    return s;
  }
  std::string name() const override { return "odeint_dopri5"; }
  bool is_explicit() const override { return true; }

 private:
  OdeSystem& sys_;
  IntegratorOptions opt_;
  odeint::dense_output_runge_kutta<odeint::controlled_runge_kutta<odeint::runge_kutta_dopri5<State>>> stepper_;
  double t_ = 0.0;
  long steps_ = 0, calls_ = 0;
  double last_step_ = 0.0;
};

}  // namespace

std::unique_ptr<Integrator> make_odeint_integrator(OdeSystem& sys, const IntegratorOptions& o) {
  return std::make_unique<OdeintDopri5>(sys, o);
}

}  // namespace railsim::engine
