// Equivalent conicity of a contact geometry; see equivalent_conicity.hpp.
#include "engine/analysis/equivalent_conicity.hpp"

#include <cmath>
#include <limits>

namespace railsim::engine {

double equivalent_conicity(const ContactGeometry& g, double amplitude, int samples) {
  if (!(amplitude > 0.0) || amplitude > g.max_shift() + 1e-12 || samples < 4)
    return std::numeric_limits<double>::quiet_NaN();
  WheelContact left, right;
  double sy = 0, sd = 0, syy = 0, syd = 0;
  const double pi = std::acos(-1.0);
  for (int i = 0; i < samples; ++i) {
    const double y = amplitude * std::sin(2.0 * pi * (i + 0.5) / samples);
    g.evaluate(y, left);
    g.evaluate(-y, right);
    const double dr = left.rolling_radius - right.rolling_radius;
    sy += y;
    sd += dr;
    syy += y * y;
    syd += y * dr;
  }
  const double n = samples;
  return 0.5 * (n * syd - sy * sd) / (n * syy - sy * sy);
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
