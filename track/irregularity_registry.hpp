// Registry of irregularity generators, chosen by name in a track file's
// `irregularities:` list ("defect", "twist", "psd", "measured"). Adding a
// generator is adding one file (with its parse function) and one line in
// irregularity_registry.cpp.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "config/yaml_input.hpp"
#include "track/irregularity.hpp"

namespace railsim::track {

// What a generator may need to know about the track it belongs to.
struct IrregularityContext {
  double track_length = 0.0;  // [m]
  double rail_spacing = 1.5;  // 2b [m]
  std::string base_dir;       // folder of the track file (relative data files)
  // Legal but doubtful input ("file:line: key 'k': ..."), kept by the Track
  // (Track::warnings); nullptr: not collected.
  std::vector<std::string>* warnings = nullptr;
};

// Build a component from its YAML mapping (the `type` key is already known and
// allowed); throws InputError with file:line:key.
using IrregularityParser = std::unique_ptr<IrregularityComponent> (*)(const config::InputNode& node,
                                                                      const IrregularityContext& context);

struct IrregularityGeneratorEntry {
  const char* name;
  const char* description;
  IrregularityParser parse;
};

const std::vector<IrregularityGeneratorEntry>& irregularity_generators();
// "defect, twist, psd, measured".
std::string irregularity_generator_names();
// nullptr when the name is unknown.
const IrregularityGeneratorEntry* find_irregularity_generator(std::string_view name);

}  // namespace railsim::track
