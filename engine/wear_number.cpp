// Wear number T-gamma; see wear_number.hpp.
#include "engine/wear_number.hpp"

namespace railsim::engine {

double wear_number(const WheelOutput& w) {
  return -(w.Fx * w.creep.xi + w.Fy * w.creep.eta + w.Mz * w.creep.phi);
}

}  // namespace railsim::engine
