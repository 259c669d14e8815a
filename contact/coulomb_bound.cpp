// The Coulomb bound and TangentialModel::solve; see coulomb_bound.hpp and
// tangential_model.hpp.
#include "contact/coulomb_bound.hpp"

#include <cmath>

#include "contact/tangential_model.hpp"

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

ContactForces TangentialModel::solve(const ContactInput& in, TangentialWorkspace* ws) const {
  ContactForces f = compute(in, ws);
  if (coulomb_bounded() && in.patch.Fz > 0.0) apply_coulomb_bound(f, friction_coefficient(in) * in.patch.Fz);
  return f;
}

}  // namespace railsim::contact
