// Recorded history of a run; see run_history.hpp.
#include "engine/analysis/run_history.hpp"

#include <cmath>

#include "engine/wear_number.hpp"

namespace railsim::engine {

RunHistory::RunHistory(const Model& model) : vehicle(model.vehicle_name) {
  for (const auto& b : model.bodies) total_mass += b.mass;
  for (const auto& w : model.wheelsets) {
    WheelsetHistory h;
    h.name = w.name;
    const RigidBody& b = model.bodies[w.body];
    h.offset = b.position.x();
    // static_load holds the normal loads N0 = Q0 / cos(delta0); Q0 is the vertical load.
    WheelContact c;
    double q0 = 0.0;
    for (int i = 0; i < 2; ++i) {
      w.geometry->evaluate(0.0, c);
      q0 += w.static_load[i] * std::cos(c.contact_angle);
    }
    h.static_wheel_load = 0.5 * q0;
    wheelsets.push_back(std::move(h));
  }
}

void RunHistory::reserve(std::size_t n) {
  time.reserve(n);
  distance.reserve(n);
  speed.reserve(n);
  for (auto& w : wheelsets) {
    for (auto* v : {&w.y, &w.yaw, &w.curvature, &w.curvature_rate, &w.cant}) v->reserve(n);
    for (auto& h : w.wheel)
      for (auto* v : {&h.Q, &h.Y, &h.Fx, &h.Fy, &h.Mz, &h.xi, &h.eta, &h.spin, &h.Tgamma}) v->reserve(n);
  }
}

void RunHistory::record(const Model& model, double t, const Eigen::VectorXd& x, const Data& d) {
  time.push_back(t);
  distance.push_back(model.speed.distance(t));
  speed.push_back(model.speed.speed(t));
  for (std::size_t w = 0; w < wheelsets.size(); ++w) {
    WheelsetHistory& h = wheelsets[w];
    const int body = model.wheelsets[w].body;
    const RigidBody& b = model.bodies[body];
    const TrackSample& T = d.track[body];
    h.y.push_back(x[b.q_index[kLat]] - 0.5 * (T.lat_left + T.lat_right));
    h.yaw.push_back(x[b.q_index[kYaw]]);
    h.curvature.push_back(T.curvature);
    h.curvature_rate.push_back(T.curvature_rate);
    h.cant.push_back(T.cant);
    for (int i = 0; i < 2; ++i) {
      const WheelOutput& o = d.wheel[2 * w + i];
      WheelHistory& wh = h.wheel[i];
      wh.Q.push_back(o.Q);
      wh.Y.push_back(o.Y);
      wh.Fx.push_back(o.Fx);
      wh.Fy.push_back(o.Fy);
      wh.Mz.push_back(o.Mz);
      wh.xi.push_back(o.creep.xi);
      wh.eta.push_back(o.creep.eta);
      wh.spin.push_back(o.creep.phi);
      wh.Tgamma.push_back(wear_number(o));
    }
  }
}

}  // namespace railsim::engine
