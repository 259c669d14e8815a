// The engine's view of a track::Track (track/track.hpp): curvature, cant
// angle and rail irregularities by distance, as a TrackReference
// (track_frame.hpp). Sign conventions are the same in both libraries
// (curvature > 0 turns left; cant angle > 0 raises the right rail; rails
// y_left = y_a + g/2, z_left = z_v - c/2, ...).
#pragma once

#include <memory>

#include "engine/track_frame.hpp"
#include "track/track.hpp"

namespace railsim::engine {

class TrackInput final : public TrackReference {
 public:
  explicit TrackInput(std::shared_ptr<const track::Track> track) : track_(std::move(track)) {}
  void sample(double s, TrackSample& out) const override;
  void sample_alignment(double s, TrackSample& out) const override;
  std::string describe() const override;
  const track::Track& track() const { return *track_; }

 private:
  std::shared_ptr<const track::Track> track_;
};

}  // namespace railsim::engine
