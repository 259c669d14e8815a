// Model "chopaya": exponential saturation law in the style of CHOPAYA
// (Chollet-Pascal-Ayasse, VOCO) - A RECONSTRUCTION, NOT VOCO'S PUBLISHED LAW.
//
// The published CHOPAYA coefficients were not found (physics-reference.md sec. 4.6,
// [GAP]). This file implements the labelled hypothetical reconstruction of that
// section, consistent with the description in Toumi (2016, eq. 52 and 155):
// exponential saturation F/(mu Fz) = 1 - exp(-tau), spin through reduced creepages.
//   eta* = eta + (f23 / f22) phi           (reduced lateral creepage absorbing spin,
//                                           so that f22 eta* = the linear Fy incl. spin)
//   xi'  = f11 xi / (mu Fz),  eta' = f22 eta* / (mu Fz)
//   tau  = sqrt(xi'^2 + eta'^2),  F_R = mu Fz (1 - exp(-tau)),
//   (Fx, Fy) = -F_R (xi', eta') / tau,  Mz = eps Mz_lin,  eps = (1 - exp(-tau)) / tau,
// with f11 = G c^2 k11 C11, f22 = G c^2 k22 C22, f23 = G c^3 k23 C23 (linear_theory.hpp).
// Properties: slope at tau = 0 equals Kalker's linear theory, asymptote mu Fz, C-infinity
// smooth. Any VOCO-specific constants (a tuning factor in the exponent, a spin
// weighting) are unknown; its error will be measured against the exact solver.
// Validity: spin enters only through the reduced creepage; flagged when the
// normalised spin psi = |f23 phi| / (mu Fz) exceeds 0.3 (provisional limit).
// Units: SI; signs as in types.hpp.
#include <cmath>

#include "contact/linear_theory.hpp"
#include "contact/registry.hpp"

namespace railsim::contact {

namespace {

class Chopaya final : public TangentialModel {
 public:
  std::string_view name() const override { return "chopaya"; }
  ContactForces compute(const ContactInput& in, TangentialWorkspace*) const override {
    const LinearCoefficients f = linear_coefficients(in);
    // The reduced creepages in force units are exactly the linear forces
    // (f22 eta* = f22 eta + f23 phi), so saturate those.
    const LinearForces lin = linear_forces(f, in.creep);
    const double tau = norm2(lin.Fx, lin.Fy) / (in.material.mu * in.patch.Fz);
    // eps = (1 - exp(-tau)) / tau; below tau = 1e-4 the series 1 - tau/2 + tau^2/6
    // (error < 1e-17; exp there would lose digits, expm1 costs twice as much).
    const double eps = tau > 1e-4 ? (1.0 - std::exp(-tau)) / tau : 1.0 - tau * (0.5 - tau / 6.0);
    ContactForces out = scaled_forces(lin, eps);
    if (spin_measure(f, in) > kSpinLimit) {
      out.valid = false;
      out.reason = "large spin (|f23 phi| > 0.3 mu Fz): spin only through reduced creepage";
    }
    return out;
  }

 private:
  static constexpr double kSpinLimit = 0.3;
};

}  // namespace

std::unique_ptr<TangentialModel> make_chopaya(const TangentialModelOptions&) {
  return std::make_unique<Chopaya>();
}

}  // namespace railsim::contact
