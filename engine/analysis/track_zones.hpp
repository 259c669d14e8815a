// Track sections and zones of a run, from the track's alignment: every
// alignment segment (track/segment.hpp) is a section; consecutive straight
// segments are merged. Each section gets the zone of EN 14363 it belongs to:
//   straight              straight segments, and circular curves with
//                         R >= straight_min_radius (test zone 1, "straight
//                         track and very large radius curves"; the 5000 m
//                         default is our reading [U], set it if you know better)
//   large_radius_curve    circular, R >= large_min_radius (600 m; test zone 2)
//   small_radius_curve    circular, small_min_radius <= R < large_min_radius
//                         (250..600 m; test zones 3 (400..600 m) and 4 (250..400 m))
//   very_small_radius_curve  circular, R < 250 m (test zone 5, outside the
//                         acceptance tests; CEN/TS 17843:2022 scope, public summary)
//   transition            clothoids (varying curvature or cant)
// Sources: EN 14363:2016 test zones as recalled in physics-reference §9.3 [K]
// (zones 2-4 radius bands; the 250 m boundary is also the (Y/Q) limit change,
// 0.8 for R >= 250 m and 1.2 below), CEN/TS 17843:2022 summary for zone 5 [V].
// Sections are open at both ends of the run: the first starts at -inf and the
// last ends at +inf, as the alignment continues with its end curvature.
// Also the isolated defects of the track (cosine and twist defects) as
// distance ranges, for charts. Units: m, 1/m.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "track/track.hpp"

namespace railsim::engine {

enum class TrackZone { straight, large_radius_curve, small_radius_curve, very_small_radius_curve, transition };
inline constexpr int kZoneCount = 5;

// "straight", "large_radius_curve", ...
const char* zone_name(TrackZone z);
// EN 14363 test zone: "1", "2", "3", "4", "5" or "transition".
std::string test_zone_label(TrackZone z, double radius);

struct ZoneLimits {
  double straight_min_radius = 5000.0;  // [m] [U]
  double large_min_radius = 600.0;      // [m] [K]
  double small_min_radius = 250.0;      // [m] [K]
};

struct TrackSection {
  TrackZone zone = TrackZone::straight;
  double start = -std::numeric_limits<double>::infinity();  // [m]
  double end = std::numeric_limits<double>::infinity();     // [m]
  double design_start = 0.0, design_end = 0.0;  // the segment's own (finite) range [m]
  double radius = std::numeric_limits<double>::infinity();  // smallest radius in the section [m]
  double cant = 0.0;                 // largest |cant| in the section [m]
  std::string kind;                  // "straight", "circular", "clothoid"
  std::string direction;             // "left", "right" or "" (straight)
};

struct DefectRange {
  double start = 0.0, end = 0.0;  // [m]
  std::string description;
};

// Zone of a circular curve of radius R (R = inf: straight).
TrackZone zone_of_radius(double radius, const ZoneLimits& limits = {});

// Sections of the track's alignment (at least one).
std::vector<TrackSection> track_sections(const track::Track& track, const ZoneLimits& limits = {});

// One straight section covering everything (tracks without alignment data).
std::vector<TrackSection> single_section(TrackZone zone = TrackZone::straight,
                                         double radius = std::numeric_limits<double>::infinity());

// Index of the section holding distance s (sections sorted, contiguous).
std::size_t section_at(const std::vector<TrackSection>& sections, double s);

// Isolated defects (track::CosineDefect, track::TwistDefect) of the track.
std::vector<DefectRange> track_defects(const track::Track& track);

}  // namespace railsim::engine
