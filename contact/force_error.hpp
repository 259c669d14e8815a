// Error of a tangential contact solution against a reference solution (e.g.
// a simplified model against the exact MIM solver), as used by
// `railsim compare-contact`.
//
// Definitions (our own choice, stated in the README and in the outputs):
//   F_ref   = |(Fx_ref, Fy_ref)|, the reference resultant tangential force;
//   scale_F = max(F_ref, 1e-3 mu Fz)  (the floor only matters at zero creepage);
//   Fx      = |Fx - Fx_ref| / scale_F,  Fy = |Fy - Fy_ref| / scale_F;
//   F       = |(Fx, Fy) - (Fx_ref, Fy_ref)| / scale_F  (vector difference, so
//             a wrong force direction counts as an error too);
//   Mz      = |Mz - Mz_ref| / max(|Mz_ref|, 1e-2 mu Fz c),  c = sqrt(a b)
//             (mu Fz c is the scale of the full-slip spin moment).
// All errors are fractions (0.1 = 10 %), relative to the reference, not to mu Fz,
// so small-creepage errors are not hidden by a large saturation force.
#pragma once

#include "contact/types.hpp"

namespace railsim::contact {

struct ForceError {
  double Fx = 0.0;
  double Fy = 0.0;
  double Mz = 0.0;
  double F = 0.0;  // resultant tangential force (vector difference)
};

// `in` supplies mu, Fz and the semi-axes for the floors of the scales.
ForceError force_error(const ContactForces& f, const ContactForces& ref, const ContactInput& in);

}  // namespace railsim::contact
