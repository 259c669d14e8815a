// Reading the `running_safety:` section of a scenario (engine/analysis/safety_settings.hpp):
// values taken, defaults kept, bad keys and values refused naming file, line and key.
#include <catch2/catch.hpp>

#include "config/yaml_input.hpp"
#include "core/errors.hpp"
#include "engine/analysis/safety_settings.hpp"

using namespace railsim;
using namespace railsim::engine;

namespace {
SafetySettings read(const std::string& yaml) {
  return load_safety_settings(config::InputNode::load_string(yaml, "s.yaml").at("running_safety"));
}
}  // namespace

TEST_CASE("running_safety settings: values, defaults and errors", "[safety][settings]") {
  const SafetySettings s = read(
      "running_safety:\n  vehicle_category: freight\n  hunting_frequency_hz: 4.5\n  body_ends_m: [12.5, -12.5]\n"
      "  straight_min_radius: 8000\n");
  CHECK(s.category == VehicleCategory::freight);
  CHECK(track_shift_factor(s.category) == 0.85);
  CHECK(s.hunting_frequency == 4.5);
  CHECK(s.body_ends == std::vector<double>{12.5, -12.5});
  CHECK(s.zones.straight_min_radius == 8000.0);
  // The standard's processing stays as default.
  CHECK(s.force_lowpass == 20.0);
  CHECK(s.window == 2.0);
  CHECK(s.step == 0.5);
  CHECK(s.percentile_low == 0.15);
  CHECK(s.percentile_high == 99.85);
  CHECK(s.rms_window == 100.0);
  const SafetySettings d = read("running_safety: {}\n");
  CHECK(d.category == VehicleCategory::passenger);
  CHECK(d.hunting_frequency == 0.0);
  CHECK(d.body_ends.empty());
  for (const char* bad : {"running_safety: {vehicle_category: tram}\n", "running_safety: {hunting_frequency_hz: 0}\n",
                          "running_safety: {body_ends_m: []}\n", "running_safety: {straight_min_radius: 100}\n",
                          "running_safety: {window: 3}\n"}) {
    INFO(bad);
    try {
      read(bad);
      FAIL("accepted");
    } catch (const InputError& e) {
      const std::string msg = e.what();
      CHECK(msg.find("s.yaml:1") != std::string::npos);
      CHECK(msg.find("running_safety") != std::string::npos);
    }
  }
}
