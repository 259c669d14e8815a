// Model "linear_sat": Kalker's linear theory with a Coulomb cut-off.
//
// Source: physics-reference.md sec. 4.1 [K]. With the linear forces F_lin
// (linear_theory.hpp, spin included in Fy) and beta = |F_lin| / (mu Fz):
//   F_R / (mu Fz) = min(beta, 1),  (Fx, Fy, Mz) = eps (Fx, Fy, Mz)_lin,
//   eps = F_R / |F_lin|.
// Slope at zero creepage = linear theory; saturated level mu Fz; a reduction
// factor k scales f_ij and therefore the slope by k, not the level.
// Validity: spin only through the linear forces; flagged when the normalised
// spin psi = |f23 phi| / (mu Fz) exceeds 0.3 (provisional limit, to be revisited
// against the exact solver). The slope is discontinuous at saturation.
// Units: SI; signs as in types.hpp.
#include <cmath>

#include "contact/linear_theory.hpp"
#include "contact/registry.hpp"

namespace railsim::contact {

namespace {

class LinearSaturated final : public TangentialModel {
 public:
  std::string_view name() const override { return "linear_sat"; }
  ContactForces compute(const ContactInput& in, TangentialWorkspace*) const override {
    const LinearCoefficients f = linear_coefficients(in);
    const LinearForces lin = linear_forces(f, in.creep);
    const double bound = in.material.mu * in.patch.Fz;
    const double F = norm2(lin.Fx, lin.Fy);
    ContactForces out = scaled_forces(lin, F > bound ? bound / F : 1.0);
    if (spin_measure(f, in) > kSpinLimit) {
      out.valid = false;
      out.reason = "large spin (|f23 phi| > 0.3 mu Fz): spin only through linear forces";
    }
    return out;
  }

 private:
  static constexpr double kSpinLimit = 0.3;
};

}  // namespace

std::unique_ptr<TangentialModel> make_linear_sat(const TangentialModelOptions&) {
  return std::make_unique<LinearSaturated>();
}

}  // namespace railsim::contact
