// Shared options of the geometry commands (see support_geometry.hpp).
#include "cli/support_geometry.hpp"

#include <spdlog/spdlog.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <string>
#include <utility>

#include "core/errors.hpp"

namespace railsim::cli {

namespace {

// The library's range checks name its own keys ('gauge', 'y step'); on the
// command line the message leads with the option that set the value.
template <class Check>
void checked_as_options(const Check& check) {
  static const std::pair<const char*, const char*> kOptionOf[] = {
      {"'flange_back' must be smaller", "--flange-back/--gauge"},
      {"'gauge'", "--gauge"},
      {"'gauge_depth'", "--gauge-depth"},
      {"'flange_back'", "--flange-back"},
      {"'back_face'", "--back-face"},
      {"'r0 ", "--radius"},
      {"'inclination'", "--inclination"},
      {"y range", "--y-min/--y-max"},
      {"y step", "--y-step"},
      {"rows requested", "--y-step"},
  };
  try {
    check();
  } catch (const InputError& e) {
    const std::string msg = e.what();
    for (const auto& [key, option] : kOptionOf)
      if (msg.find(key) != std::string::npos) throw InputError(std::string(option) + ": " + msg);
    throw;
  }
}

}  // namespace

void add_geometry_options(CLI::App& cmd, GeometryOptions& o) {
  cmd.add_option("--wheel", o.wheel, "Wheel profile: file (.prw, .csv) or shipped name S1002")->capture_default_str();
  cmd.add_option("--rail", o.rail,
                 "Rail profile: file (.prr, .csv) or shipped name UIC60 (upright) / UIC60_MBench (already canted 1/40)")
      ->capture_default_str();
  cmd.add_option("--wheel-units", o.wheel_units, "Length unit of a CSV wheel file when not stated in it: mm or m")
      ->check(CLI::IsMember({"mm", "m"}));
  cmd.add_option("--rail-units", o.rail_units, "Length unit of a CSV rail file when not stated in it: mm or m")
      ->check(CLI::IsMember({"mm", "m"}));
  cmd.add_option("--inclination", o.inclination, "Rail inclination applied to the rail profile: 1/40, 1/20, none")
      ->capture_default_str();
  cmd.add_option("--gauge", o.gauge, "Track gauge [m], measured --gauge-depth below the top of rail")->capture_default_str();
  cmd.add_option("--gauge-depth", o.gauge_depth, "Depth below the top of rail of the gauge points [m]")->capture_default_str();
  cmd.add_option("--flange-back", o.flange_back, "Flange-back (back-to-back) distance [m]")->capture_default_str();
  cmd.add_option("--back-face", o.back_face, "Wheel-profile y of the flange back face [m] (S1002: -0.070)")->capture_default_str();
  cmd.add_option("--radius", o.radius, "Nominal rolling radius at the wheel-profile origin [m]")->capture_default_str();
  cmd.add_option("--y-min", o.y_min, "Smallest lateral shift [m] (positive to the left)")->capture_default_str();
  cmd.add_option("--y-max", o.y_max, "Largest lateral shift [m]")->capture_default_str();
  cmd.add_option("--y-step", o.y_step, "Lateral shift step [m]")->capture_default_str();
  cmd.add_option("--cache-dir", o.cache_dir, "Contact-table cache folder (default $RAILSIM_CACHE_DIR, $XDG_CACHE_HOME/railsim or ~/.cache/railsim)");
  cmd.add_flag("--no-cache", o.no_cache, "Always compute the table; do not read or write the cache");
}

GeometrySetup make_geometry(const GeometryOptions& o) {
  GeometrySetup g;
  contact::ProfileReadOptions wo, ro;
  if (!o.wheel_units.empty()) wo.unit = o.wheel_units == "mm" ? 1e-3 : 1.0;
  if (!o.rail_units.empty()) ro.unit = o.rail_units == "mm" ? 1e-3 : 1.0;
  g.wheel = std::make_unique<contact::Profile>(contact::read_profile(o.wheel, contact::ProfileKind::wheel, wo));
  g.rail = std::make_unique<contact::Profile>(contact::read_profile(o.rail, contact::ProfileKind::rail, ro));
  contact::TrackSetup ts;
  ts.gauge = o.gauge;
  ts.gauge_depth = o.gauge_depth;
  ts.flange_back = o.flange_back;
  ts.back_face = o.back_face;
  ts.r0 = o.radius;
  ts.inclination = contact::parse_inclination(o.inclination, "--inclination");
  checked_as_options([&] { ts.validate(); });
  if (ts.inclination != 0.0 && g.rail->source().find("MBench_UIC60") != std::string::npos && g.rail->source().find("upright") == std::string::npos)
    spdlog::warn("rail profile {} is already canted 1/40; with --inclination {} it is canted twice", g.rail->source(),
                 o.inclination);
  g.geometry = std::make_unique<contact::WheelRailGeometry>(*g.wheel, *g.rail, ts);
  g.grid.y_min = o.y_min;
  g.grid.y_max = o.y_max;
  g.grid.y_step = o.y_step;
  checked_as_options([&] { g.grid.validate(); });
  return g;
}

contact::ContactTable make_table(const GeometryOptions& o, const GeometrySetup& g) {
  const auto t0 = std::chrono::steady_clock::now();
  bool from_cache = false;
  contact::ContactTable t;
  try {
    t = o.no_cache ? contact::ContactTable::build(*g.geometry, g.grid)
                   : contact::ContactTable::cached(*g.geometry, *g.wheel, *g.rail, g.grid, o.cache_dir, &from_cache);
  } catch (const InputError& e) {
    // A pose the profiles cannot take within the y range: the set-up that made it.
    const std::string msg = e.what();
    if (msg.find("puts both wheels on their rails") != std::string::npos ||
        msg.find("within 1 mm of the end of its profile") != std::string::npos)
      throw InputError("--wheel " + o.wheel + " / --rail " + o.rail + " with --gauge, --flange-back, --back-face, "
                       "--inclination as given: " + msg + " (a rail profile given as the wheel, or a gauge and "
                       "flange-back spacing the wheelset cannot sit in?)");
    throw;
  }
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  spdlog::info("contact table: {} rows, {} in {:.1f} ms", t.rows(), from_cache ? "read from cache" : "computed", ms);
  return t;
}

}  // namespace railsim::cli
