// Equivalent conicity of a scenario's wheel-rail geometry, for reports.
//
// Delta r(y) = r_left(y) - r_right(y) from the geometry's main contact point
// (engine/contact_geometry.hpp: shift s toward a wheel, so the left wheel sees
// s = +y and the right wheel s = -y). Equivalent conicity for a harmonic
// lateral motion y = A sin(wt), as EN 15302:2008 (linear-regression method;
// the same definition as contact/geometry/conicity.hpp for contact tables):
// tan(gamma_e) = slope / 2 of the least-squares line Delta r ~ c + slope y
// over the samples y_i = A sin(2 pi (i + 1/2) / N). For conical wheels it is
// the cone's conicity at every amplitude below the flange. Units: m, [-].
#pragma once

#include <vector>

#include "engine/contact_geometry.hpp"

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
