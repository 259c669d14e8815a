// Equivalent conicity and the rolling-radius-difference curve.
//
// Delta r(y) = r_left(y) - r_right(y) of the touching points, from a contact
// table (y positive to the left, so Delta r grows with y for a normal wheel).
// Equivalent conicity for a harmonic lateral motion y = A sin(wt) (EN 15302:2008,
// linear-regression method): tan(gamma_e) = slope / 2, where slope is the
// least-squares straight line (with intercept) Delta r ~ c + slope y over the
// sample y_i = A sin(2 pi (i + 1/2) / N), i = 0..N-1, i.e. weighted with the time
// the motion spends at each y. Units: m, dimensionless conicity.
#pragma once

#include <functional>
#include <vector>

#include "contact/geometry/contact_table.hpp"

namespace railsim::contact {

struct RollingRadiusCurve {
  std::vector<double> y;        // [m]
  std::vector<double> delta_r;  // [m]
};

RollingRadiusCurve rolling_radius_difference(const ContactTable& table);

// Equivalent conicity at amplitude A [m]; InputError when +-A leaves the table
// or its y step exceeds A/4 (too coarse to resolve the delta-r curve).
double equivalent_conicity(const ContactTable& table, double amplitude, int samples = 2000);
// The same for any rolling-radius difference Delta r(y) [m] defined on [-A, A].
double equivalent_conicity(const std::function<double(double)>& delta_r, double amplitude, int samples = 2000);

}  // namespace railsim::contact
