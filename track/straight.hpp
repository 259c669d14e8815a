// Straight segment: zero curvature, constant cant (normally zero; a constant
// cant is allowed so that cant can be carried between reverse curves).
// offset(u) = (u, 0). Units m; signs as in segment.hpp.
#pragma once

#include "track/segment.hpp"

namespace railsim::track {

class Straight final : public Segment {
 public:
  explicit Straight(double length, double cant = 0.0) : Segment(length), cant_(cant) {}
  const char* kind() const override { return "straight"; }
  Derivs curvature(double) const override { return {}; }
  Derivs cant(double) const override { return {cant_, 0.0, 0.0}; }
  double heading_change(double) const override { return 0.0; }
  std::array<double, 2> offset(double u) const override { return {u, 0.0}; }

 private:
  double cant_;
};

}  // namespace railsim::track
