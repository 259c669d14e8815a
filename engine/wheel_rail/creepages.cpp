// Wheel creepages; see creepages.hpp.
#include "engine/wheel_rail/creepages.hpp"

#include <cmath>

namespace railsim::engine {

contact::Creepages wheel_creepages(const WheelsetKinematics& k, const ContactPointGeometry& c, int side) {
  const double s = side;
  const double r = c.rolling_radius, a = c.lateral, x = c.lead;
  const double cd = std::cos(c.contact_angle), sd = std::sin(c.contact_angle);
  contact::Creepages cr;
  cr.xi = (k.V * (1.0 - s * a * k.kappa) + k.psi * k.ydot + r * (k.psi * k.phidot - k.Omega) - s * a * k.psidot) / k.V;
  cr.eta = ((k.ydot + x * k.psidot - k.V * k.psi + k.phi * k.zdot + r * k.phidot) * cd +
            s * (k.zdot - k.phi * k.ydot + s * a * k.phidot - x * k.Omega) * sd) / k.V;
  cr.phi = ((k.psidot + k.V * k.kappa) * cd - s * (k.Omega - k.psi * k.phidot) * sd) / k.V;
  return cr;
}

}  // namespace railsim::engine
