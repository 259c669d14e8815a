// Shared command-line options of the wheel-rail geometry commands
// (`railsim geometry`, `railsim conicity`): profiles, track set-up, y grid.
#pragma once

#include <CLI/CLI.hpp>

#include <memory>
#include <string>

#include "contact/geometry/contact_table.hpp"

namespace railsim::cli {

struct GeometryOptions {
  std::string wheel = "S1002";
  std::string rail = "UIC60";
  std::string wheel_units;  // "", "mm", "m"
  std::string rail_units;
  std::string inclination = "1/40";
  double gauge = 1.435;
  double flange_back = 1.360;
  double back_face = -0.070;
  double radius = 0.46;
  double gauge_depth = 0.014;
  double y_min = -0.012, y_max = 0.012, y_step = 1e-4;
  std::string cache_dir;
  bool no_cache = false;
};

void add_geometry_options(CLI::App& cmd, GeometryOptions& o);

struct GeometrySetup {
  std::unique_ptr<contact::Profile> wheel, rail;
  std::unique_ptr<contact::WheelRailGeometry> geometry;
  contact::TableGrid grid;
};
GeometrySetup make_geometry(const GeometryOptions& o);
// Build or load the table; logs the time and whether the cache was used.
contact::ContactTable make_table(const GeometryOptions& o, const GeometrySetup& g);

}  // namespace railsim::cli
