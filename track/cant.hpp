// Cant, equilibrium cant, cant deficiency and excess (physics-reference §10.1).
//
//   equilibrium cant  E_eq = 2b V^2 |kappa| / g          [m]
//   cant deficiency   D = E_eq - E_outer                 [m]  (> 0: deficiency,
//                     vehicle pushed outward; < 0: cant excess)
//   uncompensated lateral acceleration in the track plane (small angles)
//                     a_nc = V^2 |kappa| - g E_outer / 2b = g D / 2b   [m/s^2]
// E_outer is the cant raising the outer rail. With the track convention
// E = z_right - z_left (segment.hpp), E_outer = E sign(kappa); on a straight
// (kappa = 0) there is no outer rail and any cant counts as excess
// (E_outer = |E|). 2b = rail_spacing (1.5 m for standard gauge, which gives the
// practical form E_eq[mm] = 11.8 V^2[km/h] / R[m]). g = 9.81 m/s^2 by default.
#pragma once

namespace railsim::track {

inline constexpr double kStandardGravity = 9.81;  // [m/s^2], the value behind the 11.8 V^2/R rule

// Cant angle phi = asin(E / 2b) [rad].
double cant_angle(double cant, double rail_spacing);
// Cant raising the outer rail for signed cant E and curvature kappa [m].
double outer_rail_cant(double cant, double curvature);
// E_eq [m] for speed V [m/s] on curvature kappa [1/m].
double equilibrium_cant(double speed, double curvature, double rail_spacing, double g = kStandardGravity);
// D [m] (> 0 deficiency, < 0 excess).
double cant_deficiency(double speed, double curvature, double cant, double rail_spacing,
                       double g = kStandardGravity);
// Cant excess = -D [m].
inline double cant_excess(double speed, double curvature, double cant, double rail_spacing,
                          double g = kStandardGravity) {
  return -cant_deficiency(speed, curvature, cant, rail_spacing, g);
}
// a_nc = g D / 2b [m/s^2].
double uncompensated_acceleration(double speed, double curvature, double cant, double rail_spacing,
                                  double g = kStandardGravity);

}  // namespace railsim::track
