// Time simulation and channels; see simulation.hpp.
#include "engine/simulation.hpp"

#include <time.h>

#include <chrono>
#include <cstdio>

#include "core/errors.hpp"
#include <cmath>

#include "engine/system.hpp"
#include "engine/wheel_rail/wear_number.hpp"

namespace railsim::engine {
namespace {
double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}
}  // namespace

RunSummary simulate(const Model& model, const IntegratorOptions& options, const Eigen::VectorXd& x0,
                    double duration, double dt_out, const Observer& observer, const StopRequest& stop) {
  Data data(model), rec(model);
  rec.record_patches = true;  // the reported outputs carry each patch's contact input (contact audit)
  ModelOde ode(model, data);
  auto integ = make_integrator(ode, options);
  RunSummary sum;
  sum.integrator = integ->name();
  sum.max_abs_lateral.assign(model.wheelsets.size(), 0.0);
  Eigen::VectorXd x = x0, xdot(model.n_states);
  const auto start = std::chrono::steady_clock::now();
  const double cpu0 = thread_cpu_seconds();
  auto report = [&](double t) {
    rec.approach_warm_start = data.approach_warm_start;  // the integrator's latest solves start the output's
    rhs_or_throw(model, rec, t, x.data(), xdot.data());
    rec.xdot = xdot;  // same size every time: no allocation after the first output
    for (std::size_t w = 0; w < model.wheelsets.size(); ++w) {
      const int qi = model.bodies[model.wheelsets[w].body].q_index[kLat];
      sum.max_abs_lateral[w] = std::max(sum.max_abs_lateral[w], std::abs(x[qi]));
    }
    ++sum.outputs;
    if (observer) observer(t, x, rec);
  };
  integ->init(0.0, x);
  report(0.0);
  const long n_out = std::max(1L, std::lround(duration / dt_out));
  for (long k = 1; k <= n_out; ++k) {
    const double t = k == n_out ? duration : k * dt_out;
    try {
      integ->advance(t, x);
    } catch (const NumericalError& e) {
      // A derailment is physics (the model says so), anything else numerics:
      // say which, with the last step the integrator took.
      // The place: the track distance between the last output and this one.
      const double t_prev = (k - 1) * dt_out;
      char buf[256];
      std::snprintf(buf, sizeof buf, " (last step %.3g s); place: track distance %.2f-%.2f m (t = %.4g-%.4g s)",
                    integ->stats().last_step, model.speed.distance(t_prev), model.speed.distance(t), t_prev, t);
      const std::string where = std::string(buf) + "; model: " + wheelset_model_name(model.wheelset_model) +
                                " wheelset, contact " + model.coupling.describe();
      if (data.derailed) throw DerailmentError(std::string(e.what()) + where);
      if (data.left_range) throw ModelRangeError(std::string(e.what()) + where);
      throw NumericalError(std::string(e.what()) + where);
    }
    report(t);
    if (k < n_out && stop.requested()) {
      char buf[160];
      std::snprintf(buf, sizeof buf, "interrupted at t = %.6g s of %.6g s (track distance %.2f m)", t, duration,
                    model.speed.distance(t));
      throw InterruptedError(buf);
    }
  }
  sum.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  sum.cpu_time = thread_cpu_seconds() - cpu0;
  sum.real_time_factor_cpu = sum.cpu_time > 0 ? duration / sum.cpu_time : 0.0;
  sum.simulated_time = duration;
  sum.real_time_factor = sum.wall_time > 0 ? duration / sum.wall_time : 0.0;
  sum.stats = integ->stats();
  // Every evaluation of the model, including those of our assembled Jacobians
  // and the band detection (SUNDIALS counts only its own calls).
  sum.stats.rhs_calls = data.rhs_calls;
  sum.invalid_contact_calls = data.invalid_contact_calls;
  sum.first_invalid_reason = data.first_invalid_reason;
  return sum;
}

std::vector<std::string> channel_names(const Model& model) {
  std::vector<std::string> c = {"time", "distance", "speed"};
  for (const auto& w : model.wheelsets) {
    c.push_back(w.name + ".y");
    c.push_back(w.name + ".yaw");
    for (const char* side : {"L", "R"}) {
      const std::string p = w.name + "." + side + ".";
      for (const char* q : {"Q", "Y", "Fx", "xi", "eta", "spin", "contact_y", "YQ", "Tgamma"}) c.push_back(p + q);
    }
    // Flexible track (wheel_rail/track_flexibility.hpp): where the rails under
    // the wheelset are, geometry plus deflection [m].
    if (w.track_lateral_state >= 0) c.push_back(w.name + ".track_y");
    for (int i = 0; i < 2; ++i)
      if (w.rail_vertical_state[i] >= 0) c.push_back(w.name + (i == 0 ? ".L" : ".R") + ".rail_z");
  }
  return c;
}

void channel_row(const Model& model, double t, const Eigen::VectorXd& x, const Data& d, std::vector<double>& row) {
  row.clear();
  row.push_back(t);
  row.push_back(model.speed.distance(t));
  row.push_back(model.speed.speed(t));
  for (std::size_t w = 0; w < model.wheelsets.size(); ++w) {
    const auto& b = model.bodies[model.wheelsets[w].body];
    row.push_back(x[b.q_index[kLat]]);
    row.push_back(x[b.q_index[kYaw]]);
    for (int i = 0; i < 2; ++i) {
      const WheelOutput& o = d.wheel[2 * w + i];
      const double yq = o.Q > 0.0 ? o.Y / o.Q : 0.0;  // lifted wheel: no meaningful Y/Q
      row.insert(row.end(), {o.Q, o.Y, o.Fx, o.creep.xi, o.creep.eta, o.creep.phi, o.contact_y, yq, wear_number(o)});
    }
    const Wheelset& ws = model.wheelsets[w];
    if (ws.track_lateral_state >= 0) row.push_back(d.rail[w].lateral);
    for (int i = 0; i < 2; ++i)
      if (ws.rail_vertical_state[i] >= 0) row.push_back(d.rail[w].vertical[i]);
  }
}

}  // namespace railsim::engine
