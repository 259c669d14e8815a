// Wheel-rail coupling; see wheel_rail_coupling.hpp.
#include "engine/wheel_rail/wheel_rail_coupling.hpp"

#include <cmath>
#include <cstdio>

#include "contact/kalker_coefficients.hpp"
#include "contact/reduction.hpp"
#include "contact/registry.hpp"
#include "core/errors.hpp"

namespace railsim::engine {

WheelRailCoupling::WheelRailCoupling(const CouplingOptions& o) : opt_(o) {
  G_ = o.shear_modulus > 0 ? o.shear_modulus : o.material.shear_modulus();
  if (o.tangential != "coefficients") model_ = contact::make_tangential_model(o.tangential);
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
  if (used) *used = in;
  if (!model_) {
    double f11, f22, f23, f33;
    if (opt_.f11 > 0) {
      const double r = N / Nref;
      const double r23 = std::cbrt(r * r);
      f11 = opt_.f11 * r23;
      f22 = opt_.f22 * r23;
      f23 = opt_.f23 * r;
      f33 = opt_.f33 * r23 * r23;
    } else {
      const double ab = a * b, c = std::sqrt(ab);
      double C11 = g.C11, C22 = g.C22, C23 = g.C23, C33 = 0.0;  // C33 not in the tables (physics-reference §13 item 1)
      if (C11 <= 0.0 && a > 0 && b > 0) {  // no table coefficients: Kalker's table at this a/b (contact library)
        const contact::KalkerCoefficients k = contact::kalker_coefficients(a / b, opt_.material.nu);
        C11 = k.C11;
        C22 = k.C22;
        C23 = k.C23;
        C33 = k.C33;
      }
      f11 = G_ * ab * C11;
      f22 = G_ * ab * C22;
      f23 = G_ * ab * c * C23;
      f33 = G_ * ab * ab * C33;
    }
    f11 *= opt_.reduction.k11;
    f22 *= opt_.reduction.k22;
    f23 *= opt_.reduction.k23;
    f33 *= opt_.reduction.k23;
    out.Fx = -f11 * cr.xi;
    out.Fy = -f22 * cr.eta - f23 * cr.phi;
    out.Mz = f23 * cr.eta - f33 * cr.phi;
    if (opt_.saturation == "she") {
      const double F = std::hypot(out.Fx, out.Fy);
      const double muN = opt_.material.mu * N;
      if (F > 0) {
        const double u = F / muN;
        const double Fs = u < 3.0 ? muN * (u - u * u / 3.0 + u * u * u / 27.0) : muN;
        const double k = Fs / F;
        out.Fx *= k;
        out.Fy *= k;
        out.Mz *= k;
      }
    }
    return out;
  }
  return model_->solve(in, ws);
}

std::string WheelRailCoupling::describe() const {
  std::string s = opt_.tangential;
  if (!model_) s += opt_.f11 > 0 ? " (prescribed creep coefficients)" : " (Kalker coefficients from the geometry)";
  if (!model_ && opt_.saturation != "none") s += " + " + opt_.saturation + " saturation";
  s += ", reduction " + contact::describe_reduction(opt_.reduction);
  if (!opt_.spin) s += ", spin creepage off";
  return s;
}

}  // namespace railsim::engine
