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
// number). With several loaded points per wheel (two-point contact: tread and
// flange root or flange) the frictional work is the sum over the points, each
// point's forces with its own creepages: the flange patch's spin and lateral
// creepage differ from the tread's, and pairing the summed forces with one
// point's creepages misstates T gamma. (On S1002/UIC60 1:40 the flange root's
// loaded strips stay one patch, so the coach's runs are unchanged by this.)
#pragma once

#include "contact/types.hpp"
#include "engine/data.hpp"

namespace railsim::engine {

// T gamma of one contact point: its creep forces and spin moment with its creepages.
inline double point_wear_number(const contact::ContactForces& f, const contact::Creepages& c) {
  return -(f.Fx * c.xi + f.Fy * c.eta + f.Mz * c.phi);
}

// T gamma of a wheel: the sum over its loaded points (WheelOutput::Tgamma,
// accumulated by the wheelset's contact loop).
double wear_number(const WheelOutput& w);

}  // namespace railsim::engine
