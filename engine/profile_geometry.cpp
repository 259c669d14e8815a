// Engine contact geometry from wheel and rail profiles; see profile_geometry.hpp.
#include "engine/profile_geometry.hpp"

#include <spdlog/spdlog.h>

#include <cmath>
#include <algorithm>
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
  {
    contact::TableSample t;
    table_.lookup(0.0, t);
    z0_ = t.z;
  }
  const ContactPointGeometry c = main_point(0.0);
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
// approach at the reference load; gap = q0 + (normal gap at the rigid pose),
// so that the load law gives K (dq - gap_n)^{3/2} (contact_geometry.hpp).
void fill(const contact::ContactPoint& p, double s, const contact::Material& material, ContactPointGeometry& out) {
  out = ContactPointGeometry{};
  out.rolling_radius = p.radius;
  out.contact_angle = p.angle;
  out.lateral = p.y - s;
  out.lead = p.x;
  out.A = p.A;
  out.B = p.B;
  const contact::HertzPatch h = contact::hertz_from_load(p.A, p.B, ProfileGeometry::kReferenceLoad, material);
  out.semi_a = h.a;
  out.semi_b = h.b;
  out.N0 = ProfileGeometry::kReferenceLoad;
  out.q0 = h.approach;
  out.gap = out.q0 + p.gap;
}

}  // namespace

void ProfileGeometry::evaluate(double s, double yaw, WheelGeometry& out) const {
  (void)yaw;
  contact::TableSample t;
  table_.lookup(s, t);
  const contact::WheelContact& w = t.wheel[static_cast<int>(contact::Side::left)];
  out.n = std::min(w.n, WheelGeometry::kMaxPoints);
  for (int k = 0; k < out.n; ++k) fill(w.p[static_cast<std::size_t>(k)], s, material_, out.p[k]);
}

bool ProfileGeometry::rigid_pose(double y, double yaw, RigidPose& out) const {
  (void)yaw;
  contact::TableSample t, a, b;
  const double h = 1e-6;
  const double y0 = std::clamp(y, -s_max_ + h, s_max_ - h);
  table_.lookup(y0, t);
  table_.lookup(y0 - h, a);
  table_.lookup(y0 + h, b);
  out.roll = t.roll;  // the table's roll: positive lifts the left (+y) side
  out.droll_dy = (b.roll - a.roll) / (2 * h);
  out.height = t.z - z0_;
  out.dheight_dy = (b.z - a.z) / (2 * h);
  return true;
}

}  // namespace railsim::engine
