// Scenario variants from the command line: `--set key=value` for any key of a
// scenario file and `--speed-kmh V`, applied to the YAML tree before it is
// read, so no copied YAML is needed (`railsim run`).
//
// Keys are dotted paths from the top of the scenario; a sequence element is
// [i] (0-based) and a key holding dots is written in brackets:
//   contact.material.mu=0.2    track.segments[2].radius=500
//   integrator.max_step=1e-3   initial[ws1.lateral]=0.007
// Values are YAML (numbers, strings, {flow: maps}, [lists]). Missing mappings
// on the way are created; a path through a value (e.g. into `track` when the
// scenario names a track file) is refused. Setting `speed` removes
// `speed_kmh` and the reverse (a scenario gives exactly one; one command line
// giving it twice is refused). Relative paths,
// in the file or in a value, resolve from the scenario's own folder as always.
// Every error about an overridden key (unknown key, value out of range,
// malformed option) is an InputError that starts with the option, e.g.
//   --set contact.material.mu=abc: scenario.yaml:18: key 'contact.material.mu': expected a number (got abc)
#pragma once

#include <string>
#include <vector>

#include "config/yaml_input.hpp"
#include "engine/io/scenario.hpp"

namespace railsim::cli {

struct ScenarioOverride {
  std::string option;  // as typed, for messages: "--set contact.material.mu=0.2"
  std::vector<std::string> path;  // components ("[3]" for a sequence index)
  std::string key;     // path as the input reader names it: "contact.material.mu", "track.segments[2].radius"
  std::string value;   // YAML text
};

// Parse "key=value" of a --set option; InputError naming the option otherwise.
ScenarioOverride parse_set_option(const std::string& text);
// The --speed-kmh override (speed_kmh = v; v checked by the scenario reader).
ScenarioOverride speed_kmh_override(double v);

struct LoadedScenario {
  engine::Scenario scenario;
  config::InputNode root;  // the YAML tree after the overrides
};

// Refuse overrides that contradict each other (InputError naming both options):
// the speed given twice (speed, speed_kmh, --speed-kmh) unless identical, one
// key given two different values, or a key inside another key's value
// (contact.material.mu and contact.material={...}), whose result would depend
// on the order of the options. A key repeated with the same value is accepted.
void check_overrides_agree(const std::vector<ScenarioOverride>& overrides);

// Read `path`, check the overrides agree, apply them in order, load the scenario (engine/io/scenario.hpp).
LoadedScenario load_scenario_with_overrides(const std::string& path, const std::vector<ScenarioOverride>& overrides);

// Rethrow an InputError about an overridden key with the option in front (otherwise unchanged).
[[noreturn]] void rethrow_for_overrides(const InputError& e, const std::vector<ScenarioOverride>& overrides);

}  // namespace railsim::cli
