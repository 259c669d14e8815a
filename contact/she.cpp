// Model "she": Shen, Hedrick & Elkins (1983) saturation of Kalker's linear forces.
//
// Source: Shen, Hedrick & Elkins, "A comparison of alternative creep force models
// for rail vehicle dynamic analysis", Proc. 8th IAVSD Symposium (1983) 591-605;
// physics-reference.md sec. 4.3 [K]. With the linear forces F_lin including the
// spin term -f23 phi in Fy (linear_theory.hpp) and beta = |F_lin| / (mu Fz):
//   F_R / (mu Fz) = beta - beta^2/3 + beta^3/27 = 1 - (1 - beta/3)^3   (beta <= 3)
//                 = 1                                                  (beta > 3)
//   (Fx, Fy) = eps (Fx, Fy)_lin,  eps = F_R / |F_lin|;  Mz = eps Mz_lin (common
//   practice, not universal [U]).
// Slope at zero creepage = linear theory; C1-smooth saturation at beta = 3.
// Validity: spin enters only through the linear C23 term, which over-estimates the
// lateral force at large spin (the known weakness of SHE). Flagged when the
// normalised spin psi = |f23 phi| / (mu Fz) exceeds 0.3 (provisional limit, to be
// revisited against the exact solver).
// Units: SI; signs as in types.hpp.
#include "contact/she.hpp"

#include <cmath>

#include "contact/registry.hpp"

namespace railsim::contact {

namespace {

constexpr double kSpinLimit = 0.3;  // psi = |f23 phi| / (mu Fz) beyond which SHE flags its result

class ShenHedrickElkins final : public TangentialModel {
 public:
  std::string_view name() const override { return "she"; }
  ContactForces compute(const ContactInput& in, TangentialWorkspace*) const override {
    return she_forces(linear_coefficients(in), in);
  }
};

}  // namespace

ContactForces she_forces(const LinearCoefficients& f, const ContactInput& in) {
  const LinearForces lin = linear_forces(f, in.creep);
  const double bound = in.material.mu * in.patch.Fz;
  const double beta = norm2(lin.Fx, lin.Fy) / bound;
  double eps = 1.0;  // F_R / |F_lin|, limit 1 at beta -> 0
  if (beta > 3.0)
    eps = 1.0 / beta;
  else if (beta > 0.0)
    eps = 1.0 - beta / 3.0 + beta * beta / 27.0;
  ContactForces out = scaled_forces(lin, eps);
  if (spin_measure(f, in) > kSpinLimit) {
    out.valid = false;
    out.reason = "large spin (|f23 phi| > 0.3 mu Fz): SHE over-estimates the spin force";
  }
  return out;
}

std::unique_ptr<TangentialModel> make_she(const TangentialModelOptions&) {
  return std::make_unique<ShenHedrickElkins>();
}

}  // namespace railsim::contact
