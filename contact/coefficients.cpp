// Model "coefficients": Kalker's linear theory on the creep coefficients the
// contact geometry gives (ContactInput::coefficients, types.hpp), saturated by
// a law chosen once when the model is built (TangentialModelOptions::saturation,
// registry.hpp: "none" = the linear theory as model "linear", "she" = the
// Shen-Hedrick-Elkins cubic on the resultant as model "she"; DYTSI's creep law,
// cooperrider-car.md sec. 7.5).
//
// Coefficients in force units (Kalker 1990 App. E; physics-reference.md sec. 2.1),
// the first that is given:
//   - prescribed at the load Fz_ref, scaled with r = Fz / Fz_ref (Hertz):
//       f11 = f11_ref r^(2/3), f22 = f22_ref r^(2/3), f23 = f23_ref r, f33 = f33_ref r^(4/3);
//   - the geometry's C_ij at this patch (c^2 = ab):
//       f11 = G c^2 C11, f22 = G c^2 C22, f23 = G c^3 C23, f33 = G c^4 C33;
//   - neither: the same with Kalker's C_ij at the patch's a/b (kalker_coefficients.hpp);
//     without a patch (a or b zero) the coefficients and forces are zero;
// then the reductions f11 k11, f22 k22, f23 k23, f33 k23 and the law:
//   Fx = -f11 xi, Fy = -f22 eta - f23 phi, Mz = f23 eta - f33 phi, saturated.
// G is GeometryCoefficients::shear_modulus when given, else the material's.
// Validity flags are the laws': "none" beyond |F| > 0.3 mu Fz (linear_theory.hpp),
// "she" beyond |f23 phi| > 0.3 mu Fz (she.hpp).
// Units: SI (f11, f22 in N, f23 in N m, f33 in N m^2); signs as in types.hpp.
#include <cmath>
#include <string>

#include "contact/kalker_coefficients.hpp"
#include "contact/linear_theory.hpp"
#include "contact/registry.hpp"
#include "core/errors.hpp"

namespace railsim::contact {

namespace {

// The coefficients of the header, reductions included. No allocation.
LinearCoefficients geometry_coefficients(const ContactInput& in) {
  const GeometryCoefficients& g = in.coefficients;
  if (!(std::isfinite(in.patch.Fz) && in.patch.Fz > 0.0))
    throw InputError("contact input: normal load Fz [N] expected a positive number (model coefficients)");
  if (!(std::isfinite(in.material.mu) && in.material.mu > 0.0))
    throw InputError("contact input: friction coefficient mu expected a positive number (model coefficients)");
  LinearCoefficients f;
  if (g.f11 > 0.0) {
    if (!(g.Fz_ref > 0.0))
      throw InputError("contact input: reference load Fz_ref [N] of the prescribed creep coefficients expected a "
                       "positive number (model coefficients)");
    const double r = in.patch.Fz / g.Fz_ref;
    const double r23 = std::cbrt(r * r);
    f = {g.f11 * r23, g.f22 * r23, g.f23 * r, g.f33 * r23 * r23};
  } else {
    const double a = in.patch.a, b = in.patch.b;
    const double G = g.shear_modulus > 0 ? g.shear_modulus : in.material.shear_modulus();
    const double ab = a * b, c = std::sqrt(ab);
    KalkerCoefficients C{g.C11, g.C22, g.C23, g.C33};
    if (C.C11 <= 0.0 && a > 0 && b > 0) C = kalker_coefficients(a / b, in.material.nu);
    f = {G * ab * C.C11, G * ab * C.C22, G * ab * c * C.C23, G * ab * ab * C.C33};
  }
  f.f11 *= in.reduction.k11;
  f.f22 *= in.reduction.k22;
  f.f23 *= in.reduction.k23;
  f.f33 *= in.reduction.k23;
  return f;
}

class GeometryCoefficientsModel final : public TangentialModel {
 public:
  explicit GeometryCoefficientsModel(const SaturationLawEntry& law) : law_(law) {}
  std::string_view name() const override { return "coefficients"; }
  bool coulomb_bounded() const override { return law_.coulomb_bounded; }
  ContactForces compute(const ContactInput& in, TangentialWorkspace*) const override {
    return law_.forces(geometry_coefficients(in), in);
  }

 private:
  const SaturationLawEntry& law_;  // an entry of the static table saturation_laws()
};

}  // namespace

std::unique_ptr<TangentialModel> make_coefficients(const TangentialModelOptions& o) {
  return std::make_unique<GeometryCoefficientsModel>(find_saturation_law(o.saturation));
}

}  // namespace railsim::contact
