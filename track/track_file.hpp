// Loading a Track from YAML (tracks/*.yaml). Format:
//
//   name: curve_R300                # optional, default: file stem
//   description: "..."              # optional
//   rail_spacing: 1.5               # 2b [m], distance of the rail centres (cant angle)
//   gauge: 1.435                    # nominal gauge [m]
//   start: {x: 0, y: 0, heading_deg: 0}   # optional pose at s = 0 (|x|, |y| <= 1e7 m, |heading| <= 360 deg)
//   segments:
//     - {type: straight, length: 50}
//     - {type: clothoid, length: 30, shape: linear}      # linear | bloss | cosine
//     - {type: circular, length: 60, radius: 300, direction: left, cant_mm: 150}
//     - {type: clothoid, length: 30}
//     - {type: straight, length: 100}
//   irregularities:                 # optional, summed; generators by name:
//     - {type: defect, channel: lateral, start: 80, wavelength: 20, amplitude_mm: 10}
//     - {type: twist, start: 150, base_length: 3, amplitude_mm: 15}
//     - {type: psd, spectrum: erri_low, seed: 1, wavelength_min: 3, wavelength_max: 150}
//     - {type: measured, file: survey.csv, units: mm}
//
// A clothoid takes its start curvature and cant from the segment before it and
// its end values from the segment after it (zero at the track ends), so the
// radius and cant are written once, on the circular curve. Every error names
// the file, line and segment: "f.yaml:7: segments[2] (clothoid): key 'length':
// expected a positive number (got 0)". Unknown keys are refused.
#pragma once

#include <memory>
#include <string>

#include "config/yaml_input.hpp"
#include "track/track.hpp"

namespace railsim::track {

// Load a track file; relative file names inside (measured data) are resolved
// against the folder of the YAML file. Throws InputError.
Track load_track(const std::string& path);
// Same, from an already parsed node (embedded in a scenario); `base_dir` is the
// folder for relative file names.
Track load_track(const config::InputNode& root, const std::string& base_dir, const std::string& default_name);

}  // namespace railsim::track
