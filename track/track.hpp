// Track: the object the multibody engine runs on. Alignment (design geometry:
// straight, clothoid, circular curve, cant) plus irregularities (defects,
// synthesised PSD samples, measured records), evaluated by distance s.
//
// Built once (track/track_file.hpp loads it from YAML), immutable afterwards:
// at() is const, thread-safe and does not allocate, so one Track can be shared
// by many simulations running in parallel (hold it in a shared_ptr<const Track>).
//
// Sign conventions (details in alignment.hpp and irregularity.hpp):
//   track frame: x along the track (direction of increasing s), y left, z up;
//   curvature > 0 turns left; cant E = z_right - z_left, cant angle phi =
//   asin(E/2b) > 0 raises the right rail (balances a left-hand curve); the
//   track-following frame is rolled by -phi about x.
//   Rail irregularities: y_left = y_a + g/2, y_right = y_a - g/2,
//   z_left = z_v - c/2, z_right = z_v + c/2 (y_a lateral alignment, z_v level,
//   c cross-level, g gauge deviation); slopes are d/ds.
//
// Typical use in the engine:
//   const track::TrackState t = track.at(s);
//   t.curvature, t.dcurvature, t.cant_angle, t.dcant_angle, t.heading, t.x, t.y;
//   t.irregularity.left_lateral(), t.irregularity.left_lateral_slope(), ...
#pragma once

#include <string>
#include <vector>

#include "track/alignment.hpp"
#include "track/irregularity.hpp"

namespace railsim::track {

// Everything known about the track at one distance.
struct TrackState : AlignmentState {
  IrregularityState irregularity;
};

class Track {
 public:
  // gauge_given: the track file states its gauge (else 1.435 m by default).
  // warnings: legal but doubtful input found when the track was read.
  Track(std::string name, Alignment alignment, IrregularitySet irregularities, double gauge = 1.435,
        bool gauge_given = false, std::vector<std::string> warnings = {});
  Track(Track&&) noexcept = default;
  Track& operator=(Track&&) noexcept = default;
  Track(const Track&) = delete;
  Track& operator=(const Track&) = delete;

  // Alignment and irregularities at s (any s: the alignment is extended with
  // the end curvature and cant beyond [0, length]; irregularities are zero
  // outside their ranges).
  TrackState at(double s) const {
    TrackState t;
    static_cast<AlignmentState&>(t) = alignment_.at(s);
    t.irregularity = irregularities_.at(s);
    return t;
  }
  AlignmentState alignment_at(double s) const { return alignment_.at(s); }
  IrregularityState irregularity_at(double s) const { return irregularities_.at(s); }

  // Cant deficiency [m] at s for a speed V [m/s] (physics-reference §10.1):
  // D = 2b V^2 |kappa| / g - E_outer, with E_outer the cant raising the outer
  // rail (negative E_outer: the inner rail is higher). D > 0: deficiency
  // (vehicle pushed outward), D < 0: cant excess. Design cant only.
  double cant_deficiency(double s, double speed) const;

  const std::string& name() const { return name_; }
  double length() const { return alignment_.length(); }
  double rail_spacing() const { return alignment_.rail_spacing(); }  // 2b [m]
  double gauge() const { return gauge_; }                            // nominal gauge [m]
  bool gauge_given() const { return gauge_given_; }                  // stated by the track file
  // Legal but doubtful input of the track file, "file:line: ...: ..." (e.g. a
  // measured record reaching beyond the track); the readers of a scenario
  // record them in its warnings.
  const std::vector<std::string>& warnings() const { return warnings_; }
  const Alignment& alignment() const { return alignment_; }
  const IrregularitySet& irregularities() const { return irregularities_; }

 private:
  std::string name_;
  Alignment alignment_;
  IrregularitySet irregularities_;
  double gauge_;
  bool gauge_given_ = false;
  std::vector<std::string> warnings_;
};

}  // namespace railsim::track
