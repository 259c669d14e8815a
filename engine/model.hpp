// engine::Model: the immutable description of one vehicle on one track with
// its contact choices (Pinocchio/MuJoCo style: Model is built once from YAML
// and never changes while integrating; per-run scratch lives in engine::Data,
// data.hpp; algorithms are functions over (Model, Data), system.hpp).
//
// State vector: per body, the positions of its active DOFs, then their
// velocities, then (full wheelset model) the spin perturbation beta [rad/s];
// after all bodies, one elongation state per yaw damper, then (flexible
// track) per wheelset the track's lateral position and rate and per wheel the
// rail's vertical position and rate. All states are
// deviations from the static equilibrium on straight, level track (gravity is
// balanced by spring preloads computed in finalize_model(), system.hpp).
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "engine/elements/anti_roll_bar.hpp"
#include "engine/elements/bump_stop.hpp"
#include "engine/wheel_rail/contact_geometry.hpp"
#include "engine/elements/rigid_body.hpp"
#include "engine/elements/spring_damper.hpp"
#include "engine/track_frame.hpp"
#include "engine/wheel_rail/strip_patches.hpp"
#include "engine/wheel_rail/wheel_rail_coupling.hpp"
#include "engine/elements/yaw_damper.hpp"

namespace railsim::engine {

enum class WheelsetModel { lateral, full };
const char* wheelset_model_name(WheelsetModel m);

struct Wheelset {
  std::string name;
  int body = -1;
  std::shared_ptr<const ContactGeometry> geometry;
  double static_load[2] = {0.0, 0.0};  // normal load per wheel at rest [N] (left, right)
  double hertz_q0[2] = {0.0, 0.0};     // q0 of points without a reference state (cones) [m]
  // Full model: vertical approach of each wheel at x = 0 that carries its
  // static load (finalize_model; wheelset_contact.hpp) [m].
  double static_approach[2] = {0.0, 0.0};
  int beta_state = -1;                 // spin perturbation state (full model, or axle_rotation free)
  // Flexible track (Model::track): the position state of the track's lateral
  // mass under this wheelset and of each rail's vertical mass (-1: rigid); each
  // is followed by its rate state.
  int track_lateral_state = -1;
  int rail_vertical_state[2] = {-1, -1};
  double static_vertical_load[2] = {0.0, 0.0};  // Q0 per wheel [N] (finalize_model)
  // The track's position states of this wheelset: lateral, left rail, right rail (-1 where rigid).
  std::array<int, 3> track_states() const { return {track_lateral_state, rail_vertical_state[0], rail_vertical_state[1]}; }
};

// One direction of the flexible track under a wheelset
// (wheel_rail/track_flexibility.hpp): a mass on a spring and a damper to the
// track geometry.
struct TrackSupport {
  bool active = false;
  double mass = 0.0;       // [kg]
  double stiffness = 0.0;  // [N/m]
  double damping = 0.0;    // [N s/m]
  // Vertical: bending stiffness EI of the rail [N m^2]; > 0: the rails follow
  // the track's vertical geometry smoothed as a beam on an elastic
  // foundation (track_flexibility.hpp), 0: exactly.
  double bending_stiffness = 0.0;
};
class SmoothedRailGeometry;  // wheel_rail/track_flexibility.hpp
struct TrackFlexibility {
  TrackSupport lateral;   // per wheelset (both rails)
  TrackSupport vertical;  // per rail under each wheel (full wheelset model)
  std::shared_ptr<const SmoothedRailGeometry> vertical_geometry;  // with vertical.bending_stiffness > 0
};

// Speed V(t) = V0 + a t (a = 0: constant speed), distance s(t) = s0 + V0 t + a t^2 / 2.
struct SpeedProfile {
  double v0 = 0.0;
  double accel = 0.0;
  double s0 = 0.0;
  double speed(double t) const { return v0 + accel * t; }
  double distance(double t) const { return s0 + v0 * t + 0.5 * accel * t * t; }
};

struct Model {
  std::string vehicle_name;
  std::vector<RigidBody> bodies;
  std::vector<SpringDamper> springs;
  std::vector<BumpStop> bump_stops;
  std::vector<YawDamper> yaw_dampers;
  std::vector<AntiRollBar> anti_roll_bars;
  std::vector<Wheelset> wheelsets;
  WheelsetModel wheelset_model = WheelsetModel::lateral;
  WheelRailCoupling coupling;
  std::shared_ptr<const TrackReference> track;
  SpeedProfile speed;
  double max_lateral_shift = 0.0;  // run stops beyond (0: geometry range)
  // Rails rigid (default) or on the lumped flexible track of
  // wheel_rail/track_flexibility.hpp (scenario key track_flexibility).
  TrackFlexibility track_flexibility;
  // Lateral wheelset model: wheelset roll follows the geometry quasi-statically
  // (phi = (r_L - r_R) / (a_L + a_R), rigid rails) when true; held at zero when
  // false (the textbook model of physics-reference §8.1).
  bool kinematic_roll = true;
  // Lateral wheelset model: the axle's rotation speed. Imposed (false): Omega =
  // V / r0, the textbook lateral model's (Cooperrider's, DYTSI's); the axle then
  // carries whatever torque the longitudinal creep forces need, which in flange
  // contact is a braking torque (the two wheels' rolling radii differ by
  // millimetres: sum Fx 16 kN on the coach's leading wheelset in an R 250 m
  // curve). Free (true): the spin perturbation beta is a state, Iyy beta' =
  // M_y, as in the full model: the axle rolls freely, sum Fx r ~ 0. The full
  // model always has it.
  bool free_axle_rotation = false;
  // Distributed contact (profiles geometry): the ellipse each patch hands to
  // the tangential models, Hertz's for the patch's curvatures or the
  // semi-Hertzian patch's area and length (wheel_rail/strip_patches.hpp;
  // scenario key contact.normal: hertz | semi_hertz).
  PatchShape patch_shape = PatchShape::hertz;
  int n_states = 0;
  std::vector<std::string> state_names;
  bool finalized = false;

  int body_index(const std::string& name) const;  // -1 if none
};

}  // namespace railsim::engine
