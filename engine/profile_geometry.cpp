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
// approach at the reference load.
void fill(const contact::ContactPoint& p, double s, const contact::Material& material, WheelContact& out) {
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
}

}  // namespace

void ProfileGeometry::evaluate(double s, WheelContact& out) const {
  contact::TableSample t;
  table_.lookup(s, t);
  fill(t.wheel[static_cast<int>(contact::Side::left)].p[0], s, material_, out);
}

double ProfileGeometry::rigid_roll(double y) const {
  contact::TableSample t;
  table_.lookup(y, t);
  return t.roll;  // the table's roll: positive lifts the left (+y) side
}

void ProfileGeometry::evaluate_point(double s, int k, WheelContact& out) const {
  if (k == 0) return evaluate(s, out);
  contact::TableSample t;
  table_.lookup(s, t);
  const contact::WheelContact& w = t.wheel[static_cast<int>(contact::Side::left)];
  if (k >= w.n) {
    out = WheelContact{};  // N0 = 0: no such point at this shift
    return;
  }
  WheelContact main;
  fill(w.p[0], s, material_, main);
  fill(w.p[static_cast<std::size_t>(k)], s, material_, out);
  // Shared vertical approach of the wheel (see the header): the reference
  // normal approach of this point is q_ref = (q0_main / cos(d_0) - v_k) cos(d_k)
  // with v_k its vertical gap above the main point's (the table's gaps are
  // normal gaps; between rows the main point's own gap may be > 0), written as
  // the offset gap = q0_k - q_ref of the engine's load law.
  const contact::ContactPoint& p0 = w.p[0];
  const contact::ContactPoint& pk = w.p[static_cast<std::size_t>(k)];
  const double v = pk.gap / std::cos(pk.angle) - p0.gap / std::cos(p0.angle);
  const double q_ref = (main.q0 / std::cos(main.contact_angle) - v) * std::cos(out.contact_angle);
  out.gap = out.q0 - q_ref;
}

}  // namespace railsim::engine
