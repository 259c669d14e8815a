// Error of a tangential solution against a reference; see force_error.hpp.
#include "contact/force_error.hpp"

#include <algorithm>
#include <cmath>

namespace railsim::contact {

ForceError force_error(const ContactForces& f, const ContactForces& ref, const ContactInput& in) {
  const double muFz = in.material.mu * in.patch.Fz;
  const double c = std::sqrt(in.patch.a * in.patch.b);
  const double scale_F = std::max(std::hypot(ref.Fx, ref.Fy), 1e-3 * muFz);
  const double scale_M = std::max(std::abs(ref.Mz), 1e-2 * muFz * c);
  ForceError e;
  e.Fx = std::abs(f.Fx - ref.Fx) / scale_F;
  e.Fy = std::abs(f.Fy - ref.Fy) / scale_F;
  e.F = std::hypot(f.Fx - ref.Fx, f.Fy - ref.Fy) / scale_F;
  e.Mz = std::abs(f.Mz - ref.Mz) / scale_M;
  return e;
}

}  // namespace railsim::contact
