// Vehicles from YAML (vehicles/*.yaml), read through config::InputNode so
// that every mistake names the file, line, key and allowed range.
//
//   name: manchester_coach
//   description: "..."
//   bodies:
//     - {name: ws1, type: wheelset, mass: 1813, inertia: [1120, 112, 1120], position: [11.78, 0, 0.46]}
//     - {name: car, type: rigid, mass: 32000, inertia: [...], position: [0, 0, 1.8],
//        dofs: [lateral, vertical, roll, pitch, yaw]}          # default: all five
//   elements:
//     - {type: spring_damper, name: prim1, body: ws1, other: bogie1, at: [11.78, 1.0, 0.46],
//        other_at: [...],               # default: same point as `at`
//        stiffness: [kx, ky, kz], damping: [cx, cy, cz], sides: both}
//     - {type: bump_stop, ..., axis: y, table: [[0.025, 0], [0.030, 600], ...]}   # [m, N]
//     - {type: yaw_damper, ..., series_stiffness: 5e6, damping: 2e5}
//     - {type: anti_roll_bar, name, body, other, stiffness: 9.4e5}
// Positions are nominal, in the vehicle frame (x forward from the vehicle
// reference, y left, z above the rail tops). `other: track` ties an element to
// the track-following frame. `sides: both` duplicates an element mirrored in y
// (names get _L / _R). Units SI.
//
// Checked as a whole: masses in [1, 1e6] kg and inertias in [1e-3, 1e8]
// kg m^2 per body, inertias obeying the triangle inequality of a rigid body
// (Ixx + Iyy >= Izz and cyclic), element names unique over all element kinds,
// no element from a body to itself.
#pragma once

#include <string>

#include "config/yaml_input.hpp"
#include "engine/model.hpp"

namespace railsim::engine {

// Sane ranges of a body (README "Exit codes and limits").
inline constexpr double kMinBodyMass = 1.0, kMaxBodyMass = 1e6;          // [kg]
inline constexpr double kMinBodyInertia = 1e-3, kMaxBodyInertia = 1e8;   // [kg m^2]

// Fills model.vehicle_name, bodies, elements and wheelsets (geometry unset).
void load_vehicle(const std::string& path, Model& model);
void load_vehicle(const config::InputNode& root, Model& model);

}  // namespace railsim::engine
