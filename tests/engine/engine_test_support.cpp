#include "engine_test_support.hpp"

#include "config/yaml_input.hpp"
#include "test_support.hpp"

namespace railsim::test {

engine::Scenario scenario_from_text(const std::string& text) {
  return engine::load_scenario(config::InputNode::load_string(text, "test_scenario.yaml"), source_path(""));
}

engine::Scenario single_wheelset(double V, double f, const std::string& vehicle, const std::string& extra) {
  const std::string text =
      "vehicle: " + vehicle + "\n"
      "track: {segments: [{type: straight, length: 5000}]}\n"
      "speed: " + std::to_string(V) + "\n"
      "duration: 1\n"
      "wheelset_roll: none\n"
      "contact:\n"
      "  geometry: {type: conical, r0: 0.46, conicity: 0.2, l0: 0.75, contact_angle: 0}\n"
      "  tangential: coefficients\n"
      "  creep_coefficients: {f11: " + std::to_string(f) + ", f22: " + std::to_string(f) + "}\n"
      "  spin: false\n" + extra;
  return scenario_from_text(text);
}

}  // namespace railsim::test
