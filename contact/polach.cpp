// Polach's creep-force method; see polach.hpp for equations, sources and validity.
#include "contact/polach.hpp"

#include <cmath>
#include <cstdio>
#include <string>

#include "contact/kalker_coefficients.hpp"
#include "contact/linear_theory.hpp"
#include "contact/registry.hpp"
#include "core/errors.hpp"

namespace railsim::contact {

namespace {

constexpr double kPi = 3.14159265358979323846;

// (2/pi) [kA e / (1 + (kA e)^2) + atan(kS e)]: force over mu Fz.
double polach_law(double e, double kA, double kS) {
  const double ae = kA * e;
  return (2.0 / kPi) * (ae / (1.0 + ae * ae) + std::atan(kS * e));
}

class Polach final : public TangentialModel {
 public:
  explicit Polach(const PolachParameters& p) : p_(p) {}
  std::string_view name() const override { return "polach"; }
  // Polach's friction mu(w) = mu0 [(1 - A) exp(-B w) + A] bounds the force.
  double friction_coefficient(const ContactInput& in) const override {
    const double mu0 = p_.mu0 > 0.0 ? p_.mu0 : in.material.mu;
    const double w = norm2(in.creep.xi, in.creep.eta) * std::abs(in.rolling_speed);
    return mu0 * ((1.0 - p_.A) * std::exp(-p_.B * w) + p_.A);
  }

  ContactForces compute(const ContactInput& in, TangentialWorkspace*) const override {
    const LinearCoefficients f = linear_coefficients(in);  // checks the input
    const double a = in.patch.a, b = in.patch.b;
    const double Fz = in.patch.Fz;
    const double xi = in.creep.xi, eta = in.creep.eta, phi = in.creep.phi;
    const double s = norm2(xi, eta);
    const double muN = friction_coefficient(in) * Fz;

    ContactForces out;
    // Translational creepage. f11 = G ab k11 C11, so G pi a b C_jj s / 4 = (pi/4) |(f11 xi, f22 eta)|.
    const double Flin_t = norm2(f.f11 * xi, f.f22 * eta);
    if (s > 0.0) {
      const double e = 0.25 * kPi * Flin_t / muN;
      const double F = muN * polach_law(e, p_.kA, p_.kS);
      out.Fx = -F * xi / s;
      out.Fy = -F * eta / s;
    }
    // Spin: lateral force.
    if (phi != 0.0) {
      const double syC = eta + phi * a;
      const double sC = std::abs(syC) <= std::abs(eta) ? s : norm2(xi, syC);
      const double shape = 1.0 + 6.3 * (1.0 - std::exp(-a / b));
      // f23 = G (ab)^{3/2} k23 C23, so G b sqrt(ab) k23 C23 = f23 / a.
      const double eS = (8.0 / 3.0) * (f.f23 / a) * sC / (muN * shape);
      const double e2 = eS * eS;
      const double d = (e2 - 1.0) / (e2 + 1.0);
      const double one_m_d2 = 1.0 - d * d;
      const double KM = eS * (d * d * d / 3.0 - d * d / 2.0 + 1.0 / 6.0) - std::sqrt(one_m_d2 * one_m_d2 * one_m_d2) / 3.0;
      out.Fy += (9.0 / 16.0) * a * muN * KM * shape * phi / sC;
    }
    // Spin moment: linear Mz times the law's saturation ratio for the total linear force.
    const LinearForces lin = linear_forces(f, in.creep);
    const double Flin = norm2(lin.Fx, lin.Fy);
    if (Flin > 0.0) {
      const double e = 0.25 * kPi * Flin / muN;
      out.Mz = lin.Mz * muN * polach_law(e, p_.kA, p_.kS) / Flin;
    } else {
      out.Mz = lin.Mz;
    }
    const double ab = a / b;
    if (ab < kKalkerTableMinAspect || ab > kKalkerTableMaxAspect) {
      out.valid = false;
      out.reason = "a/b outside [0.1, 10], where Polach's spin factor is fitted";
    } else if (norm2(out.Fx, out.Fy) > muN * (1.0 + 1e-9)) {
      out.valid = false;
      out.reason = "spin and creep forces superposed above mu Fz: limited to mu Fz";
    }
    return out;
  }

 private:
  PolachParameters p_;
};

void check(bool ok, const char* what, const char* range, double v) {
  if (ok) return;
  char buf[48];
  std::snprintf(buf, sizeof buf, "%g", v);
  throw InputError(std::string("polach: ") + what + " expected " + range + " (got " + buf + ")");
}

}  // namespace

std::unique_ptr<TangentialModel> make_polach_model(const PolachParameters& p) {
  check(std::isfinite(p.kA) && p.kA > 0.0 && p.kA <= 1.0, "kA", "a number in (0, 1]", p.kA);
  check(std::isfinite(p.kS) && p.kS > 0.0 && p.kS <= p.kA, "kS", "a number in (0, kA]", p.kS);
  check(std::isfinite(p.mu0) && p.mu0 >= 0.0, "mu0", "a number >= 0 (0: material mu)", p.mu0);
  check(std::isfinite(p.A) && p.A > 0.0 && p.A <= 1.0, "A", "a number in (0, 1]", p.A);
  check(std::isfinite(p.B) && p.B >= 0.0, "B [s/m]", "a number >= 0", p.B);
  return std::make_unique<Polach>(p);
}

std::unique_ptr<TangentialModel> make_polach(const TangentialModelOptions&) {
  return make_polach_model(PolachParameters{});
}

}  // namespace railsim::contact
