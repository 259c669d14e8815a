// Equivalent conicity of a scenario's wheel-rail geometry, for reports.
//
// Delta r(y) = r_left(y) - r_right(y) from the geometry's main contact point
// at zero yaw (engine/wheel_rail/contact_geometry.hpp: shift s toward a wheel, so the
// left wheel sees s = +y and the right wheel s = -y), put through
// contact/geometry/conicity.hpp's EN 15302:2008 regression for a harmonic
// lateral motion y = A sin(wt) (the same computation as the scenario's
// equivalent_conicity_3mm, here at every amplitude 1..6 mm). For conical wheels it is
// the cone's conicity at every amplitude below the flange. Units: m, [-].
#pragma once

#include <vector>

#include "engine/wheel_rail/contact_geometry.hpp"

namespace railsim::engine {

// Equivalent conicity at amplitude A [m]; NaN when A is not in (0, max_shift].
double equivalent_conicity(const ContactGeometry& g, double amplitude, int samples = 2000);

struct ConicityPoint {
  double amplitude = 0.0;  // [m]
  double conicity = 0.0;   // [-]
};

// At the amplitudes 1, 2, ... mm up to max_mm that the geometry's range allows.
std::vector<ConicityPoint> conicity_curve(const ContactGeometry& g, int max_mm = 6);

}  // namespace railsim::engine
