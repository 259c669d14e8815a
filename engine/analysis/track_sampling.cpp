// Sampling a track along its length; see track_sampling.hpp.
#include "engine/analysis/track_sampling.hpp"

#include <algorithm>
#include <cmath>

namespace railsim::engine {

double track_sample_count(double from, double to, double step) {
  const double whole = std::floor((to - from) / step + 1e-9);  // steps inside [from, to]
  // Plus the end itself when the step does not divide the range (it was dropped).
  return whole + 1.0 + (from + whole * step < to - 1e-9 * step ? 1.0 : 0.0);
}

TrackSamplingStats sample_track(const track::Track& track, double from, double to, double step,
                                std::optional<double> speed, const std::function<void(const TrackSample&)>& sample) {
  TrackSamplingStats st;
  st.rows = static_cast<long>(track_sample_count(from, to, step));
  std::array<double, track::kChannelCount> sumsq{};
  TrackSample smp;
  for (long j = 0; j < st.rows; ++j) {
    smp.s = std::min(from + static_cast<double>(j) * step, to);
    smp.state = track.at(smp.s);
    smp.cant_deficiency = speed ? track.cant_deficiency(smp.s, *speed) : std::nan("");
    sample(smp);
    for (std::size_t c = 0; c < sumsq.size(); ++c) {
      const double r = smp.state.irregularity.value[c];
      st.max_abs[c] = std::max(st.max_abs[c], std::abs(r));
      sumsq[c] += r * r;
    }
  }
  for (std::size_t c = 0; c < sumsq.size(); ++c) st.rms[c] = std::sqrt(sumsq[c] / static_cast<double>(st.rows));
  return st;
}

}  // namespace railsim::engine
