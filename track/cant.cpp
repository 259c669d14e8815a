// Cant deficiency and excess; see cant.hpp (physics-reference §10.1).
#include "track/cant.hpp"

#include <cmath>

namespace railsim::track {

double cant_angle(double cant, double rail_spacing) { return std::asin(cant / rail_spacing); }

double outer_rail_cant(double cant, double curvature) {
  if (curvature > 0.0) return cant;
  if (curvature < 0.0) return -cant;
  return std::abs(cant);
}

double equilibrium_cant(double speed, double curvature, double rail_spacing, double g) {
  return rail_spacing * speed * speed * std::abs(curvature) / g;
}

double cant_deficiency(double speed, double curvature, double cant, double rail_spacing, double g) {
  return equilibrium_cant(speed, curvature, rail_spacing, g) - outer_rail_cant(cant, curvature);
}

double uncompensated_acceleration(double speed, double curvature, double cant, double rail_spacing, double g) {
  return g * cant_deficiency(speed, curvature, cant, rail_spacing, g) / rail_spacing;
}

}  // namespace railsim::track
