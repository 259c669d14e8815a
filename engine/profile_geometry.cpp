// Engine contact geometry from wheel and rail profiles; see profile_geometry.hpp.
#include "engine/profile_geometry.hpp"

#include <spdlog/spdlog.h>

#include <cmath>
#include <cstdio>

#include "contact/geometry/profile.hpp"
#include "contact/hertz.hpp"

namespace railsim::engine {

namespace {

contact::ContactTable make_table(const ProfileGeometryParams& p) {
  const contact::Profile wheel = contact::read_profile(p.wheel, contact::ProfileKind::wheel);
  const contact::Profile rail = contact::read_profile(p.rail, contact::ProfileKind::rail);
  p.setup.validate();
  p.grid.validate();
  const contact::WheelRailGeometry geometry(wheel, rail, p.setup);
  bool cached = false;
  auto table = contact::ContactTable::cached(geometry, wheel, rail, p.grid, p.cache_dir, &cached);
  spdlog::debug("profile geometry {} on {}: contact table {} ({} rows)", p.wheel, p.rail,
                cached ? "from the cache" : "computed", table.rows());
  return table;
}

}  // namespace

ProfileGeometry::ProfileGeometry(const ProfileGeometryParams& params, const contact::Material& material)
    : table_(make_table(params)), material_(material) {
  // The symmetric use needs the table on both sides of zero.
  s_max_ = std::min(-params.grid.y_min, params.grid.y_max);
  WheelContact c;
  evaluate(0.0, c);
  r0_ = c.rolling_radius;
  l0_ = c.lateral;
  char buf[256];
  std::snprintf(buf, sizeof buf, "profiles %s on %s, inclination %.5f rad, gauge %.4f m, |y| <= %.1f mm",
                params.wheel.c_str(), params.rail.c_str(), params.setup.inclination, params.setup.gauge,
                s_max_ * 1e3);
  description_ = buf;
}

void ProfileGeometry::evaluate(double s, WheelContact& out) const {
  contact::TableSample t;
  table_.lookup(s, t);
  const contact::ContactPoint& p = t.wheel[static_cast<int>(contact::Side::left)].p[0];
  out = WheelContact{};
  out.rolling_radius = p.radius;
  out.contact_angle = p.angle;
  out.lateral = p.y - s;
  out.A = p.A;
  out.B = p.B;
  const contact::HertzPatch h = contact::hertz_from_load(p.A, p.B, kReferenceLoad, material_);
  out.semi_a = h.a;
  out.semi_b = h.b;
  out.N0 = kReferenceLoad;
  out.q0 = h.approach;
}

}  // namespace railsim::engine
