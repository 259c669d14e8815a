// Registry of irregularity generators; see irregularity_registry.hpp.
#include "track/irregularity_registry.hpp"

#include "track/defects.hpp"
#include "track/measured_irregularity.hpp"
#include "track/psd_synthesis.hpp"

namespace railsim::track {

const std::vector<IrregularityGeneratorEntry>& irregularity_generators() {
  static const std::vector<IrregularityGeneratorEntry> table = {
      {"defect", "cosine bump(s) of a given wavelength and amplitude in one channel", &parse_cosine_defect},
      {"twist", "cross-level ramp over a base length (twist defect)", &parse_twist_defect},
      {"psd", "random irregularity synthesised from a track PSD (ERRI B176, FRA classes)", &parse_psd_irregularity},
      {"measured", "measured irregularities read from a CSV file", &parse_measured_irregularity},
  };
  return table;
}

std::string irregularity_generator_names() {
  std::string s;
  for (const auto& e : irregularity_generators()) s += (s.empty() ? "" : ", ") + std::string(e.name);
  return s;
}

const IrregularityGeneratorEntry* find_irregularity_generator(std::string_view name) {
  for (const auto& e : irregularity_generators())
    if (name == e.name) return &e;
  return nullptr;
}

}  // namespace railsim::track
