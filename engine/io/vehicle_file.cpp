// Vehicle YAML reader; see vehicle_file.hpp.
#include "engine/io/vehicle_file.hpp"

#include <cmath>
#include <limits>

#include "core/errors.hpp"
#include "engine/elements/element_registry.hpp"

namespace railsim::engine {
using config::InputNode;

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
    body.inertia = read_vector3(b.at("inertia"), 0.0, std::numeric_limits<double>::max(), "kg m^2");  // range below
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
    body.position = read_vector3(b.at("position"), -kMaxVehicleCoordinate, kMaxVehicleCoordinate, "m");
    const std::string type = b.string("type");
    if (type == "wheelset") {
      if (b.has("dofs")) b.at("dofs").fail("a wheelset's DOFs follow from the wheelset model (lateral or full)");
      // A wheelset runs centred on its track frame at its wheels' height; a
      // lateral offset or an odd height was ignored silently.
      if (body.position.y() != 0.0)
        b.at("position").fail("a wheelset's y must be 0 (it runs centred on its track frame; initial deviations "
                              "are the scenario's key 'initial'), got " + config::format_number(body.position.y()));
      if (!(body.position.z() >= 0.1 && body.position.z() <= 1.5))
        b.at("position").fail("a wheelset's z is its axle height, the wheel radius: expected [0.1, 1.5] m, got " +
                              config::format_number(body.position.z()));
      for (const auto& other : m.wheelsets) {
        const RigidBody& ob = m.bodies[std::size_t(other.body)];
        if (std::abs(ob.position.x() - body.position.x()) < 0.5)
          b.at("position").fail("wheelset '" + body.name + "' at x = " + config::format_number(body.position.x()) +
                                " m lies within 0.5 m of wheelset '" + ob.name + "' (x = " +
                                config::format_number(ob.position.x()) + " m)");
      }
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
          if (body.active[k]) n.fail("DOF '" + s + "' given twice");
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
      if (e.choice_or("sides", "one", {"one", "both"}) == "both") {
        read_element(e, m, 1.0, "_L");
        read_element(e, m, -1.0, "_R");
      } else {
        read_element(e, m, 1.0, "");
      }
    }
}

}  // namespace railsim::engine
