// Contact geometry of real wheel and rail profiles for the engine: railsim's
// own rigid contact search (contact/geometry/wheel_rail_geometry.hpp)
// tabulated strip by strip versus lateral shift and yaw
// (contact/geometry/strip_contact_table.hpp, cached on disk), seen through the
// engine's one-wheel interface (engine/wheel_rail/contact_geometry.hpp) as a distributed
// contact: the wheelset models compute each wheel's normal loads and patches
// from its strips and its approach (engine/wheel_rail/strip_patches.hpp), so loads and
// creep forces change continuously when a patch opens or closes and when the
// contact slides through the flange root (S1002 on UIC60 1:40: near 6.25 mm,
// where the rigid contact point jumps from about 37 to 70 degrees).
//
// The table is solved for the whole wheelset (both wheels, wheelset roll and
// height that keep both on their rails) at yaw 0 .. yaw_max; the engine uses
// it symmetrically: for a shift s toward a wheel and that wheel's yaw it reads
// the LEFT wheel's entry at (s, yaw) (profiles, track set-up and placement are
// mirror-symmetric; negative yaw is the fore-aft mirror). The rigid pose
// (roll, axle height) is the table's. evaluate() gives the patches under the
// reference load N_ref = 50 kN per wheel at the rigid pose's roll (statics,
// reports). Units SI (m, rad, N, Pa).
#pragma once

#include <string>

#include "contact/geometry/strip_contact_table.hpp"
#include "contact/types.hpp"
#include "engine/wheel_rail/contact_geometry.hpp"

namespace railsim::engine {

struct ProfileGeometryParams {
  std::string wheel = "S1002";   // profile file or shipped name
  std::string rail = "UIC60";
  contact::TrackSetup setup;     // gauge, flange back, r0, inclination
  contact::StripTableGrid grid;  // y and yaw ranges and steps, strip width
  std::string cache_dir;         // empty: the default contact-table cache folder
};

class ProfileGeometry final : public ContactGeometry {
 public:
  static constexpr double kReferenceLoad = 5.0e4;  // N_ref of evaluate() [N]
  static constexpr double kGapCutoff = 1.5e-3;     // strips evaluated up to this gap [m]

  // Builds (or loads from the cache) the strip table. InputError for bad
  // profiles or set-up.
  ProfileGeometry(const ProfileGeometryParams& params, const contact::Material& material);
  void evaluate(double s, double yaw, WheelGeometry& out) const override;
  bool rigid_pose(double y, double yaw, RigidPose& out) const override;
  bool strips(double s, double yaw, double cutoff, contact::StripSet& out) const override;
  bool distributed() const override { return true; }
  double contact_modulus() const override { return Es_; }
  double r0() const override { return r0_; }
  double l0() const override { return l0_; }
  double max_shift() const override { return s_max_; }
  double max_yaw() const override { return table_.yaw_max(); }
  std::string describe() const override { return description_; }
  const contact::StripContactTable& table() const { return table_; }

 private:
  contact::StripContactTable table_;
  contact::Material material_;
  double Es_ = 0.0;
  double r0_ = 0.0, l0_ = 0.0, s_max_ = 0.0;
  std::string description_;
};

}  // namespace railsim::engine
