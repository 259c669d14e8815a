// Force-element registry and the readers of its kinds; see element_registry.hpp.
#include "engine/elements/element_registry.hpp"

namespace railsim::engine {
namespace {

using config::InputNode;

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

// The two ends of an element: `body` and `other` (a body or the track frame),
// which must differ (from a body to itself an element exerts no net force but
// shifts the reported loads).
std::pair<int, int> ends(const InputNode& e, const Model& m) {
  const int a = body_ref(e.at("body"), m, false);
  const int b = body_ref(e.at("other"), m, true);
  if (a == b)
    e.at("other").fail("element joins body '" + e.string("body") + "' to itself; 'other' must be another body or "
                       "'track'");
  return {a, b};
}

// Attachment of a point element: its ends and the points `at` / `other_at`
// (mirrored by side_sign) relative to the bodies' centres.
struct Attachment {
  int body_a = -1, body_b = -1;
  Eigen::Vector3d r_a, r_b;
};
Attachment attachment(const InputNode& e, const Model& m, double side_sign) {
  Attachment t;
  std::tie(t.body_a, t.body_b) = ends(e, m);
  auto point = [&](const char* key) {
    Eigen::Vector3d p = read_vector3(e.at(key), -kMaxVehicleCoordinate, kMaxVehicleCoordinate, "m");
    p.y() *= side_sign;
    return p;
  };
  auto centre = [&](int b) { return b >= 0 ? m.bodies[b].position : Eigen::Vector3d::Zero(); };
  const Eigen::Vector3d at = point("at");
  const Eigen::Vector3d other_at = e.has("other_at") ? point("other_at") : at;
  t.r_a = at - centre(t.body_a);
  t.r_b = other_at - centre(t.body_b);
  return t;
}

template <class Element>
Element attached(const InputNode& e, const std::string& name, double side_sign, const Model& m) {
  const Attachment t = attachment(e, m, side_sign);
  Element s;
  s.name = name;
  s.body_a = t.body_a;
  s.body_b = t.body_b;
  s.r_a = t.r_a;
  s.r_b = t.r_b;
  return s;
}

void read_spring_damper(const InputNode& e, const std::string& name, double side_sign, Model& m) {
  e.allow_only({"type", "name", "body", "other", "at", "other_at", "stiffness", "damping", "sides"});
  auto s = attached<SpringDamper>(e, name, side_sign, m);
  s.k = read_vector3(e.at("stiffness"), 0.0, kMaxStiffness, "N/m");
  s.c = e.has("damping") ? read_vector3(e.at("damping"), 0.0, kMaxDamping, "N s/m") : Eigen::Vector3d::Zero();
  m.springs.push_back(s);
}

void read_bump_stop(const InputNode& e, const std::string& name, double side_sign, Model& m) {
  e.allow_only({"type", "name", "body", "other", "at", "other_at", "axis", "table", "sides"});
  auto s = attached<BumpStop>(e, name, side_sign, m);
  const std::string ax = e.at("axis").as_choice({"x", "y", "z"});
  s.axis = ax == "x" ? 0 : ax == "y" ? 1 : 2;
  for (const auto& row : e.at("table").elements()) {
    const auto v = row.as_numbers();
    if (v.size() != 2) row.fail("expected [deflection, force]");
    if (!(v[0] >= 0 && v[0] <= kMaxStopDeflection && v[1] >= 0 && v[1] <= kMaxStopForce))
      row.fail("expected a deflection in [0, " + config::format_number(kMaxStopDeflection) + "] m and a force in [0, " +
               config::format_number(kMaxStopForce) + "] N (got [" + config::format_number(v[0]) + ", " +
               config::format_number(v[1]) + "])");
    if (!s.deflection.empty() && v[0] <= s.deflection.back()) row.fail("deflections must increase");
    s.deflection.push_back(v[0]);
    s.force.push_back(v[1]);
  }
  if (s.deflection.size() < 2) e.at("table").fail("expected at least 2 points");
  if (s.force.front() != 0.0) e.at("table").fail("the first point must have zero force (end of free play)");
  m.bump_stops.push_back(s);
}

void read_yaw_damper(const InputNode& e, const std::string& name, double side_sign, Model& m) {
  e.allow_only({"type", "name", "body", "other", "at", "other_at", "series_stiffness", "damping", "sides"});
  auto y = attached<YawDamper>(e, name, side_sign, m);
  y.series_stiffness = e.in_range("series_stiffness", 0.0, kMaxStiffness, true);  // [N/m]
  y.damping = e.in_range("damping", 0.0, kMaxDamping, true);                      // [N s/m]
  m.yaw_dampers.push_back(y);
}

void read_anti_roll_bar(const InputNode& e, const std::string& name, double, Model& m) {
  e.allow_only({"type", "name", "body", "other", "stiffness"});
  AntiRollBar a;
  a.name = name;
  std::tie(a.body_a, a.body_b) = ends(e, m);
  a.stiffness = e.in_range("stiffness", 0.0, kMaxRollStiffness);  // [N m/rad]
  m.anti_roll_bars.push_back(a);
}

// Every element of the model by name (all kinds share one name space).
bool element_name_taken(const Model& m, const std::string& name) {
  auto in = [&](const auto& v) {
    for (const auto& e : v)
      if (e.name == name) return true;
    return false;
  };
  return in(m.springs) || in(m.bump_stops) || in(m.yaw_dampers) || in(m.anti_roll_bars);
}

}  // namespace

Eigen::Vector3d read_vector3(const InputNode& n, double lo, double hi, const char* unit) {
  const auto v = n.as_numbers();
  if (v.size() != 3) n.fail("expected a list of 3 numbers (got " + std::to_string(v.size()) + ")");
  for (double x : v)
    if (!(x >= lo && x <= hi))
      n.fail("expected numbers in [" + config::format_number(lo) + ", " + config::format_number(hi) + "] " + unit +
             " (got " + config::format_number(x) + ")");
  return {v[0], v[1], v[2]};
}

const std::vector<ElementKind>& element_kinds() {
  static const std::vector<ElementKind> kinds = {
      {"spring_damper", "linear springs and dampers per axis between two points", &read_spring_damper},
      {"bump_stop", "one-sided stop along one axis, tabulated force after the free play", &read_bump_stop},
      {"yaw_damper", "damper with series stiffness (Maxwell element)", &read_yaw_damper},
      {"anti_roll_bar", "roll stiffness between two bodies", &read_anti_roll_bar},
  };
  return kinds;
}

std::string element_kind_names() {
  std::string s;
  for (const auto& k : element_kinds()) s += (s.empty() ? "" : ", ") + std::string(k.name);
  return s;
}

void read_element(const InputNode& e, Model& m, double side_sign, const std::string& suffix) {
  const std::string type = e.string("type");
  const std::string name = e.string("name") + suffix;
  if (element_name_taken(m, name))
    e.at("name").fail("duplicate element name '" + name + "' (each element needs its own name; a second element "
                      "of the same name would add a second suspension)");
  for (const auto& k : element_kinds())
    if (type == k.name) return k.read(e, name, side_sign, m);
  e.at("type").fail("unknown element type '" + type + "' (known: " + element_kind_names() + ")");
}

}  // namespace railsim::engine
