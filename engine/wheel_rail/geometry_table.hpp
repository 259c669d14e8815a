// Contact geometry from a 13-column contact-geometry table file (the RSGEO
// format of the DTU pre-processor used by DYTSI; cooperrider-car.md §7):
// a line "#", a header of 13 quoted column names, then rows of
//   shift, N0, delta, a, b, a_w, r_w, C11, C22, C23, z_c, q0, (unused)
// on a uniform grid of shift toward the wheel [m]. Several blocks, each
// starting with a "#" line, are several contact points per wheel
// (cooperrider-car.md §7.1); the static quantities r0, l0 are those of the
// first block at zero shift. The table does not depend on yaw.
//
// Smoothing (contact/geometry/smooth_columns.hpp): the rows of such files
// carry cell-scale noise (for the shipped RSGEO table at its 0.01 mm spacing
// the second differences are 10 (radius) to 260 (contact angle) times larger
// than at 1 mm spacing), which a stiff integrator resolves with steps of one
// cell. Each block is therefore represented by a local least-squares quadratic
// (Savitzky-Golay) of half-width `smoothing` evaluated at nodes every
// `node_step` (both 0.1 mm by default) and cubic Hermite interpolation between
// the nodes (C1). The largest deviation of the smooth curve from the raw rows
// is reported per column (deviation_report()); near the jump of the contact
// point to the flange (7-8 mm for RSGEO) it is the jump itself spread over
// the fit width. node_step = smoothing = the file's spacing with
// `smoothing: 0` reproduces the rows (interpolation without smoothing).
//
// Rigid pose (the lateral model's kinematic roll): the knife-edge roll
// (r_L - r_R)/(a_L + a_R) with its exact derivative from the smooth fit;
// height 0. The table's contact angles are those of the
// pre-processor's rolled rigid wheelset measured from the axle, and DYTSI's
// full model measures its approaches from the table's reference state at
// every shift (reference_follows_shift), so the full model does not use the
// pose. For the lateral model the knife-edge roll reproduces the full model's
// limit cycle best (Cooperrider car, 120 m/s: leading-wheelset amplitude
// 4.6 mm against the full model's 4.0 mm; a rigid roll from the contact-height
// column z_c, ((r_L + z_cL) - (r_R + z_cR))/(a_L + a_R), gives 6.0 mm and no
// roll 7.2 mm).
#pragma once

#include <string>
#include <vector>

#include "contact/geometry/smooth_columns.hpp"
#include "engine/wheel_rail/contact_geometry.hpp"

namespace railsim::engine {

struct GeometryTableOptions {
  double node_step = 1e-4;  // [m] spacing of the smooth nodes
  double smoothing = 1e-4;  // [m] half-width of the local fit; 0: interpolate the rows (no smoothing)
};

class GeometryTable final : public ContactGeometry {
 public:
  // Throws InputError naming file and line for malformed files.
  explicit GeometryTable(const std::string& path, const GeometryTableOptions& options = {});
  void evaluate(double s, double yaw, WheelGeometry& out) const override;
  bool reference_follows_shift() const override { return true; }
  bool rigid_pose(double y, double yaw, RigidPose& out) const override;
  double r0() const override { return r0_; }
  double l0() const override { return l0_; }
  double max_shift() const override { return s_max_; }
  std::string describe() const override;
  std::size_t rows() const { return rows_; }
  int blocks() const { return static_cast<int>(blocks_.size()); }
  // Largest deviation of the smooth curve from the raw rows, per column, as text.
  std::string deviation_report() const;

  // Column indices of the smooth representation (file columns 1..11).
  enum Col { kN0, kDelta, kSemiA, kSemiB, kLateral, kRadius, kC11, kC22, kC23, kZc, kQ0, kCols };

 private:
  struct Block {
    contact::SmoothColumns fit;
    double s_min = 0.0, s_max = 0.0;
  };
  std::string path_;
  GeometryTableOptions options_;
  std::vector<Block> blocks_;
  std::size_t rows_ = 0;  // rows of the first block
  double raw_step_ = 0.0;
  double s_min_ = 0.0, s_max_ = 0.0, r0_ = 0.0, l0_ = 0.0;
};

}  // namespace railsim::engine
