// Undeformed gap on the MIM grid from a wheel-rail gap profile (non-Hertzian
// patches, e.g. S1002 on UIC60): the gap across the contact plane h(q) and
// the local longitudinal relative curvature A(q) of
// contact/geometry/wheel_rail_geometry.hpp (GapProfile) give
//   h(x, y) = h(y) + A(y) x^2
// (x rolling direction, y = q lateral in the contact plane; the usual
// approximation of the wheel and rail surfaces near the contact, as in
// Kik-Piotrowski and STRIPES). h and A are interpolated linearly at the
// element centres. The grid has square elements of size `element` and covers
// every point with h(x, y) < max_gap plus two unused elements on each side.
// Units: m, 1/m.
#pragma once

#include <vector>

#include "contact/geometry/wheel_rail_geometry.hpp"
#include "contact/mim/grid.hpp"

namespace railsim::contact::mim {

struct GapOnGrid {
  ContactGrid grid;
  std::vector<double> h;  // undeformed gap at the element centres [m]
};

// Throws InputError for an empty/non-uniform profile, element <= 0 or max_gap <= 0,
// or when no part of the profile lies below max_gap.
GapOnGrid gap_from_profile(const GapProfile& profile, double element, double max_gap);

}  // namespace railsim::contact::mim
