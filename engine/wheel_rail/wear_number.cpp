// Wear number T-gamma; see wear_number.hpp.
#include "engine/wheel_rail/wear_number.hpp"

namespace railsim::engine {

double wear_number(const WheelOutput& w) {
  return w.Tgamma;
}

}  // namespace railsim::engine
