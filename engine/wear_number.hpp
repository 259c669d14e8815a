// Wear number T-gamma of one wheel: the frictional work per unit rolled
// distance in the contact patch,
//   T gamma = -(Fx xi + Fy eta + Mz phi)   [N = J/m]
// with (Fx, Fy, Mz) the creep forces and spin moment of the rail on the wheel
// in the contact plane and (xi, eta, phi) Kalker's creepages [-, -, 1/m]
// (creepages.hpp). The forces oppose the creepages, so T gamma >= 0 (for the
// linear theory it is f11 xi^2 + f22 eta^2 + f33 phi^2: the f23 cross terms
// cancel). The spin term Mz phi IS included; wear indices that drop it (e.g.
// the Whole Life Rail Model's T gamma = T_x gamma_x + T_y gamma_y) are smaller
// when the spin moment is large (flange contact). Source: Pearce & Sherratt
// (1991), Wear 144, 343-351 (energy dissipation approach; T gamma as the wear
// number). With several contact points per wheel (full wheelset model) the
// summed forces are paired with the creepages of the most loaded point.
#pragma once

#include "engine/data.hpp"

namespace railsim::engine {

double wear_number(const WheelOutput& w);

}  // namespace railsim::engine
