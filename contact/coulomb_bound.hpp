// The Coulomb bound on a tangential contact force: |(Fx, Fy)| <= mu Fz.
//
// Exact theory (Kalker 1990): the traction never exceeds mu p anywhere, so the
// total tangential force never exceeds mu Fz. Force-level laws (Polach's spin
// term superposed on the creep force, table interpolation, strip-model
// round-off) can give more; the law is enforced here for every model:
//   s = mu Fz / |(Fx, Fy)| < 1  ->  (Fx, Fy, Mz) <- s (Fx, Fy, Mz),
// i.e. the force is limited to mu Fz along its own direction (for the
// saturation laws the direction of the reduced creepage) and the spin moment
// is scaled alike (as the saturation laws scale it). A limit by more than
// 0.1 % (a real excess of the law, not round-off) flags the result invalid
// with the reason, unless the model already flagged it for its own reason.
// Units: N, N m; mu Fz > 0.
#pragma once

#include "contact/types.hpp"

namespace railsim::contact {

// Relative excess below which the limit is applied silently (round-off of
// the discretised models).
inline constexpr double kCoulombSilentExcess = 1e-3;

// Apply the bound to f for the limit muFz = mu Fz [N]; returns true when f
// was limited.
bool apply_coulomb_bound(ContactForces& f, double muFz);

}  // namespace railsim::contact
