// Model "polach": Polach's creep-force method with spin (1999/2000) and the
// extension for large creep (2005): reduction factors kA, kS and the
// slip-velocity-dependent friction mu(w) = mu0 [(1 - A) exp(-B w) + A].
//
// Sources: O. Polach, "A fast wheel-rail forces calculation computer code",
// VSD 33 Suppl. (1999) 728-739; "Creep forces in simulations of traction vehicles
// running on adhesion limit", Wear 258 (2005) 992-1000; physics-reference.md
// sec. 4.4 (spin structure [U]) and 4.5 (parameter table [U]).
//   s = |(xi, eta)|, C_jj = |(k11 C11 xi, k22 C22 eta)| / s,
//   eps = (1/4) G pi a b C_jj s / (mu Fz)                    (gradient of tangential stress)
//   F   = (2 mu Fz / pi) [kA eps / (1 + (kA eps)^2) + atan(kS eps)]
//   (Fx, Fy) = -F (xi, eta) / s                              (Polach: along the creepage)
// Spin (Kalker's sign: positive phi acts like positive eta):
//   s_yC = eta + phi a;  s_C = s if |s_yC| <= |eta| else |(xi, s_yC)|
//   eps_S = (8/3) G b sqrt(ab) k23 C23 s_C / [mu Fz (1 + 6.3 (1 - exp(-a/b)))]
//   delta = (eps_S^2 - 1) / (eps_S^2 + 1)
//   K_M = |eps_S| (delta^3/3 - delta^2/2 + 1/6) - (1/3) sqrt((1 - delta^2)^3)
//   Fy += (9/16) a mu Fz K_M [1 + 6.3 (1 - exp(-a/b))] phi / s_C
// Small-creepage limit (checked in the tests): kA = kS = 1 gives exactly Kalker's
// f11, f22 (pure xi or pure eta) and f23 (pure spin). With kA != kS the initial
// slope is (kA + kS)/2 times Kalker's (Polach 2005). The reduction factors
// k11, k22, k23 scale the slope by k and leave the level mu Fz unchanged.
// Polach gives no spin moment: Mz = Mz_lin times the saturation ratio of the law
// applied to the total linear force |F_lin| (incl. spin), i.e. eps = pi |F_lin| / (4 mu Fz).
// w = s V (V = ContactInput::rolling_speed); with V = 0, mu = mu0.
// Validity: Hertzian patches; the spin factor 6.3 (1 - exp(-a/b)) is fitted for
// 0.1 <= a/b <= 10 - flagged outside. The spin term is superposed on the
// translational force, so the formula can exceed mu Fz (up to 1.46 mu Fz on
// tests/data/contact/spin_reference); the Coulomb law of the interface
// (coulomb_bound.hpp) limits it to mu(w) Fz along its direction and the case
// is flagged.
// Units: SI (B in s/m, w in m/s); signs as in types.hpp.
#pragma once

#include <memory>

#include "contact/tangential_model.hpp"

namespace railsim::contact {

struct PolachParameters {
  double kA = 1.0;   // reduction in the area of adhesion (initial slope), (0, 1]
  double kS = 1.0;   // reduction in the area of slip, (0, kA]
  double mu0 = 0.0;  // maximum friction at zero slip velocity; 0 = use Material::mu
  double A = 1.0;    // mu_inf / mu0, (0, 1]; 1 = no friction decrease
  double B = 0.0;    // exponential rate of friction decrease [s/m], >= 0
  // Defaults: kA = kS = 1, A = 1, B = 0 -> the 1999 constant-friction law, whose
  // initial slope is Kalker's. Polach (2005) parameter sets ([U], values from memory):
  static PolachParameters dry() { return {1.00, 0.40, 0.55, 0.40, 0.60}; }
  static PolachParameters wet() { return {0.30, 0.10, 0.30, 0.40, 0.20}; }
};

// Throws InputError when a parameter lies outside the ranges above.
std::unique_ptr<TangentialModel> make_polach_model(const PolachParameters& p);

}  // namespace railsim::contact
