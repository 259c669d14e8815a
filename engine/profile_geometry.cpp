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
  // Second points up to 1 mm of vertical gap: they close under the loads of
  // flange contact (the Hertz approach is ~0.1 mm at 100 kN).
  contact::SearchOptions search;
  search.second_gap_max = 1.0e-3;
  const contact::WheelRailGeometry geometry(wheel, rail, p.setup, search);
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
  // Reference vertical approach: the centred wheel's at N0.
  {
    contact::TableSample t;
    table_.lookup(0.0, t);
    const contact::ContactPoint& p = t.wheel[static_cast<int>(contact::Side::left)].p[0];
    const contact::HertzPatch h = contact::hertz_from_load(p.A, p.B, kReferenceLoad, material_);
    w0_ = h.approach / std::cos(p.angle);
  }
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

namespace {

// One tabulated point as the engine sees it, with its Hertz patch and
// approach at the reference load, and the offset `gap` that puts its normal
// approach at the reference state (engine z = 0) at (w0 - v) cos(delta), v its
// vertical gap in the rigid touching position (see the header).
void fill(const contact::ContactPoint& p, double s, double w0, const contact::Material& material,
          WheelContact& out) {
  out = WheelContact{};
  out.rolling_radius = p.radius;
  out.contact_angle = p.angle;
  out.lateral = p.y - s;
  out.A = p.A;
  out.B = p.B;
  const contact::HertzPatch h = contact::hertz_from_load(p.A, p.B, ProfileGeometry::kReferenceLoad, material);
  out.semi_a = h.a;
  out.semi_b = h.b;
  out.N0 = ProfileGeometry::kReferenceLoad;
  out.q0 = h.approach;
  const double cd = std::cos(p.angle);
  out.gap = out.q0 - (w0 - p.gap / cd) * cd;  // table gaps are normal gaps: vertical = gap / cos(delta)
}

}  // namespace

void ProfileGeometry::evaluate(double s, WheelContact& out) const {
  contact::TableSample t;
  table_.lookup(s, t);
  fill(t.wheel[static_cast<int>(contact::Side::left)].p[0], s, w0_, material_, out);
}

double ProfileGeometry::rigid_roll(double y) const {
  contact::TableSample t;
  table_.lookup(y, t);
  return t.roll;  // the table's roll: positive lifts the left (+y) side
}

void ProfileGeometry::evaluate_point(double s, int k, WheelContact& out) const {
  contact::TableSample t;
  table_.lookup(s, t);
  const contact::WheelContact& w = t.wheel[static_cast<int>(contact::Side::left)];
  if (k >= w.n) {
    out = WheelContact{};  // N0 = 0: no such point at this shift
    return;
  }
  fill(w.p[static_cast<std::size_t>(k)], s, w0_, material_, out);
}

}  // namespace railsim::engine
