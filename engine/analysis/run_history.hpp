// The recorded history of one run, for evaluations after the run (running
// safety, curving): at every output time the time, the vehicle reference
// distance and speed, and per wheelset its lateral shift and yaw relative to
// the track, the track curvature, curvature rate and cant angle at the
// wheelset, and per wheel the forces and creepages of engine::WheelOutput
// (data.hpp) with the wear number (wear_number.hpp).
// Units: s, m, m/s, rad, 1/m, N, N m; signs as in the engine (y left, kappa > 0
// turning left, Y = lateral force of the rail on the wheel along track y).
// record() appends (amortised allocation per output sample, not per step);
// reserve() first when the number of outputs is known.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "engine/data.hpp"
#include "engine/model.hpp"

namespace railsim::engine {

struct WheelHistory {
  std::vector<double> Q, Y, Fx, Fy, Mz, xi, eta, spin, Tgamma;
};

struct WheelsetHistory {
  std::string name;
  double offset = 0.0;             // longitudinal position from the vehicle reference [m]
  double static_wheel_load = 0.0;  // mean static vertical wheel load Q0 [N]
  std::vector<double> y, yaw;      // relative to the track at the wheelset [m, rad]
  std::vector<double> curvature, curvature_rate, cant;  // track at the wheelset
  WheelHistory wheel[2];           // left, right
};

struct RunHistory {
  std::string vehicle;
  double total_mass = 0.0;          // [kg], all bodies
  std::vector<double> time, distance, speed;  // distance of the vehicle reference
  std::vector<WheelsetHistory> wheelsets;

  explicit RunHistory(const Model& model);
  RunHistory() = default;
  void reserve(std::size_t n);
  void record(const Model& model, double t, const Eigen::VectorXd& x, const Data& d);
  std::size_t size() const { return time.size(); }
  // Track distance of wheelset w at sample i [m].
  double wheelset_distance(std::size_t w, std::size_t i) const { return distance[i] + wheelsets[w].offset; }
};

}  // namespace railsim::engine
