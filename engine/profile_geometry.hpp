// Contact geometry of real wheel and rail profiles for the engine: railsim's
// own rigid contact search (contact/geometry/wheel_rail_geometry.hpp) tabulated
// versus lateral shift (contact/geometry/contact_table.hpp, cached on disk),
// seen through the engine's one-wheel interface (engine/contact_geometry.hpp).
//
// The table is solved for the whole wheelset (both wheels, wheelset roll that
// keeps both on their rails, zero yaw). The engine uses it symmetrically: for
// a shift s toward a wheel it reads the LEFT wheel's entry at y = s (profiles,
// track set-up and placement are mirror-symmetric). Per point: rolling radius,
// contact angle (> 0 tilts the normal toward the track centre; the table's sign
// for the left wheel), lateral distance of the point from the wheelset centre,
// relative curvatures A, B, and the Hertz patch (a along the rolling direction,
// from A; Hertz 1882, via contact/hertz.hpp) and approach at the reference load
// N0 = 50 kN; the engine scales them as N^(1/3) and N^(2/3), exactly Hertz for
// fixed curvatures. Kalker's coefficients follow from a/b in the coupling.
// Two points per wheel (points() = 2): the main (touching) point and, where
// the profiles have a second local minimum of the gap within 1 mm (S1002 on
// UIC60 at 1:40: near 0 mm and 4.0-5.25 mm, the tread jump; none at the
// flange jump, where the point slides through the flange root), that second
// point with its own radius, angle, curvatures and Hertz patch. All points
// share the wheel's vertical approach, measured from one reference that is
// continuous in the shift: at the engine's z = 0 the wheel is pressed by
// w0 = q0 / cos(delta) (the centred wheel's Hertz approach under N0) below its
// rigid touching position at that shift, so point k has the normal approach
//   q_k = (w0 - v_k) cos(delta_k),   v_k its vertical gap (0 for the touching point),
// and carries N_k = K_k (q_k + dq_k)^{3/2} (Hertz, K_k = N0 / q0_k^{3/2} from its
// own curvatures) while positive: the offsets `gap` of engine/contact_geometry.hpp.
// The wheel's load thus passes continuously from one point to the other
// (the table interpolates each point on its own, contact_table.hpp). The
// lateral (quasi-static) model shares the wheel's load the same way
// (wheelset_lateral.hpp). Wheelset yaw is not in the table (zero yaw).
// Units SI (m, rad, 1/m, N).
#pragma once

#include <string>

#include "contact/geometry/contact_table.hpp"
#include "contact/types.hpp"
#include "engine/contact_geometry.hpp"

namespace railsim::engine {

struct ProfileGeometryParams {
  std::string wheel = "S1002";   // profile file or shipped name
  std::string rail = "UIC60";
  contact::TrackSetup setup;     // gauge, flange back, r0, inclination
  contact::TableGrid grid{-0.015, 0.015, 1e-4};
  std::string cache_dir;         // empty: the default contact-table cache folder
};

class ProfileGeometry final : public ContactGeometry {
 public:
  static constexpr double kReferenceLoad = 5.0e4;  // N0 of the tabulated Hertz patch [N]

  // Builds (or loads from the cache) the contact table. InputError for bad
  // profiles or set-up.
  ProfileGeometry(const ProfileGeometryParams& params, const contact::Material& material);
  void evaluate(double s, double yaw, WheelGeometry& out) const override;
  bool rigid_pose(double y, double yaw, RigidPose& out) const override;
  double r0() const override { return r0_; }
  double l0() const override { return l0_; }
  double max_shift() const override { return s_max_; }
  std::string describe() const override { return description_; }

 private:
  contact::ContactTable table_;
  contact::Material material_;
  double r0_ = 0.0, l0_ = 0.0, s_max_ = 0.0;
  double z0_ = 0.0;  // axle height of the centred wheelset in the table [m]
  std::string description_;
};

}  // namespace railsim::engine
