// The recorded history of one run, for evaluations after the run (running
// safety, curving): at every output time the time, the vehicle reference
// distance and speed, and per wheelset its lateral shift and yaw relative to
// the track, the track curvature, curvature rate and cant angle at the
// wheelset, and per wheel the forces and creepages of engine::WheelOutput
// (data.hpp) with the wear number (wear_number.hpp); per measuring point the
// lateral and vertical accelerations an accelerometer fixed to the body reads.
//
// Lateral shift: `y` is relative to the rails (the wheelset's lateral position
// minus the mean lateral irregularity of its two rails, what flange contact
// depends on); `y_absolute` is relative to the design centre line.
//
// Running gear and measuring points, from the model's topology: a bogie frame
// is a non-wheelset body joined by an element to a wheelset; a car body is any
// other non-wheelset body. Points (EN 14363 measuring positions):
//   <bogie>@<wheelset>   bogie frame above each of its wheelsets (simplified
//                        method of the stability assessment), on the centre line
//                        at the frame's CoM height;
//   <car>@<bogie>        car body above each bogie centre, on the centre line at
//                        the car body's CoM height;
//   <car>@end1, @end2    car body ends: AccelerationOptions::body_ends, or above
//                        the outermost wheelsets when none are given.
// Accelerations (first-order kinematics of rigid_body.hpp, in the body's own
// track frame, track_frame.hpp) at a point at offset r = (rx, ry, rz) from the
// CoM, with qdd the state accelerations (Data::xdot), phi the body roll:
//   a_rel  = (ydd + psidd rx - phidd rz,  zdd + phidd ry - chidd rx)
//   frame: f_y = (V^2 (kappa + kappa' rx) + Vdot kappa rx) cos phic - g sin phic
//          f_z = V^2 kappa sin phic + g cos phic
//   ay = a_rel_y + f_y + f_z phi      (specific force along the body's y axis:
//                                      includes the uncompensated centripetal
//                                      acceleration and gravity through roll)
//   az = a_rel_z + f_z - g - f_y phi  (static g removed)
// (Iwnicki (ed.) 2006, Handbook of Railway Vehicle Dynamics, ch. 8, for the
// track-frame terms; small rotations as in rigid_body.hpp.)
// Units: s, m, m/s, m/s^2, rad, 1/m, N, N m; signs as in the engine (y left,
// z up, kappa > 0 turning left, Y = lateral force of the rail on the wheel
// along track y). record() appends (amortised allocation per output sample,
// not per step); reserve() first when the number of outputs is known.
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
  std::vector<double> y;           // lateral shift relative to the rails [m]
  std::vector<double> y_absolute;  // lateral shift relative to the design centre line [m]
  std::vector<double> yaw;         // relative to the track at the wheelset [rad]
  std::vector<double> curvature, curvature_rate, cant;  // track at the wheelset
  WheelHistory wheel[2];           // left, right
};

enum class PointRole { bogie_frame_above_wheelset, car_body_above_bogie, car_body_end };
const char* point_role_name(PointRole r);

struct AccelerationPoint {
  std::string name;        // "bogie1@ws1", "car@bogie1", "car@end1"
  std::string body;        // body name
  int body_index = -1;
  PointRole role = PointRole::car_body_above_bogie;
  std::string group;       // the bogie (frame points) or the car body
  Eigen::Vector3d r = Eigen::Vector3d::Zero();  // offset from the body's CoM [m]
  double offset = 0.0;     // longitudinal position from the vehicle reference [m]
  std::vector<double> ay, az;  // [m/s^2]
};

struct RunningGear {
  std::string name;         // bogie frame body
  int body = -1;
  double mass = 0.0;        // frame and its wheelsets [kg]
  double offset = 0.0;      // frame CoM from the vehicle reference [m]
  std::vector<int> wheelsets;  // indices into RunHistory::wheelsets
};

struct AccelerationOptions {
  std::vector<double> body_ends;  // x of the car-body end points [m]; empty: above the outermost wheelsets
};

struct RunHistory {
  std::string vehicle;
  double total_mass = 0.0;          // [kg], all bodies
  std::vector<double> time, distance, speed;  // distance of the vehicle reference
  std::vector<WheelsetHistory> wheelsets;
  std::vector<RunningGear> bogies;
  std::vector<std::string> car_bodies;
  std::vector<AccelerationPoint> points;
  double acceleration = 0.0;        // dV/dt of the speed profile [m/s^2]

  explicit RunHistory(const Model& model, const AccelerationOptions& options = {});
  RunHistory() = default;
  void reserve(std::size_t n);
  // Appends one sample. With measuring points, d.xdot must hold the state
  // derivative (simulate() sets it); otherwise std::invalid_argument.
  void record(const Model& model, double t, const Eigen::VectorXd& x, const Data& d);
  std::size_t size() const { return time.size(); }
  // Track distance of wheelset w at sample i [m].
  double wheelset_distance(std::size_t w, std::size_t i) const { return distance[i] + wheelsets[w].offset; }
  // Extra channels.csv columns: per wheelset <ws>.y_rel (relative to the rails),
  // per point <body>.ay@<where> and .az@<where>; values of the last sample.
  std::vector<std::string> channel_names() const;
  void last_channel_values(std::vector<double>& row) const;  // appends
};

}  // namespace railsim::engine
