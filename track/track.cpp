// Track = alignment + irregularities; see track.hpp.
#include "track/track.hpp"

#include "track/cant.hpp"

namespace railsim::track {

Track::Track(std::string name, Alignment alignment, IrregularitySet irregularities, double gauge,
             bool gauge_given, std::vector<std::string> warnings)
    : name_(std::move(name)),
      alignment_(std::move(alignment)),
      irregularities_(std::move(irregularities)),
      gauge_(gauge),
      gauge_given_(gauge_given),
      warnings_(std::move(warnings)) {}

double Track::cant_deficiency(double s, double speed) const {
  const AlignmentState a = alignment_.at(s);
  return track::cant_deficiency(speed, a.curvature, a.cant, alignment_.rail_spacing());
}

}  // namespace railsim::track
