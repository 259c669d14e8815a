// Conical wheels on knife-edge rails: the geometry of the linear theory.
//
// Rolling radius r = r0 + lambda s (s = shift toward the wheel), constant
// contact angle delta0, constant lateral contact position l0, constant relative
// curvatures (A, B) for Hertz. Optional flange: a dead-band lateral spring
// F = k_f (s - c) for s > c (Kaas-Petersen 1986 style), pushing the wheelset
// back toward the track centre. Klingel (1883); physics-reference §8.1-8.2.
// Rigid pose on knife-edge rails: roll (r_L - r_R)/(2 l0) = lambda y / l0,
// axle height (r_L + r_R)/2 - r0 = 0. No yaw dependence.
#pragma once

#include "engine/wheel_rail/contact_geometry.hpp"

namespace railsim::engine {

struct ConicalParams {
  double r0 = 0.46;
  double conicity = 0.2;
  double l0 = 0.75;
  double contact_angle = 0.0;   // [rad]
  double A = 0.0, B = 0.0;      // relative curvatures [1/m] (0: unknown)
  double flange_clearance = 0.0;  // [m]; 0 = no flange
  double flange_stiffness = 0.0;  // [N/m]
  double max_shift = 0.05;        // [m]
};

class ConicalGeometry final : public ContactGeometry {
 public:
  explicit ConicalGeometry(const ConicalParams& p) : p_(p) {}
  void evaluate(double s, double yaw, WheelGeometry& out) const override;
  bool rigid_pose(double y, double yaw, RigidPose& out) const override;
  double r0() const override { return p_.r0; }
  double l0() const override { return p_.l0; }
  double max_shift() const override { return p_.max_shift; }
  std::string describe() const override;
  const ConicalParams& params() const { return p_; }

 private:
  ConicalParams p_;
};

}  // namespace railsim::engine
