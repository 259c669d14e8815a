// Anti-roll bar: a torsional spring between the roll angles of two bodies,
//   M_a,x = -k_phi (phi_a - phi_b),  M_b,x = -M_a,x   [N m/rad].
// (The linkage geometry is folded into k_phi, as in Iwnicki 2006, ch. 7.)
#pragma once

#include <string>

#include "engine/elements/spring_damper.hpp"

namespace railsim::engine {

struct AntiRollBar {
  std::string name;
  int body_a = -1, body_b = -1;
  double stiffness = 0.0;  // [N m/rad]
};

void apply_anti_roll_bar(const AntiRollBar& e, const std::vector<BodyMotion>& m, std::vector<GenForce>& f);

}  // namespace railsim::engine
