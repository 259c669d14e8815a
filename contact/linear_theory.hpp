// Kalker's linear theory of rolling contact (model "linear") and the pieces the
// force-level saturation laws share.
//
// Source: Kalker (1967, 1990 App. E); physics-reference.md sec. 2.1:
//   Fx = -G c^2 C11 xi,  Fy = -G c^2 C22 eta - G c^3 C23 phi,
//   Mz =  G c^3 C23 eta - G c^4 C33 phi,     c = sqrt(ab),
// with reduction factors (physics-reference.md sec. 11; contact/reduction.hpp):
//   C11 -> k11 C11, C22 -> k22 C22, C23 -> k23 C23, C33 -> k23 C33.
// Units: G in Pa, a, b in m, creepages xi, eta [-], phi [1/m]; forces N, moment N m.
// Signs: forces of the rail on the wheel; positive creepage gives negative force.
//
// Validity of the "linear" model: small creepage (adhesion over nearly the whole
// patch). It flags results with |F| > 0.3 mu Fz, where a saturating law (e.g.
// SHE) is already ~10 % lower.
#pragma once

#include <cmath>

#include "contact/types.hpp"

namespace railsim::contact {

// Creep coefficients in force units, reductions included:
// f11 = G c^2 k11 C11 [N], f22 = G c^2 k22 C22 [N], f23 = G c^3 k23 C23 [N m],
// f33 = G c^4 k23 C33 [N m^2].
struct LinearCoefficients {
  double f11 = 0.0, f22 = 0.0, f23 = 0.0, f33 = 0.0;
};

// Checks the input (finite creepages, positive patch, load, friction, E; nu in
// (0, 0.5]; reduction factors in (0, 1.5]) - throws InputError otherwise - and
// returns the coefficients. No allocation.
LinearCoefficients linear_coefficients(const ContactInput& in);

// Linear-theory forces for the coefficients and creepages.
struct LinearForces {
  double Fx = 0.0, Fy = 0.0, Mz = 0.0;
  double Fy_spin = 0.0;  // the spin part -f23 phi of Fy
};
LinearForces linear_forces(const LinearCoefficients& f, const Creepages& c);

// The "linear" model's law on given coefficients: the linear forces, flagged
// invalid when |F| > 0.3 mu Fz (also the law "none" of the model
// "coefficients").
ContactForces linear_theory_forces(const LinearCoefficients& f, const ContactInput& in);

// Forces of a force-level saturation law: the linear forces times eps (direction
// of the linear force kept, spin moment scaled alike).
ContactForces scaled_forces(const LinearForces& lin, double eps);

// Dimensionless spin: the linear spin force over the friction bound,
// psi = |f23 phi| / (mu Fz) (the normalisation of CONTACT's tables). Saturation
// laws that treat spin only through the linear forces flag large psi.
double spin_measure(const LinearCoefficients& f, const ContactInput& in);

// |(x, y)| without std::hypot's overflow guard (several times faster; forces and
// creepages are far from the overflow range).
inline double norm2(double x, double y) { return std::sqrt(x * x + y * y); }

}  // namespace railsim::contact
