// Contact-geometry registry and the readers of its kinds; see geometry_registry.hpp.
#include "engine/wheel_rail/geometry_registry.hpp"

#include <spdlog/spdlog.h>

#include <cmath>
#include <filesystem>
#include <tuple>

#include "contact/geometry/profile.hpp"
#include "core/errors.hpp"
#include "engine/wheel_rail/conical_geometry.hpp"
#include "engine/wheel_rail/geometry_table.hpp"
#include "engine/wheel_rail/profile_geometry.hpp"

namespace railsim::engine {
namespace {

using config::InputNode;
namespace fs = std::filesystem;

// Geometries that carry their own gauge (a table's rows, cones) cannot take
// the track file's: a gauge other than the standard one is said in the
// scenario's warnings (the run goes on with the geometry as it is).
void warn_track_gauge_unused(const InputNode& g, const GeometryReadContext& ctx, const char* kind) {
  if (!(ctx.track_gauge > 0.0) || std::abs(ctx.track_gauge - 1.435) <= 5e-4 || !ctx.warnings) return;
  ctx.warnings->push_back(g.where() + ": the track file's gauge " + config::format_number(ctx.track_gauge) +
                          " m is not used by the '" + kind + "' contact geometry, which stands for its own gauge "
                          "(use type: profiles to run on the track's gauge)");
  spdlog::warn("{}", ctx.warnings->back());
}

std::shared_ptr<const ContactGeometry> read_conical(const InputNode& g, const GeometryReadContext& ctx) {
  warn_track_gauge_unused(g, ctx, "conical");
  g.allow_only({"type", "r0", "conicity", "l0", "contact_angle", "flange_clearance", "flange_stiffness", "max_shift",
                "curvatures"});
  ConicalParams p;
  p.r0 = g.in_range("r0", 0.1, 1.5);
  p.conicity = g.in_range("conicity", 0.0, 1.0);
  p.l0 = g.in_range("l0", 0.3, 1.5);
  p.contact_angle = g.has("contact_angle") ? g.in_range("contact_angle", -1.5, 1.5) : 0.0;
  p.flange_clearance = g.has("flange_clearance") ? g.non_negative("flange_clearance") : 0.0;
  p.flange_stiffness = g.has("flange_stiffness") ? g.non_negative("flange_stiffness") : 0.0;
  p.max_shift = g.has("max_shift") ? g.in_range("max_shift", 0.0, 0.2, true) : 0.05;
  if (auto cv = g.find("curvatures")) {
    cv->allow_only({"A", "B"});
    p.A = cv->positive("A");
    p.B = cv->positive("B");
  }
  return std::make_shared<ConicalGeometry>(p);
}

std::shared_ptr<const ContactGeometry> read_table(const InputNode& g, const GeometryReadContext& ctx) {
  g.allow_only({"type", "file", "node_step", "smoothing"});
  warn_track_gauge_unused(g, ctx, "table");
  GeometryTableOptions o;
  if (g.has("node_step")) o.node_step = g.in_range("node_step", 1e-6, 2e-3);
  if (g.has("smoothing")) o.smoothing = g.in_range("smoothing", 0.0, 2e-3);
  auto table = std::make_shared<GeometryTable>(g.at("file").as_existing_file(ctx.base_dir), o);
  spdlog::info("contact geometry: {}; largest deviation of the fit from the rows: {}", table->describe(),
               table->deviation_report());
  return table;
}

// A profile key: a file relative to the scenario, or a shipped profile name.
std::string profile_source(const InputNode& g, const char* key, const std::string& fallback,
                           const GeometryReadContext& ctx) {
  if (!g.has(key)) return fallback;
  const std::string v = g.string(key);
  const std::string path = fs::path(v).is_absolute() ? v : (fs::path(ctx.base_dir) / v).lexically_normal().string();
  std::error_code ec;
  if (fs::exists(path, ec)) return path;
  if (!contact::is_shipped_profile_name(v))
    g.at(key).fail("file '" + v + "' not found (looked for " + path + ") and not a shipped profile name (" +
                   contact::shipped_profile_names() + ")");
  return v;
}

std::shared_ptr<const ContactGeometry> read_profiles(const InputNode& g, const GeometryReadContext& ctx) {
  g.allow_only({"type", "wheel", "rail", "inclination", "gauge", "gauge_depth", "flange_back", "back_face", "r0",
                "max_shift", "step", "max_yaw", "yaw_step", "strip", "cache_dir"});
  ProfileGeometryParams p;
  p.wheel = profile_source(g, "wheel", p.wheel, ctx);
  p.rail = profile_source(g, "rail", p.rail, ctx);
  // Physics sanity: profile widths outside the usual range (a warning in the run's summary).
  for (const auto& [key, path, kind] : {std::tuple{"wheel", p.wheel, contact::ProfileKind::wheel},
                                        std::tuple{"rail", p.rail, contact::ProfileKind::rail}}) {
    const std::string w = contact::profile_width_warning(contact::read_profile(path, kind));
    if (w.empty() || !ctx.warnings) continue;
    ctx.warnings->push_back((g.has(key) ? g.at(key).where() : g.where()) + ": key 'contact.geometry." + key +
                            "': " + w);
    spdlog::warn("{}", ctx.warnings->back());
  }
  p.setup = read_track_setup(g, "r0");
  // The gauge of the track the wheels run on: the track file's, unless the
  // geometry states its own, which must then be the same.
  if (ctx.track_gauge > 0.0) {
    if (!g.has("gauge")) p.setup.gauge = ctx.track_gauge;
    else if (std::abs(p.setup.gauge - ctx.track_gauge) > 5e-4)
      g.at("gauge").fail("contact.geometry.gauge " + config::format_number(p.setup.gauge) +
                         " m differs from the track file's gauge " + config::format_number(ctx.track_gauge) +
                         " m: give one of them (the geometry then uses the track's)");
  }
  const double s_max = g.has("max_shift") ? g.in_range("max_shift", 0.002, 0.02) : 0.015;
  p.grid.y_min = -s_max;
  p.grid.y_max = s_max;
  if (g.has("step")) p.grid.y_step = g.in_range("step", 1e-5, 1e-3);
  if (g.has("max_yaw")) p.grid.yaw_max = g.in_range("max_yaw", 0.0, 0.1);
  if (g.has("yaw_step")) p.grid.yaw_step = g.in_range("yaw_step", 1e-4, 0.05);
  if (g.has("strip")) p.grid.strip = g.in_range("strip", 1e-4, 5e-3);
  if (g.has("cache_dir")) {
    const std::string d = g.string("cache_dir");
    p.cache_dir = fs::path(d).is_absolute() ? d : (fs::path(ctx.base_dir) / d).lexically_normal().string();
  }
  try {
    return std::make_shared<ProfileGeometry>(p, ctx.material);
  } catch (const InputError& e) {
    if (!(ctx.track_gauge > 0.0) || g.has("gauge")) throw;
    g.fail(std::string(e.what()) + " (with the track file's gauge " + config::format_number(ctx.track_gauge) +
           " m, which the profiles geometry takes: a vehicle for another gauge? give flange_back for it)");
  }
}

}  // namespace

const std::vector<GeometryKind>& geometry_kinds() {
  static const std::vector<GeometryKind> kinds = {
      {"conical", "conical wheels on knife-edge rails, optional flange spring", &read_conical, false},
      {"table", "RSGEO-format contact-geometry file (shift-indexed rows)", &read_table, true},
      {"profiles", "wheel and rail profiles: strips over shift and yaw", &read_profiles, true},
  };
  return kinds;
}

std::string geometry_kind_names() {
  std::string s;
  for (const auto& k : geometry_kinds()) s += (s.empty() ? "'" : ", '") + std::string(k.name) + "'";
  return s;
}

const GeometryKind& find_geometry_kind(const InputNode& node) {
  const InputNode t = node.at("type");
  const std::string type = t.as_string();
  for (const auto& k : geometry_kinds())
    if (type == k.name) return k;
  t.fail("expected one of " + geometry_kind_names() + " (got '" + type + "')");
}

std::shared_ptr<const ContactGeometry> read_geometry(const InputNode& node, const GeometryReadContext& context) {
  return find_geometry_kind(node).read(node, context);
}

contact::TrackSetup read_track_setup(const InputNode& g, const std::string& radius_key) {
  contact::TrackSetup t;
  if (g.has("inclination")) {
    const InputNode n = g.at("inclination");
    t.inclination = contact::parse_inclination(n.as_string(), n.where() + ": key 'inclination'");
  } else {
    t.inclination = std::atan(1.0 / 40.0);
  }
  if (g.has("gauge")) t.gauge = g.in_range("gauge", 0.9, 1.8);
  if (g.has("gauge_depth")) t.gauge_depth = g.in_range("gauge_depth", 0.0, 0.03, true);  // (0: the top itself)
  if (g.has("flange_back")) t.flange_back = g.in_range("flange_back", 0.8, 1.8);
  if (g.has("back_face")) t.back_face = g.in_range("back_face", -0.2, 0.0);
  if (g.has(radius_key)) t.r0 = g.in_range(radius_key, 0.1, 1.5);
  // The flange backs lie inside the running edges (1.360 m within 1.435 m).
  if (!(t.flange_back < t.gauge)) {
    const InputNode& n = g.has("flange_back") ? g.at("flange_back") : g.at("gauge");
    n.fail("flange_back " + config::format_number(t.flange_back) + " m" +
           (g.has("flange_back") ? "" : " (the default)") + " is not smaller than gauge " +
           config::format_number(t.gauge) + " m" + (g.has("gauge") ? "" : " (the default)") +
           ": the flange backs lie inside the rails' running edges (1.360 m within 1.435 m for standard gauge)");
  }
  return t;
}

}  // namespace railsim::engine
