// Recorded history of a run; see run_history.hpp.
#include "engine/analysis/run_history.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

#include "engine/track_frame.hpp"
#include "engine/wheel_rail/wear_number.hpp"

namespace railsim::engine {

const char* point_role_name(PointRole r) {
  switch (r) {
    case PointRole::bogie_frame_above_wheelset: return "bogie frame above wheelset";
    case PointRole::car_body_above_bogie: return "car body above bogie centre";
    case PointRole::car_body_end: return "car body end";
  }
  return "unknown";
}

namespace {

// Pairs of bodies joined by an element (track = -1 excluded).
std::vector<std::pair<int, int>> links(const Model& m) {
  std::vector<std::pair<int, int>> out;
  auto add = [&](int a, int b) {
    if (a >= 0 && b >= 0 && a != b) out.emplace_back(a, b);
  };
  for (const auto& e : m.springs) add(e.body_a, e.body_b);
  for (const auto& e : m.bump_stops) add(e.body_a, e.body_b);
  for (const auto& e : m.yaw_dampers) add(e.body_a, e.body_b);
  for (const auto& e : m.anti_roll_bars) add(e.body_a, e.body_b);
  return out;
}

}  // namespace

RunHistory::RunHistory(const Model& model, const AccelerationOptions& options)
    : vehicle(model.vehicle_name), acceleration(model.speed.accel) {
  for (const auto& b : model.bodies) total_mass += b.mass;
  for (const auto& w : model.wheelsets) {
    WheelsetHistory h;
    h.name = w.name;
    const RigidBody& b = model.bodies[w.body];
    h.offset = b.position.x();
    // static_load holds the normal loads N0 = Q0 / cos(delta0); Q0 is the vertical load.
    const ContactPointGeometry c = w.geometry->main_point(0.0);
    double q0 = 0.0;
    for (int i = 0; i < 2; ++i) q0 += w.static_load[i] * std::cos(c.contact_angle);
    h.static_wheel_load = 0.5 * q0;
    wheelsets.push_back(std::move(h));
  }

  // Topology: bogie frames hold wheelsets, car bodies are the other rigid bodies.
  const auto pairs = links(model);
  const int nb = static_cast<int>(model.bodies.size());
  std::vector<std::set<int>> wheelsets_of(nb);
  std::vector<std::set<int>> neighbours(nb);
  for (auto [a, b] : pairs) {
    neighbours[a].insert(b);
    neighbours[b].insert(a);
    const int wa = model.bodies[a].wheelset, wb = model.bodies[b].wheelset;
    if (wa >= 0 && wb < 0) wheelsets_of[b].insert(wa);
    if (wb >= 0 && wa < 0) wheelsets_of[a].insert(wb);
  }
  std::vector<bool> is_bogie(nb, false);
  for (int i = 0; i < nb; ++i) {
    if (model.bodies[i].wheelset >= 0 || wheelsets_of[i].empty()) continue;
    is_bogie[i] = true;
    RunningGear g;
    g.name = model.bodies[i].name;
    g.body = i;
    g.offset = model.bodies[i].position.x();
    g.mass = model.bodies[i].mass;
    for (int w : wheelsets_of[i]) {
      g.wheelsets.push_back(w);
      g.mass += model.bodies[model.wheelsets[w].body].mass;
    }
    bogies.push_back(std::move(g));
  }
  auto add_point = [&](int body, PointRole role, const std::string& where, double x, const std::string& group) {
    AccelerationPoint p;
    p.body_index = body;
    p.body = model.bodies[body].name;
    p.name = p.body + "@" + where;
    p.role = role;
    p.group = group;
    p.offset = x;
    p.r = Eigen::Vector3d(x - model.bodies[body].position.x(), 0.0, 0.0);
    points.push_back(std::move(p));
  };
  for (const auto& g : bogies)
    for (int w : g.wheelsets)
      add_point(g.body, PointRole::bogie_frame_above_wheelset, wheelsets[w].name, wheelsets[w].offset, g.name);
  double xmin = 0.0, xmax = 0.0;
  for (std::size_t w = 0; w < wheelsets.size(); ++w) {
    xmin = w == 0 ? wheelsets[w].offset : std::min(xmin, wheelsets[w].offset);
    xmax = w == 0 ? wheelsets[w].offset : std::max(xmax, wheelsets[w].offset);
  }
  for (int i = 0; i < nb; ++i) {
    if (model.bodies[i].wheelset >= 0 || is_bogie[i]) continue;
    bool carries = false;
    for (int j : neighbours[i]) carries = carries || is_bogie[j];
    if (!carries) continue;
    car_bodies.push_back(model.bodies[i].name);
    for (int j : neighbours[i])
      if (is_bogie[j]) add_point(i, PointRole::car_body_above_bogie, model.bodies[j].name, model.bodies[j].position.x(),
                                 model.bodies[i].name);
    std::vector<double> ends = options.body_ends;
    if (ends.empty() && !wheelsets.empty()) ends = {xmax, xmin};
    for (std::size_t e = 0; e < ends.size(); ++e)
      add_point(i, PointRole::car_body_end, "end" + std::to_string(e + 1), ends[e], model.bodies[i].name);
  }
}

void RunHistory::reserve(std::size_t n) {
  time.reserve(n);
  distance.reserve(n);
  speed.reserve(n);
  for (auto& w : wheelsets) {
    for (auto* v : {&w.y, &w.y_absolute, &w.yaw, &w.curvature, &w.curvature_rate, &w.cant}) v->reserve(n);
    for (auto& h : w.wheel)
      for (auto* v : {&h.Q, &h.Y, &h.Fx, &h.Fy, &h.Mz, &h.xi, &h.eta, &h.spin, &h.Tgamma}) v->reserve(n);
  }
  for (auto& p : points) {
    p.ay.reserve(n);
    p.az.reserve(n);
  }
}

void RunHistory::record(const Model& model, double t, const Eigen::VectorXd& x, const Data& d) {
  if (!points.empty() && d.xdot.size() != x.size())
    throw std::invalid_argument("RunHistory::record: Data::xdot does not hold the state derivative");
  time.push_back(t);
  distance.push_back(model.speed.distance(t));
  const double V = model.speed.speed(t);
  speed.push_back(V);
  for (std::size_t w = 0; w < wheelsets.size(); ++w) {
    WheelsetHistory& h = wheelsets[w];
    const int body = model.wheelsets[w].body;
    const RigidBody& b = model.bodies[body];
    const TrackSample& T = d.track[body];
    h.y.push_back(x[b.q_index[kLat]] - d.rail[w].lateral);  // relative to the rails (flexible track: as deflected)
    h.y_absolute.push_back(x[b.q_index[kLat]]);
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
  for (auto& p : points) {
    const RigidBody& b = model.bodies[p.body_index];
    std::array<double, kNumDof> qdd{};
    for (int k = 0; k < kNumDof; ++k) qdd[k] = b.v_index[k] >= 0 ? d.xdot[b.v_index[k]] : 0.0;
    const Eigen::Vector3d a = point_displacement(qdd, p.r);
    const double phi = b.q_index[kRoll] >= 0 ? x[b.q_index[kRoll]] : 0.0;
    const TrackSample& T = d.track[p.body_index];
    const double c = std::cos(T.cant), s = std::sin(T.cant), rx = p.r.x();
    const double fy =
        (V * V * (T.curvature + T.curvature_rate * rx) + acceleration * T.curvature * rx) * c - kGravity * s;
    const double fz = V * V * T.curvature * s + kGravity * c;
    p.ay.push_back(a.y() + fy + fz * phi);
    p.az.push_back(a.z() + fz - kGravity - fy * phi);
  }
}

std::vector<std::string> RunHistory::channel_names() const {
  std::vector<std::string> c;
  for (const auto& w : wheelsets) c.push_back(w.name + ".y_rel");
  for (const auto& p : points) {
    const std::string where = p.name.substr(p.name.find('@') + 1);
    c.push_back(p.body + ".ay@" + where);
    c.push_back(p.body + ".az@" + where);
  }
  return c;
}

void RunHistory::last_channel_values(std::vector<double>& row) const {
  if (time.empty()) return;
  for (const auto& w : wheelsets) row.push_back(w.y.back());
  for (const auto& p : points) {
    row.push_back(p.ay.back());
    row.push_back(p.az.back());
  }
}

}  // namespace railsim::engine
