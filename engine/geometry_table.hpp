// Contact geometry from a 13-column contact-geometry table file (the RSGEO
// format of the DTU pre-processor used by DYTSI; cooperrider-car.md §7):
// a line "#", a header of 13 quoted column names, then rows of
//   shift, N0, delta, a, b, a_w, r_w, C11, C22, C23, z_c, q0, (unused)
// on a uniform grid of shift toward the wheel [m]. Each column is
// interpolated with a cubic B-spline on the uniform grid (Boost.Math
// cardinal_cubic_b_spline; DYTSI uses a natural cubic spline: the two agree
// away from the table ends). Several blocks, each starting with a "#" line,
// are several contact points per wheel (cooperrider-car.md §7.1); the static
// quantities r0, l0 are those of the first block at zero shift.
#pragma once

#include <boost/math/interpolators/cardinal_cubic_b_spline.hpp>

#include <vector>

#include "engine/contact_geometry.hpp"

namespace railsim::engine {

class GeometryTable final : public ContactGeometry {
 public:
  // Throws InputError naming file and line for malformed files.
  explicit GeometryTable(const std::string& path);
  void evaluate(double s, WheelContact& out) const override { evaluate_point(s, 0, out); }
  int points() const override { return static_cast<int>(blocks_.size()); }
  void evaluate_point(double s, int k, WheelContact& out) const override;
  double r0() const override { return r0_; }
  double l0() const override { return l0_; }
  double max_shift() const override { return s_max_; }
  std::string describe() const override;
  std::size_t rows() const { return rows_; }

 private:
  using Spline = boost::math::interpolators::cardinal_cubic_b_spline<double>;
  std::string path_;
  struct Block {
    std::vector<Spline> col;  // columns 1..11
    double s_min = 0.0, s_max = 0.0;
  };
  std::vector<Block> blocks_;
  std::size_t rows_ = 0;  // rows of the first block
  double s_min_ = 0.0, s_max_ = 0.0, r0_ = 0.0, l0_ = 0.0;
};

}  // namespace railsim::engine
