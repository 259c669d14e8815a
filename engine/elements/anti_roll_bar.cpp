// Anti-roll bar; see anti_roll_bar.hpp.
#include "engine/elements/anti_roll_bar.hpp"

namespace railsim::engine {

void apply_anti_roll_bar(const AntiRollBar& e, const std::vector<BodyMotion>& m, std::vector<GenForce>& f) {
  const double pa = e.body_a >= 0 ? m[e.body_a].q[kRoll] : 0.0;
  const double pb = e.body_b >= 0 ? m[e.body_b].q[kRoll] : 0.0;
  const double M = -e.stiffness * (pa - pb);
  if (e.body_a >= 0) f[e.body_a][kRoll] += M;
  if (e.body_b >= 0) f[e.body_b][kRoll] -= M;
}

}  // namespace railsim::engine
