// Rigid bodies described relative to the track-following frame.
//
// Each body has up to five small deviations from its nominal position in the
// track frame (x forward, y left, z up; cooperrider-car.md §1 and
// architecture.md "Coordinates and signs"): lateral y, vertical z, roll phi
// (about +x), pitch chi (about +y), yaw psi (about +z). The longitudinal
// deviation is not modelled (constant prescribed speed). Rotations are small:
// a body-fixed offset r moves by theta x r (first-order kinematics, Shabana
// 2008 "Railroad vehicle dynamics", ch. 3). Inertia is diagonal in body axes
// (principal axes aligned with the track frame at the nominal position).
// Units: m, kg, kg m^2, rad.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <string>

namespace railsim::engine {

// Degrees of freedom of a body, in state order.
enum Dof : int { kLat = 0, kVert = 1, kRoll = 2, kPitch = 3, kYaw = 4, kNumDof = 5 };

const char* dof_name(int dof);

struct RigidBody {
  std::string name;
  double mass = 0.0;                                   // [kg]
  Eigen::Vector3d inertia = Eigen::Vector3d::Zero();   // Ixx, Iyy, Izz [kg m^2]
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // nominal CoM: x along, y left, z above rail [m]
  std::array<bool, kNumDof> active{};                  // which DOFs are states
  std::array<int, kNumDof> q_index{-1, -1, -1, -1, -1};  // state index of each position (-1: not a state)
  std::array<int, kNumDof> v_index{-1, -1, -1, -1, -1};  // state index of each velocity
  int wheelset = -1;                                   // index into Model::wheelsets, -1 for other bodies

  // Generalised mass of one DOF (mass for y, z; Ixx, Iyy, Izz for roll, pitch, yaw).
  double generalised_mass(int dof) const;
};

// Position/velocity deviations of one body (inactive DOFs are zero).
struct BodyMotion {
  std::array<double, kNumDof> q{};
  std::array<double, kNumDof> v{};
};

// First-order displacement (x, y, z) of a point at offset r from the CoM.
inline Eigen::Vector3d point_displacement(const std::array<double, kNumDof>& q, const Eigen::Vector3d& r) {
  // u = d + theta x r, d = (0, y, z), theta = (phi, chi, psi)
  const double phi = q[kRoll], chi = q[kPitch], psi = q[kYaw];
  return {chi * r.z() - psi * r.y(), q[kLat] + psi * r.x() - phi * r.z(), q[kVert] + phi * r.y() - chi * r.x()};
}

// Generalised forces (y, z force; x, y, z moments) of a force F applied at offset r.
inline void add_point_force(std::array<double, kNumDof>& gen, const Eigen::Vector3d& r, const Eigen::Vector3d& F) {
  gen[kLat] += F.y();
  gen[kVert] += F.z();
  const Eigen::Vector3d M = r.cross(F);
  gen[kRoll] += M.x();
  gen[kPitch] += M.y();
  gen[kYaw] += M.z();
}

}  // namespace railsim::engine
