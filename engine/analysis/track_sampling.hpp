// Sampling a track along its length for plotting and checking (`railsim track`):
// the alignment and irregularity state every `step` metres over [from, to]
// (the last sample clamped to `to`), with the cant deficiency at a given speed,
// and per irregularity channel the largest |r| and the RMS over the samples [m].
// Samples are handed to a callback as they are taken (a long track gives
// millions of rows; nothing is kept). Signs and units: track/track.hpp (SI).
#pragma once

#include <array>
#include <functional>
#include <optional>

#include "track/track.hpp"

namespace railsim::engine {

struct TrackSample {
  double s = 0.0;                 // [m]
  track::TrackState state;
  double cant_deficiency = 0.0;   // [m] at the given speed; NaN without one
};

struct TrackSamplingStats {
  long rows = 0;
  std::array<double, track::kChannelCount> max_abs{};  // [m]
  std::array<double, track::kChannelCount> rms{};      // [m]
};

// Number of samples over [from, to] every `step`, the end included (one more
// when the step does not divide the range: the last sample is `to`).
double track_sample_count(double from, double to, double step);

// speed [m/s]: for the cant deficiency (none: NaN in every sample).
TrackSamplingStats sample_track(const track::Track& track, double from, double to, double step,
                                std::optional<double> speed, const std::function<void(const TrackSample&)>& sample);

}  // namespace railsim::engine
