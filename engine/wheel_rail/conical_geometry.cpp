// Conical wheel geometry; see conical_geometry.hpp.
#include "engine/wheel_rail/conical_geometry.hpp"

#include <cstdio>

namespace railsim::engine {

void ConicalGeometry::evaluate(double s, double yaw, WheelGeometry& g) const {
  (void)yaw;
  g.n = 1;
  ContactPointGeometry& out = g.p[0];
  out = ContactPointGeometry{};
  out.rolling_radius = p_.r0 + p_.conicity * s;
  out.contact_angle = p_.contact_angle;
  out.lateral = p_.l0;
  out.A = p_.A;
  out.B = p_.B;
  if (p_.flange_stiffness > 0.0 && s > p_.flange_clearance)
    out.flange_force = p_.flange_stiffness * (s - p_.flange_clearance);
}

bool ConicalGeometry::rigid_pose(double y, double yaw, RigidPose& out) const {
  (void)yaw;
  out = RigidPose{};
  out.roll = p_.conicity * y / p_.l0;
  out.droll_dy = p_.conicity / p_.l0;
  return true;
}

std::string ConicalGeometry::describe() const {
  char buf[200];
  std::snprintf(buf, sizeof buf, "conical (r0 = %.4g m, conicity = %.4g, l0 = %.4g m, contact angle = %.4g rad)",
                p_.r0, p_.conicity, p_.l0, p_.contact_angle);
  return buf;
}

}  // namespace railsim::engine
