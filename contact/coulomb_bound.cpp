// The Coulomb bound and TangentialModel::solve; see coulomb_bound.hpp and
// tangential_model.hpp.
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

namespace {
[[noreturn]] [[gnu::cold]] [[gnu::noinline]] void throw_non_finite(const TangentialModel& model, const ContactInput& in) {
  const std::string_view name = model.name();
  char buf[320];
  std::snprintf(buf, sizeof buf,
                "%.*s: non-finite creep force for xi = %g, eta = %g, phi = %g 1/m on a = %g m, b = %g m, Fz = %g N",
                int(name.size()), name.data(), in.creep.xi, in.creep.eta, in.creep.phi, in.patch.a, in.patch.b,
                in.patch.Fz);
  throw NumericalError(buf);
}

// A model's forces f for `in`, computed for `used` (in itself, or its creepages
// scaled down to kFullSlipCreepage): NumericalError when not finite, then the
// Coulomb bound with the model's friction coefficient for `used`.
inline void check_and_bound(const TangentialModel& model, const ContactInput& in, const ContactInput& used,
                            ContactForces& f) {
  if (!std::isfinite(f.Fx + f.Fy + f.Mz)) [[unlikely]]
    throw_non_finite(model, in);
  if (model.coulomb_bounded() && in.patch.Fz > 0.0)
    apply_coulomb_bound(f, model.friction_coefficient(used) * in.patch.Fz);
}
}  // namespace

ContactForces TangentialModel::solve(const ContactInput& in, TangentialWorkspace* ws) const {
  // Deep full slip (a bounded law): the force is mu Fz along a direction set by
  // the creepages' ratios alone, so creepages beyond kFullSlipCreepage are
  // scaled down to it, direction kept (their squares overflow beyond 1e154 and
  // the models' forces collapsed to 0 or NaN).
  const double k = kFullSlipCreepage, phi = in.creep.phi;
  if (std::abs(in.creep.xi) > k || std::abs(in.creep.eta) > k || phi * phi * std::abs(in.patch.a * in.patch.b) > k * k)
      [[unlikely]]
    return solve_deep_slip(in, ws);
  ContactForces f = compute(in, ws);
  check_and_bound(*this, in, in, f);
  return f;
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
  check_and_bound(*this, in, scaled, f);
  return f;
}

}  // namespace railsim::contact
