// Vehicle YAML reader; see vehicle_file.hpp.
#include "engine/io/vehicle_file.hpp"

#include "core/errors.hpp"

namespace railsim::engine {
namespace {

using config::InputNode;

Eigen::Vector3d vec3(const InputNode& n, bool non_negative) {
  const auto v = n.as_numbers();
  if (v.size() != 3) n.fail("expected a list of 3 numbers (got " + std::to_string(v.size()) + ")");
  for (double x : v)
    if (non_negative && x < 0) n.fail("expected non-negative numbers (got " + config::format_number(x) + ")");
  return {v[0], v[1], v[2]};
}

int body_ref(const InputNode& n, const Model& m, bool allow_track) {
  const std::string name = n.as_string();
  if (allow_track && name == "track") return -1;
  const int i = m.body_index(name);
  if (i < 0) {
    std::string known;
    for (const auto& b : m.bodies) known += (known.empty() ? "" : ", ") + b.name;
    n.fail("unknown body '" + name + "' (bodies: " + known + (allow_track ? ", track" : "") + ")");
  }
  return i;
}

// Every element of the model by name (all kinds share one name space).
bool element_name_taken(const Model& m, const std::string& name) {
  for (const auto& e : m.springs)
    if (e.name == name) return true;
  for (const auto& e : m.bump_stops)
    if (e.name == name) return true;
  for (const auto& e : m.yaw_dampers)
    if (e.name == name) return true;
  for (const auto& e : m.anti_roll_bars)
    if (e.name == name) return true;
  return false;
}

// An element must join two different bodies: from a body to itself it would
// exert no net force but shift the reported loads.
void check_ends(const InputNode& e, int a, int b) {
  if (a == b)
    e.at("other").fail("element joins body '" + e.string("body") + "' to itself; 'other' must be another body or "
                       "'track'");
}

Eigen::Vector3d centre(const Model& m, int b) { return b >= 0 ? m.bodies[b].position : Eigen::Vector3d::Zero(); }

void add_element(const InputNode& e, Model& m, double side_sign, const std::string& suffix) {
  const std::string type = e.string("type");
  const std::string name = e.string("name") + suffix;
  if (element_name_taken(m, name))
    e.at("name").fail("duplicate element name '" + name + "' (each element needs its own name; a second element "
                      "of the same name would add a second suspension)");
  auto mirror = [&](Eigen::Vector3d p) {
    p.y() *= side_sign;
    return p;
  };
  if (type == "anti_roll_bar") {
    e.allow_only({"type", "name", "body", "other", "stiffness"});
    AntiRollBar a;
    a.name = name;
    a.body_a = body_ref(e.at("body"), m, false);
    a.body_b = body_ref(e.at("other"), m, true);
    check_ends(e, a.body_a, a.body_b);
    a.stiffness = e.non_negative("stiffness");
    m.anti_roll_bars.push_back(a);
    return;
  }
  const int a = body_ref(e.at("body"), m, false);
  const int b = body_ref(e.at("other"), m, true);
  check_ends(e, a, b);
  const Eigen::Vector3d at = mirror(vec3(e.at("at"), false));
  const Eigen::Vector3d other_at = e.has("other_at") ? mirror(vec3(e.at("other_at"), false)) : at;
  const Eigen::Vector3d ra = at - centre(m, a), rb = other_at - centre(m, b);
  if (type == "spring_damper") {
    e.allow_only({"type", "name", "body", "other", "at", "other_at", "stiffness", "damping", "sides"});
    SpringDamper s;
    s.name = name;
    s.body_a = a;
    s.body_b = b;
    s.r_a = ra;
    s.r_b = rb;
    s.k = vec3(e.at("stiffness"), true);
    s.c = e.has("damping") ? vec3(e.at("damping"), true) : Eigen::Vector3d::Zero();
    m.springs.push_back(s);
  } else if (type == "bump_stop") {
    e.allow_only({"type", "name", "body", "other", "at", "other_at", "axis", "table", "sides"});
    BumpStop s;
    s.name = name;
    s.body_a = a;
    s.body_b = b;
    s.r_a = ra;
    s.r_b = rb;
    const std::string ax = e.string("axis");
    if (ax == "x") s.axis = 0;
    else if (ax == "y") s.axis = 1;
    else if (ax == "z") s.axis = 2;
    else e.at("axis").fail("expected x, y or z (got '" + ax + "')");
    for (const auto& row : e.at("table").elements()) {
      const auto v = row.as_numbers();
      if (v.size() != 2) row.fail("expected [deflection, force]");
      if (v[0] < 0 || v[1] < 0) row.fail("deflection and force must be non-negative");
      if (!s.deflection.empty() && v[0] <= s.deflection.back()) row.fail("deflections must increase");
      s.deflection.push_back(v[0]);
      s.force.push_back(v[1]);
    }
    if (s.deflection.size() < 2) e.at("table").fail("expected at least 2 points");
    if (s.force.front() != 0.0) e.at("table").fail("the first point must have zero force (end of free play)");
    m.bump_stops.push_back(s);
  } else if (type == "yaw_damper") {
    e.allow_only({"type", "name", "body", "other", "at", "other_at", "series_stiffness", "damping", "sides"});
    YawDamper y;
    y.name = name;
    y.body_a = a;
    y.body_b = b;
    y.r_a = ra;
    y.r_b = rb;
    y.series_stiffness = e.positive("series_stiffness");
    y.damping = e.positive("damping");
    m.yaw_dampers.push_back(y);
  } else {
    e.at("type").fail("unknown element type '" + type + "' (known: spring_damper, bump_stop, yaw_damper, anti_roll_bar)");
  }
}

}  // namespace

void load_vehicle(const std::string& path, Model& model) { load_vehicle(InputNode::load_file(path), model); }

void load_vehicle(const InputNode& root, Model& m) {
  root.allow_only({"name", "description", "source", "bodies", "elements"});
  m.vehicle_name = root.string("name");
  for (const auto& b : root.at("bodies").elements()) {
    b.allow_only({"name", "type", "mass", "inertia", "position", "dofs"});
    RigidBody body;
    body.name = b.string("name");
    if (body.name == "track") b.at("name").fail("'track' is reserved for the track-following frame");
    if (m.body_index(body.name) >= 0) b.at("name").fail("duplicate body name '" + body.name + "'");
    body.mass = b.in_range("mass", kMinBodyMass, kMaxBodyMass);
    body.inertia = vec3(b.at("inertia"), true);
    for (int k = 0; k < 3; ++k)
      if (!(body.inertia[k] >= kMinBodyInertia && body.inertia[k] <= kMaxBodyInertia))
        b.at("inertia").fail("inertias must lie in [" + config::format_number(kMinBodyInertia) + ", " +
                             config::format_number(kMaxBodyInertia) + "] kg m^2 (got " +
                             config::format_number(body.inertia[k]) + ")");
    // Principal moments of a rigid body obey Ixx + Iyy >= Izz (and cyclic).
    for (int k = 0; k < 3; ++k) {
      const double i = body.inertia[k], j = body.inertia[(k + 1) % 3], l = body.inertia[(k + 2) % 3];
      if (j + l < i * (1.0 - 1e-9)) {
        static const char* axis[3] = {"Ixx", "Iyy", "Izz"};
        b.at("inertia").fail(std::string("the inertias violate the triangle inequality of a rigid body: ") +
                             axis[(k + 1) % 3] + " + " + axis[(k + 2) % 3] + " = " + config::format_number(j + l) +
                             " < " + axis[k] + " = " + config::format_number(i));
      }
    }
    body.position = vec3(b.at("position"), false);
    const std::string type = b.string("type");
    if (type == "wheelset") {
      if (b.has("dofs")) b.at("dofs").fail("a wheelset's DOFs follow from the wheelset model (lateral or full)");
      body.active = {true, false, false, false, true};
      body.wheelset = static_cast<int>(m.wheelsets.size());
      Wheelset w;
      w.name = body.name;
      w.body = static_cast<int>(m.bodies.size());
      m.wheelsets.push_back(w);
    } else if (type == "rigid") {
      body.active = {true, true, true, true, true};
      if (auto d = b.find("dofs")) {
        body.active.fill(false);
        for (const auto& n : d->elements()) {
          const std::string s = n.as_string();
          int k = -1;
          for (int j = 0; j < kNumDof; ++j)
            if (s == dof_name(j)) k = j;
          if (k < 0) n.fail("unknown DOF '" + s + "' (known: lateral, vertical, roll, pitch, yaw)");
          body.active[k] = true;
        }
      }
    } else {
      b.at("type").fail("expected 'wheelset' or 'rigid' (got '" + type + "')");
    }
    m.bodies.push_back(body);
  }
  if (m.wheelsets.empty()) root.at("bodies").fail("a vehicle needs at least one wheelset");
  if (auto els = root.find("elements"))
    for (const auto& e : els->elements()) {
      const std::string sides = e.string_or("sides", "one");
      if (sides == "both") {
        add_element(e, m, 1.0, "_L");
        add_element(e, m, -1.0, "_R");
      } else if (sides == "one") {
        add_element(e, m, 1.0, "");
      } else {
        e.at("sides").fail("expected 'one' or 'both' (got '" + sides + "')");
      }
    }
}

}  // namespace railsim::engine
