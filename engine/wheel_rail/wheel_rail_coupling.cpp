// Wheel-rail coupling; see wheel_rail_coupling.hpp.
#include "engine/wheel_rail/wheel_rail_coupling.hpp"

#include <cmath>
#include <cstdio>

#include "contact/reduction.hpp"
#include "contact/registry.hpp"
#include "core/errors.hpp"

namespace railsim::engine {

WheelRailCoupling::WheelRailCoupling(const CouplingOptions& o) : opt_(o) {
  contact::TangentialModelOptions mo;
  mo.saturation = o.saturation;
  model_ = contact::make_tangential_model(o.tangential, mo);
}

std::unique_ptr<contact::TangentialWorkspace> WheelRailCoupling::make_workspace() const {
  return model_ ? model_->make_workspace() : nullptr;
}

contact::ContactForces WheelRailCoupling::forces(const ContactPointGeometry& g, double N, double N_static,
                                                 const contact::Creepages& cr_in, double V,
                                                 contact::TangentialWorkspace* ws,
                                                 contact::ContactInput* used) const {
  contact::ContactForces out;
  if (N <= 1.0) return out;  // no load, no creep force (DYTSI: N <= 1 N)
  contact::Creepages cr = cr_in;
  if (!opt_.spin) cr.phi = 0.0;
  const double Nref = opt_.N_ref > 0 ? opt_.N_ref : N_static;
  // Patch semi-axes at the current load.
  double a = 0.0, b = 0.0;
  if (g.semi_a > 0 && g.N0 > 0) {
    const double s = std::cbrt(N / g.N0);
    a = g.semi_a * s;
    b = g.semi_b * s;
  } else if (opt_.patch_a > 0) {
    const double s = std::cbrt(N / Nref);
    a = opt_.patch_a * s;
    b = opt_.patch_b * s;
  }
  contact::ContactInput in;
  in.patch.a = a;
  in.patch.b = b;
  in.patch.Fz = N;
  in.patch.A = g.A;
  in.patch.B = g.B;
  in.patch.p0 = (a > 0 && b > 0) ? 1.5 * N / (M_PI * a * b) : 0.0;
  in.creep = cr;
  in.material = opt_.material;
  in.reduction = opt_.reduction;
  in.rolling_speed = V;
  // The geometry's creep coefficients (read by the model "coefficients" only):
  // prescribed at N_ref, else the table's C11, C22, C23 (no C33 in the tables,
  // physics-reference §13 item 1).
  contact::GeometryCoefficients& k = in.coefficients;
  if (opt_.f11 > 0) {
    k.f11 = opt_.f11;
    k.f22 = opt_.f22;
    k.f23 = opt_.f23;
    k.f33 = opt_.f33;
    k.Fz_ref = Nref;
  } else {
    k.C11 = g.C11;
    k.C22 = g.C22;
    k.C23 = g.C23;
  }
  k.shear_modulus = opt_.shear_modulus;
  if (used) *used = in;
  return model_->solve(in, ws);
}

std::string WheelRailCoupling::describe() const {
  std::string s = opt_.tangential;
  if (contact::find_tangential_model(opt_.tangential).geometry_coefficients) {
    s += opt_.f11 > 0 ? " (prescribed creep coefficients)" : " (Kalker coefficients from the geometry)";
    if (opt_.saturation != "none") s += " + " + opt_.saturation + " saturation";
  }
  s += ", reduction " + contact::describe_reduction(opt_.reduction);
  if (!opt_.spin) s += ", spin creepage off";
  return s;
}

}  // namespace railsim::engine
