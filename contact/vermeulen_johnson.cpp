// Model "vermeulen_johnson": the Vermeulen-Johnson (1964) cubic creep law, no spin.
//
// Source: Vermeulen & Johnson, "Contact of nonspherical elastic bodies
// transmitting tangential forces", J. Appl. Mech. 31 (1964) 338-340;
// physics-reference.md sec. 4.2 [K]/[U]:
//   F_R / (mu Fz) = 1 - (1 - tau)^3  (tau < 1),  1  (tau >= 1).
// The original normalises the creepages with its own ellipse constants (from
// elliptic integrals), which the reference does not reproduce [U]. Here tau is
// built from Kalker's linear forces WITHOUT spin, tau = |(f11 xi, f22 eta)| / (3 mu Fz),
// so that the slope at zero creepage equals the linear theory (the original
// constants differ from Kalker's by a few %). Forces keep the direction of
// (f11 xi, f22 eta); Mz = eps f23 eta (lateral-creepage coupling only).
// Validity: no spin in the original theory: flagged when the linear spin force
// would exceed 5 % of mu Fz (psi = |f23 phi| / (mu Fz) > 0.05); spin is ignored.
// Units: SI; signs as in types.hpp.
#include <cmath>

#include "contact/linear_theory.hpp"
#include "contact/registry.hpp"

namespace railsim::contact {

namespace {

class VermeulenJohnson final : public TangentialModel {
 public:
  std::string_view name() const override { return "vermeulen_johnson"; }
  ContactForces compute(const ContactInput& in, TangentialWorkspace*) const override {
    const LinearCoefficients f = linear_coefficients(in);
    Creepages no_spin = in.creep;
    no_spin.phi = 0.0;
    LinearForces lin = linear_forces(f, no_spin);
    const double bound = in.material.mu * in.patch.Fz;
    const double tau = norm2(lin.Fx, lin.Fy) / (3.0 * bound);
    // eps = F_R / |F_lin| = [1 - (1 - tau)^3] / (3 tau), limit 1 at tau -> 0.
    double eps = 1.0;
    if (tau >= 1.0)
      eps = 1.0 / (3.0 * tau);
    else if (tau > 0.0)
      eps = 1.0 - tau + tau * tau / 3.0;
    ContactForces out = scaled_forces(lin, eps);
    if (spin_measure(f, in) > kSpinLimit) {
      out.valid = false;
      out.reason = "spin ignored (|f23 phi| > 0.05 mu Fz): Vermeulen-Johnson has no spin";
    }
    return out;
  }

 private:
  static constexpr double kSpinLimit = 0.05;
};

}  // namespace

std::unique_ptr<TangentialModel> make_vermeulen_johnson(const TangentialModelOptions&) {
  return std::make_unique<VermeulenJohnson>();
}

}  // namespace railsim::contact
