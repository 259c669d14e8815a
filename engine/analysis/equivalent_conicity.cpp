// Equivalent conicity of a contact geometry; see equivalent_conicity.hpp.
#include "engine/analysis/equivalent_conicity.hpp"

#include <limits>

#include "contact/geometry/conicity.hpp"

namespace railsim::engine {

double equivalent_conicity(const ContactGeometry& g, double amplitude, int samples) {
  if (!(amplitude > 0.0) || amplitude > g.max_shift() + 1e-12 || samples < 4)
    return std::numeric_limits<double>::quiet_NaN();
  // Delta r(y) of the main contact points at zero yaw (the left wheel sees s = +y).
  return contact::equivalent_conicity(
      [&](double y) { return g.main_point(y).rolling_radius - g.main_point(-y).rolling_radius; }, amplitude,
      samples);
}

std::vector<ConicityPoint> conicity_curve(const ContactGeometry& g, int max_mm) {
  std::vector<ConicityPoint> out;
  for (int mm = 1; mm <= max_mm; ++mm) {
    const double A = mm * 1e-3;
    if (A > g.max_shift() + 1e-12) break;
    out.push_back({A, equivalent_conicity(g, A)});
  }
  return out;
}

}  // namespace railsim::engine
