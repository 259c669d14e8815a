// The force-element registry (engine/elements/element_registry.hpp): each
// kind by name lands in its own list of the model with its parameters, points
// relative to the bodies' centres and mirrored in y for `sides: both`; an
// unknown kind names the file, line, key and the known kinds.
#include <catch2/catch.hpp>

#include "config/yaml_input.hpp"
#include "core/errors.hpp"
#include "engine/elements/element_registry.hpp"
#include "engine/io/vehicle_file.hpp"

using namespace railsim;
using config::InputNode;

namespace {
const char* kVehicle = R"(name: test
bodies:
  - {name: ws1, type: wheelset, mass: 1500, inertia: [800, 100, 800], position: [1.25, 0, 0.46]}
  - {name: bogie, type: rigid, mass: 2500, inertia: [1500, 1500, 2500], position: [0, 0, 0.6]}
elements:
  - {type: spring_damper, name: prim, body: ws1, other: bogie, at: [1.25, 1.0, 0.46], stiffness: [1e6, 2e6, 3e6],
     damping: [0, 0, 1e4], sides: both}
  - {type: bump_stop, name: stop, body: bogie, other: track, at: [0, 0, 0.6], axis: y, table: [[0.02, 0], [0.03, 5e4]]}
  - {type: yaw_damper, name: yd, body: bogie, other: track, at: [0, 1.2, 0.6], series_stiffness: 5e6, damping: 2e5}
  - {type: anti_roll_bar, name: arb, body: bogie, other: track, stiffness: 9.4e5}
)";
}  // namespace

TEST_CASE("element registry: every kind by name, sides mirrored", "[engine][elements]") {
  std::vector<std::string> names;
  for (const auto& k : engine::element_kinds()) names.emplace_back(k.name);
  CHECK(names == std::vector<std::string>{"spring_damper", "bump_stop", "yaw_damper", "anti_roll_bar"});
  engine::Model m;
  engine::load_vehicle(InputNode::load_string(kVehicle, "v.yaml"), m);
  REQUIRE(m.springs.size() == 2);
  CHECK(m.springs[0].name == "prim_L");
  CHECK(m.springs[1].name == "prim_R");
  // Points relative to the body centres; the right side mirrored in y.
  CHECK(m.springs[0].r_a.y() == Approx(1.0));
  CHECK(m.springs[1].r_a.y() == Approx(-1.0));
  CHECK(m.springs[0].r_b.x() == Approx(1.25));
  CHECK(m.springs[0].r_b.z() == Approx(0.46 - 0.6));
  CHECK(m.springs[1].k.y() == Approx(2e6));
  REQUIRE(m.bump_stops.size() == 1);
  CHECK(m.bump_stops[0].axis == 1);
  CHECK(m.bump_stops[0].body_b == -1);  // the track frame
  REQUIRE(m.yaw_dampers.size() == 1);
  CHECK(m.yaw_dampers[0].damping == Approx(2e5));
  REQUIRE(m.anti_roll_bars.size() == 1);
  CHECK(m.anti_roll_bars[0].stiffness == Approx(9.4e5));
}

TEST_CASE("element registry: an unknown kind names file, line, key and the kinds", "[engine][elements][bad_input]") {
  std::string text = kVehicle;
  text.replace(text.find("type: yaw_damper"), 16, "type: yaw_dampr");
  engine::Model m;
  std::string msg;
  try {
    engine::load_vehicle(InputNode::load_string(text, "v.yaml"), m);
  } catch (const InputError& e) {
    msg = e.what();
  }
  CHECK(msg == "v.yaml:9: key 'elements[2].type': unknown element type 'yaw_dampr' (known: spring_damper, bump_stop, "
               "yaw_damper, anti_roll_bar)");
}
