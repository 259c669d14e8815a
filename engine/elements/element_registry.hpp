// Force elements chosen by name: `elements[].type` of a vehicle file
// (engine/io/vehicle_file.hpp). Each kind has a reader that checks its YAML
// map and appends the element to the model.
//
//   spring_damper  linear springs and dampers per axis     (spring_damper.hpp)
//   bump_stop      tabulated one-sided stop after free play (bump_stop.hpp)
//   yaw_damper     damper with series stiffness (Maxwell)   (yaw_damper.hpp)
//   anti_roll_bar  roll stiffness between two bodies       (anti_roll_bar.hpp)
//
// Adding an element: its struct and force law in a file of its own here, a
// vector of it in Model (model.hpp) with its loop in the equations of motion
// (system.cpp) and in the Jacobian pattern (integrators/jacobian_pattern.cpp),
// its reader in element_registry.cpp and a row in element_kinds().
#pragma once

#include <string>
#include <vector>

#include "config/yaml_input.hpp"
#include "engine/model.hpp"

namespace railsim::engine {

// An element's reader: `name` is the element's name with the side suffix
// (_L / _R for `sides: both`), `side_sign` +1 or -1 mirrors its points in y.
using ElementReader = void (*)(const config::InputNode& node, const std::string& name, double side_sign, Model& model);

struct ElementKind {
  const char* name;
  const char* description;
  ElementReader read;
};

const std::vector<ElementKind>& element_kinds();
std::string element_kind_names();
// Reads one element of a vehicle file (unique name over all kinds, known
// kind, two different bodies) and appends it to `model`.
void read_element(const config::InputNode& node, Model& model, double side_sign, const std::string& suffix);
// A list of 3 finite numbers, each in [lo, hi] (unit for the message):
// positions, inertias, stiffnesses.
Eigen::Vector3d read_vector3(const config::InputNode& node, double lo, double hi, const char* unit);

// Plausible ranges of a vehicle file's values (with decades to spare around
// rail vehicles): points and body positions [m] from the vehicle's centre,
// spring stiffness [N/m], damping [N s/m], anti-roll-bar stiffness [N m/rad],
// bump-stop deflection [m] and force [N].
inline constexpr double kMaxVehicleCoordinate = 50.0;
inline constexpr double kMaxStiffness = 1e10;
inline constexpr double kMaxDamping = 1e8;
inline constexpr double kMaxRollStiffness = 1e9;
inline constexpr double kMaxStopDeflection = 1.0;
inline constexpr double kMaxStopForce = 1e8;

}  // namespace railsim::engine
