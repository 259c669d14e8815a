// engine::Data: the per-run workspace of a Model (model.hpp). Sized once from
// the model; the right-hand side (system.hpp) writes only into it and does
// not allocate. Also carries the per-wheel outputs of the last evaluation and
// the failure message when the physics broke down.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "contact/geometry/strip_contact_table.hpp"
#include "contact/tangential_model.hpp"
#include "contact/types.hpp"
#include "engine/model.hpp"

namespace railsim::engine {

struct WheelOutput {
  double Q = 0.0;    // vertical wheel load [N]
  double N = 0.0;    // normal load [N]
  double Y = 0.0;    // lateral force of the rail on the wheel, track y [N]
  double Fx = 0.0;   // longitudinal creep force [N]
  double Fy = 0.0;   // lateral creep force in the contact plane [N]
  double Mz = 0.0;   // spin moment [N m]
  contact::Creepages creep;     // of the most loaded point
  double Tgamma = 0.0;          // wear number, summed over the loaded points (wear_number.hpp) [N]
  double contact_y = 0.0;       // lateral position of the contact point on the rail, track y [m]
  double contact_angle = 0.0;   // [rad]
  double rolling_radius = 0.0;  // [m]
  double contact_lead = 0.0;    // [m] of the most loaded point, ahead of the axle
  bool valid = true;
  const char* reason = "";
  int patches = 0;  // loaded patches recorded in Data::patch (Data::record_patches only)
};

// One loaded contact patch of the last evaluation: the tangential model's
// input and what it returned (Data::record_patches; the contact audit).
struct PatchState {
  contact::ContactInput input;
  contact::ContactForces forces;
  int point = 0;               // index of the potential contact point / patch of the wheel
  double contact_angle = 0.0;  // [rad]
};

// The rails under one wheelset as its wheels see them (track_flexibility.hpp):
// lateral position of the track (mean of the two rails) and each rail's
// height, with their time rates. Track y to the left, z up [m, m/s].
struct RailPosition {
  double lateral = 0.0, lateral_rate = 0.0;
  double vertical[2] = {0.0, 0.0}, vertical_rate[2] = {0.0, 0.0};  // left, right
  // Where the track's supports hold them (the geometry, smoothed by the rails'
  // bending when they have it): what the flexible track's masses are sprung to.
  double support_lateral = 0.0, support_lateral_rate = 0.0;
  double support_vertical[2] = {0.0, 0.0}, support_vertical_rate[2] = {0.0, 0.0};
};

// What the wheel-rail contact of one wheelset added to an evaluation: the
// increments of the wheelset body's generalised force (added by
// add_contact_forces, in one order, so that a replay gives the same bits),
// its spin state's rate and the two wheels' outputs (Data::record_contact,
// Data::reuse_contact).
struct WheelsetContactRecord {
  double lat = 0.0, yaw = 0.0;                  // creep forces' lateral force and yaw moment
  bool full = false;                            // full model: also these
  double vert = 0.0, roll = 0.0, yaw_gyro = 0.0;  // vertical force, roll and gyroscopic yaw moments
  double spin_rate = 0.0;                       // rate of the spin perturbation state
  WheelOutput wheel[2];
  long invalid_calls = 0;                       // contacts outside their validity domain
};
inline void add_contact_forces(const WheelsetContactRecord& r, GenForce& F) {
  F[kLat] += r.lat;
  F[kYaw] += r.yaw;
  if (r.full) {
    F[kVert] += r.vert;
    F[kRoll] += r.roll;
    F[kYaw] += r.yaw_gyro;
  }
}

struct Data {
  explicit Data(const Model& model);

  std::vector<BodyMotion> motion;
  std::vector<GenForce> force;
  std::vector<TrackSample> track;      // per body, at its own distance
  TrackSample reference;               // alignment at the vehicle reference distance s
  // Per body: its motion in the frame at the vehicle reference distance (own
  // motion + frame_offset, track_frame.hpp); what suspension elements between
  // two bodies act on.
  std::vector<BodyMotion> vehicle_motion;
  std::vector<WheelOutput> wheel;      // 2 per wheelset: left, right
  std::vector<RailPosition> rail;      // per wheelset (rail_positions)
  // Off by default; simulate() sets it on its reporting Data only: then every
  // evaluation keeps each wheel's loaded patches (N > 1 N) in
  // patch[wheel * WheelGeometry::kMaxPoints + k], k < wheel[].patches.
  bool record_patches = false;
  std::vector<PatchState> patch;
  // State derivative at the reported output: simulate() (simulation.hpp) sets
  // it before calling the observer, so recorders can form accelerations
  // (engine/analysis/run_history.hpp). Empty in other uses of Data.
  Eigen::VectorXd xdot;
  std::vector<std::unique_ptr<contact::TangentialWorkspace>> workspace;  // per wheel
  // Scratch of the strip-wise normal contact (engine/wheel_rail/wheelset_contact.cpp):
  // the strips of the two wheels of the wheelset being evaluated (25 kB each,
  // kept here so that the right-hand side does not clear them on the stack).
  std::vector<contact::StripSet> strips;
  // Warm starts of the lateral model's load-to-approach solves, 2 per
  // wheelset (strip_approach_for_load; as MuJoCo's mjData::qacc_warmstart):
  // each starts from its wheel's last solution, 2.0 instead of 3.8 share
  // passes a wheel on the ERRI coach, the loads the same as from the default
  // start within the solve's tolerance (1e-10 of the load). With warm_start
  // off the solves start from the default and leave these alone, so that an
  // evaluation does not depend on the ones before it: the linearisation, the
  // equilibrium start and the sweep cache's model hash. (ModelOde's coloured
  // differences start every colour where their base evaluation started.)
  std::vector<double> approach_warm_start;
  bool warm_start = true;
  // Contact replay for coloured Jacobian differences (ModelOde): with
  // record_contact set, each wheelset's contribution is kept in
  // contact_record; with reuse_contact set, a wheelset w with
  // reuse_contact[w] != 0 takes its recorded contribution instead of solving
  // its contact again (valid when no state its contact depends on changed:
  // the caller's responsibility; the result is then the same to the bit).
  bool record_contact = false;
  const unsigned char* reuse_contact = nullptr;
  std::vector<WheelsetContactRecord> contact_record;  // per wheelset
  double t = 0.0, V = 0.0, s = 0.0;
  long rhs_calls = 0;
  long invalid_contact_calls = 0;      // evaluations with a contact outside its validity domain
  std::string first_invalid_reason;
  bool failed = false;
  bool derailed = false;               // the failure is a derailment (physics), not numerics
  bool left_range = false;             // the failure is the motion leaving the model's range (ModelRangeError)
  std::string failure;                 // set when rhs returns false
  void fail(std::string msg);
  void derail(std::string msg);
  void leave_range(std::string msg);
};

}  // namespace railsim::engine
