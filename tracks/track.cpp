// Track = alignment + irregularities; see track.hpp.
#include "tracks/track.hpp"

#include "tracks/cant.hpp"

namespace railsim::tracks {

Track::Track(std::string name, Alignment alignment, IrregularitySet irregularities, double gauge)
    : name_(std::move(name)),
      alignment_(std::move(alignment)),
      irregularities_(std::move(irregularities)),
      gauge_(gauge) {}

double Track::cant_deficiency(double s, double speed) const {
  const AlignmentState a = alignment_.at(s);
  return tracks::cant_deficiency(speed, a.curvature, a.cant, alignment_.rail_spacing());
}

}  // namespace railsim::tracks
