// Kalker's linear theory; see linear_theory.hpp.
#include "contact/linear_theory.hpp"

#include <cmath>
#include <cstdio>
#include <string>

#include "contact/kalker_coefficients.hpp"
#include "contact/registry.hpp"
#include "core/errors.hpp"

namespace railsim::contact {

namespace {

[[noreturn]] void bad(const char* what, const char* range, double v) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%g", v);
  throw InputError(std::string("contact input: ") + what + " expected " + range + " (got " + buf + ")");
}

void check_input(const ContactInput& in) {
  const auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  if (!positive(in.patch.a)) bad("semi-axis a [m]", "a positive number", in.patch.a);
  if (!positive(in.patch.b)) bad("semi-axis b [m]", "a positive number", in.patch.b);
  if (!positive(in.patch.Fz)) bad("normal load Fz [N]", "a positive number", in.patch.Fz);
  if (!positive(in.material.E)) bad("Young's modulus E [Pa]", "a positive number", in.material.E);
  if (!(std::isfinite(in.material.nu) && in.material.nu > 0.0 && in.material.nu <= 0.5))
    bad("Poisson's ratio nu", "a number in (0, 0.5]", in.material.nu);
  if (!positive(in.material.mu)) bad("friction coefficient mu", "a positive number", in.material.mu);
  if (!std::isfinite(in.creep.xi)) bad("creepage xi", "a finite number", in.creep.xi);
  if (!std::isfinite(in.creep.eta)) bad("creepage eta", "a finite number", in.creep.eta);
  if (!std::isfinite(in.creep.phi)) bad("spin creepage phi [1/m]", "a finite number", in.creep.phi);
  const double k[3] = {in.reduction.k11, in.reduction.k22, in.reduction.k23};
  const char* names[3] = {"reduction factor k11", "reduction factor k22", "reduction factor k23"};
  for (int i = 0; i < 3; ++i)
    if (!(std::isfinite(k[i]) && k[i] > 0.0 && k[i] <= 1.5)) bad(names[i], "a number in (0, 1.5]", k[i]);
}

// Model "linear": Kalker's linear theory, no saturation.
class LinearTheory final : public TangentialModel {
 public:
  std::string_view name() const override { return "linear"; }
  bool coulomb_bounded() const override { return false; }  // the unsaturated theory by definition
  ContactForces compute(const ContactInput& in, TangentialWorkspace*) const override {
    return linear_theory_forces(linear_coefficients(in), in);
  }
};

constexpr double kSmallCreepageLimit = 0.3;  // |F| / (mu Fz) beyond which "linear" flags its result

}  // namespace

ContactForces linear_theory_forces(const LinearCoefficients& f, const ContactInput& in) {
  ContactForces out = scaled_forces(linear_forces(f, in.creep), 1.0);
  if (norm2(out.Fx, out.Fy) > kSmallCreepageLimit * in.material.mu * in.patch.Fz) {
    out.valid = false;
    out.reason = "linear theory beyond small creepage (|F| > 0.3 mu Fz)";
  }
  return out;
}

LinearCoefficients linear_coefficients(const ContactInput& in) {
  check_input(in);
  const KalkerCoefficients C = kalker_coefficients(in.patch.a / in.patch.b, in.material.nu);
  const double G = in.material.shear_modulus();
  const double c2 = in.patch.a * in.patch.b;
  const double c = std::sqrt(c2);
  return {G * c2 * in.reduction.k11 * C.C11, G * c2 * in.reduction.k22 * C.C22,
          G * c2 * c * in.reduction.k23 * C.C23, G * c2 * c2 * in.reduction.k23 * C.C33};
}

LinearForces linear_forces(const LinearCoefficients& f, const Creepages& c) {
  LinearForces l;
  l.Fy_spin = -f.f23 * c.phi;
  l.Fx = -f.f11 * c.xi;
  l.Fy = -f.f22 * c.eta + l.Fy_spin;
  l.Mz = f.f23 * c.eta - f.f33 * c.phi;
  return l;
}

ContactForces scaled_forces(const LinearForces& lin, double eps) {
  ContactForces out;
  out.Fx = eps * lin.Fx;
  out.Fy = eps * lin.Fy;
  out.Mz = eps * lin.Mz;
  return out;
}

double spin_measure(const LinearCoefficients& f, const ContactInput& in) {
  return std::abs(f.f23 * in.creep.phi) / (in.material.mu * in.patch.Fz);
}

std::unique_ptr<TangentialModel> make_linear_theory(const TangentialModelOptions&) {
  return std::make_unique<LinearTheory>();
}

}  // namespace railsim::contact
