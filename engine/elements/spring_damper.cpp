// Linear spring-damper between markers; see spring_damper.hpp.
#include "engine/elements/spring_damper.hpp"

namespace railsim::engine {

void relative_motion(const std::vector<BodyMotion>& m, int a, const Eigen::Vector3d& ra, int b,
                     const Eigen::Vector3d& rb, Eigen::Vector3d& d, Eigen::Vector3d& v) {
  d.setZero();
  v.setZero();
  if (a >= 0) {
    d += point_displacement(m[a].q, ra);
    v += point_displacement(m[a].v, ra);
  }
  if (b >= 0) {
    d -= point_displacement(m[b].q, rb);
    v -= point_displacement(m[b].v, rb);
  }
}

void apply_pair(std::vector<GenForce>& f, int a, const Eigen::Vector3d& ra, int b, const Eigen::Vector3d& rb,
                const Eigen::Vector3d& F) {
  if (a >= 0) add_point_force(f[a], ra, F);
  if (b >= 0) add_point_force(f[b], rb, -F);
}

Eigen::Vector3d apply_spring_damper(const SpringDamper& e, const std::vector<BodyMotion>& m,
                                    std::vector<GenForce>& f) {
  Eigen::Vector3d d, v;
  relative_motion(m, e.body_a, e.r_a, e.body_b, e.r_b, d, v);
  const Eigen::Vector3d F = e.preload - e.k.cwiseProduct(d) - e.c.cwiseProduct(v);
  apply_pair(f, e.body_a, e.r_a, e.body_b, e.r_b, F);
  return F;
}

}  // namespace railsim::engine
