// Settings of the running-safety evaluation; see safety_settings.hpp.
#include "engine/analysis/safety_settings.hpp"

namespace railsim::engine {

SafetySettings load_safety_settings(const config::InputNode& n) {
  n.allow_only({"vehicle_category", "hunting_frequency_hz", "body_ends_m", "straight_min_radius"});
  SafetySettings s;
  if (auto c = n.find("vehicle_category")) {
    const std::string v = c->as_string();
    if (v == "passenger") s.category = VehicleCategory::passenger;
    else if (v == "locomotive") s.category = VehicleCategory::locomotive;
    else if (v == "multiple_unit") s.category = VehicleCategory::multiple_unit;
    else if (v == "freight") s.category = VehicleCategory::freight;
    else c->fail("expected passenger, locomotive, multiple_unit or freight (got '" + v + "')");
  }
  if (n.has("hunting_frequency_hz")) s.hunting_frequency = n.in_range("hunting_frequency_hz", 0.5, 30.0);
  if (auto e = n.find("body_ends_m")) {
    s.body_ends = e->as_numbers();
    if (s.body_ends.empty() || s.body_ends.size() > 8) e->fail("expected 1 to 8 positions [m]");
  }
  if (n.has("straight_min_radius"))
    s.zones.straight_min_radius = n.in_range("straight_min_radius", s.zones.large_min_radius, 1e7);
  return s;
}

}  // namespace railsim::engine
