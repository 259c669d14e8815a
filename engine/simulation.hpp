// Time simulation of a Model: integrate from x0 over a duration, reporting
// the state at every output time to an observer (which receives a Data
// evaluated at that state: wheel loads, forces, creepages). Measures wall
// time and the real-time factor (simulated time / wall time). Failures throw
// NumericalError (integrator.hpp) naming the last step size; a derailment
// (the model's physics: a wheelset past its flange) throws DerailmentError.
// A stop request (core/stop_request.hpp) is polled after every output point;
// when it is set, InterruptedError names the time and place reached (the
// observer has seen every output up to it).
#pragma once

#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

#include "core/stop_request.hpp"
#include "engine/data.hpp"
#include "engine/integrators/integrator.hpp"
#include "engine/model.hpp"

namespace railsim::engine {

struct RunSummary {
  std::string integrator;
  IntegratorStats stats;
  double simulated_time = 0.0;
  double wall_time = 0.0;         // [s]
  double real_time_factor = 0.0;  // simulated / wall
  double cpu_time = 0.0;          // CPU time of this thread [s]
  double real_time_factor_cpu = 0.0;  // simulated / CPU time (independent of machine load)
  std::vector<double> max_abs_lateral;  // per wheelset [m]
  long invalid_contact_calls = 0;
  std::string first_invalid_reason;
  long outputs = 0;
};

using Observer = std::function<void(double t, const Eigen::VectorXd& x, const Data& d)>;

RunSummary simulate(const Model& model, const IntegratorOptions& options, const Eigen::VectorXd& x0,
                    double duration, double output_interval, const Observer& observer = {},
                    const StopRequest& stop = {});

// Channel names of the standard output (channels.csv) and one row of values:
// time, distance, speed; per wheelset <ws>.y, <ws>.yaw (relative to the
// track); per wheel <ws>.<L|R>.Q, Y, Fx, xi, eta, spin, contact_y, YQ (Y/Q,
// 0 for a lifted wheel), Tgamma (wear number, wear_number.hpp); with a
// flexible track (wheel_rail/track_flexibility.hpp) also <ws>.track_y and
// <ws>.<L|R>.rail_z, the rails' positions under the wheelset (geometry plus
// deflection) [m].
std::vector<std::string> channel_names(const Model& model);
void channel_row(const Model& model, double t, const Eigen::VectorXd& x, const Data& d, std::vector<double>& row);

}  // namespace railsim::engine
