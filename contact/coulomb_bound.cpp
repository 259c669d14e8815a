// The Coulomb bound and TangentialModel::solve beyond kFullSlipCreepage (the
// common path is inline); see coulomb_bound.hpp and tangential_model.hpp.
#include "contact/coulomb_bound.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string_view>

#include "contact/tangential_model.hpp"
#include "core/errors.hpp"

namespace railsim::contact {

bool apply_coulomb_bound(ContactForces& f, double muFz) {
  const double F = std::sqrt(f.Fx * f.Fx + f.Fy * f.Fy);
  if (!(F > muFz) || !(muFz >= 0.0)) return false;
  const double s = muFz / F;
  f.Fx *= s;
  f.Fy *= s;
  f.Mz *= s;
  if (F > muFz * (1.0 + kCoulombSilentExcess) && f.valid) {
    f.valid = false;
    f.reason = "the law's force exceeded mu Fz and was limited to mu Fz (direction kept)";
  }
  return true;
}

[[gnu::cold]] [[gnu::noinline]] void TangentialModel::throw_non_finite(const ContactInput& in) const {
  const std::string_view name = this->name();
  char buf[320];
  std::snprintf(buf, sizeof buf,
                "%.*s: non-finite creep force for xi = %g, eta = %g, phi = %g 1/m on a = %g m, b = %g m, Fz = %g N",
                int(name.size()), name.data(), in.creep.xi, in.creep.eta, in.creep.phi, in.patch.a, in.patch.b,
                in.patch.Fz);
  throw NumericalError(buf);
}

ContactForces TangentialModel::solve_deep_slip(const ContactInput& in, TangentialWorkspace* ws) const {
  const double c = std::sqrt(std::abs(in.patch.a * in.patch.b));
  const double m = std::max({std::abs(in.creep.xi), std::abs(in.creep.eta), std::abs(in.creep.phi) * c});
  ContactInput scaled = in;
  if (coulomb_bounded() && std::isfinite(m)) {
    const double s = kFullSlipCreepage / m;
    scaled.creep = {in.creep.xi * s, in.creep.eta * s, in.creep.phi * s};
  }
  ContactForces f = compute(scaled, ws);
  check_and_bound(in, scaled, f);
  return f;
}

}  // namespace railsim::contact
