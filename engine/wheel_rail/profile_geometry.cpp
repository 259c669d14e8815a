// Engine contact geometry from wheel and rail profiles; see profile_geometry.hpp.
#include "engine/wheel_rail/profile_geometry.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "contact/geometry/profile.hpp"
#include "contact/hertz.hpp"
#include "engine/wheel_rail/strip_patches.hpp"

namespace railsim::engine {

namespace {

contact::StripContactTable make_table(const ProfileGeometryParams& p) {
  const contact::Profile wheel = contact::read_profile(p.wheel, contact::ProfileKind::wheel);
  const contact::Profile rail = contact::read_profile(p.rail, contact::ProfileKind::rail);
  p.setup.validate();
  p.grid.validate();
  const contact::WheelRailGeometry geometry(wheel, rail, p.setup);
  bool cached = false;
  auto table = contact::StripContactTable::cached(geometry, wheel, rail, p.grid, p.cache_dir, &cached);
  spdlog::debug("profile geometry {} on {}: strip table {} ({} strips, {} stored entries)", p.wheel, p.rail,
                cached ? "from the cache" : "computed", table.strip_count(), table.stored_entries());
  return table;
}

}  // namespace

ProfileGeometry::ProfileGeometry(const ProfileGeometryParams& params, const contact::Material& material)
    : table_(make_table(params)), material_(material) {
  Es_ = material_.E / (2.0 * (1.0 - material_.nu * material_.nu));
  // The symmetric use needs the table on both sides of zero.
  s_max_ = std::min(-table_.y_min(), table_.y_max());
  const ContactPointGeometry c = main_point(0.0);
  r0_ = c.rolling_radius;
  l0_ = c.lateral;
  char buf[320];
  std::snprintf(buf, sizeof buf,
                "profiles %s on %s, inclination %.5f rad, gauge %.4f m, |y| <= %.1f mm, |yaw| <= %.0f mrad, "
                "strips %.2g mm",
                params.wheel.c_str(), params.rail.c_str(), params.setup.inclination, params.setup.gauge,
                s_max_ * 1e3, table_.yaw_max() * 1e3, params.grid.strip * 1e3);
  description_ = buf;
}

bool ProfileGeometry::strips(double s, double yaw, double cutoff, contact::StripSet& out) const {
  table_.strips(s, yaw, cutoff, out);
  return true;
}

bool ProfileGeometry::rigid_pose(double y, double yaw, RigidPose& out) const {
  contact::StripPose p;
  table_.pose(y, yaw, p);
  out.roll = p.roll;  // positive lifts the left (+y) side
  out.droll_dy = p.droll_dy;
  out.height = p.height;
  out.dheight_dy = p.dheight_dy;
  return true;
}

void ProfileGeometry::evaluate(double s, double yaw, WheelGeometry& out) const {
  contact::StripSet set;
  table_.strips(s, yaw, kGapCutoff, set);
  contact::StripPose pose;
  table_.pose(s, yaw, pose);
  StripLoads loads;
  strip_approach_for_load(set, kReferenceLoad, 0.0, Es_, loads);
  out.n = loads.n;
  for (int k = 0; k < loads.n; ++k) {
    ContactPointGeometry& c = out.p[k];
    c = loads.patch[k];
    const double N = loads.N[k];
    if (c.A > 0 && c.B > 0 && N > 0) {
      const contact::HertzPatch h = contact::hertz_from_load(c.A, c.B, N, material_);
      c.semi_a = h.a;
      c.semi_b = h.b;
      c.N0 = N;
      c.q0 = h.approach;
    }
  }
  // Most loaded first.
  std::sort(out.p, out.p + out.n, [](const ContactPointGeometry& a, const ContactPointGeometry& b) { return a.N0 > b.N0; });
}

}  // namespace railsim::engine
