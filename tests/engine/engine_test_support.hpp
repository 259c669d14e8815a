// Scenario builders shared by the engine tests.
#pragma once

#include <string>

#include "engine/io/scenario.hpp"

namespace railsim::test {

// The single wheelset of physics-reference §8.1 (vehicles/single_wheelset.yaml)
// on straight perfect track at speed V, conical wheels, linear creep with
// f11 = f22 = f, wheelset roll held at zero (the textbook model). `extra` is appended to the scenario text (YAML).
engine::Scenario single_wheelset(double V, double f = 1.0e7, const std::string& vehicle = "vehicles/single_wheelset.yaml",
                                 const std::string& extra = "");
// A scenario text loaded relative to the source tree root.
engine::Scenario scenario_from_text(const std::string& text);

}  // namespace railsim::test
