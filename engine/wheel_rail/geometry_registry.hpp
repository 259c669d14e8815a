// Wheel-rail contact geometries chosen by name: `contact.geometry.type` of a
// scenario. Each kind has a reader that checks its YAML map (keys, ranges,
// files relative to the scenario) and builds the immutable geometry once.
//
//   conical   cones with an optional flange spring      (conical_geometry.hpp)
//   table     an RSGEO-format geometry file              (geometry_table.hpp)
//   profiles  wheel and rail profiles, strips with yaw   (profile_geometry.hpp)
//
// Adding a geometry: implement ContactGeometry (contact_geometry.hpp) in a
// file of its own, write its reader in geometry_registry.cpp, add a row to
// geometry_kinds(). Nothing else dispatches on the name.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "config/yaml_input.hpp"
#include "contact/geometry/wheel_rail_geometry.hpp"
#include "contact/types.hpp"
#include "engine/wheel_rail/contact_geometry.hpp"

namespace railsim::engine {

// What a geometry reader needs besides its YAML map.
struct GeometryReadContext {
  std::string base_dir;                             // folder of the scenario (relative file names)
  contact::Material material;                       // the scenario's contact material
  std::vector<std::string>* warnings = nullptr;     // physics-sanity warnings of the scenario
  double track_gauge = 0.0;                         // the track file's gauge [m]; 0: not stated (1.435 m)
};

using GeometryReader = std::shared_ptr<const ContactGeometry> (*)(const config::InputNode& node,
                                                                  const GeometryReadContext& context);

struct GeometryKind {
  const char* name;
  const char* description;
  GeometryReader read;
  // Whether the geometry carries its own contact patch at a reference load
  // (a table's semi-axes, the profiles' strips); conical wheels need the
  // scenario's patch, curvatures or creep coefficients.
  bool carries_patch;
};

const std::vector<GeometryKind>& geometry_kinds();
std::string geometry_kind_names();
// The kind named by node.type; fails naming the key and the known kinds.
const GeometryKind& find_geometry_kind(const config::InputNode& node);
// Reads `node` (a scenario's contact.geometry) with its kind's reader.
std::shared_ptr<const ContactGeometry> read_geometry(const config::InputNode& node, const GeometryReadContext& context);

// Track set-up of a wheel-rail pair from a YAML map (inclination, default 1/40;
// gauge, gauge_depth, flange_back, back_face; the wheel radius under
// `radius_key`), each checked against its admissible range.
contact::TrackSetup read_track_setup(const config::InputNode& node, const std::string& radius_key);

}  // namespace railsim::engine
