// Track sections and EN 14363 zones from the alignment (engine/analysis/
// track_zones.hpp), for the shipped curve tracks and inline ones.
#include <catch2/catch.hpp>

#include <cmath>

#include "config/yaml_input.hpp"
#include "engine/analysis/track_zones.hpp"
#include "test_support.hpp"
#include "track/track_file.hpp"

using namespace railsim;
using namespace railsim::engine;

namespace {
track::Track inline_track(const std::string& yaml) {
  return track::load_track(config::InputNode::load_string(yaml, "inline.yaml"), ".", "inline");
}
}  // namespace

TEST_CASE("zones of the R 300 m curve: straight, transition, small radius (zone 4), transition, straight",
          "[safety][zones]") {
  const track::Track t = track::load_track(test::source_path("tracks/curve_R300.yaml"));
  const auto s = track_sections(t);
  REQUIRE(s.size() == 5);
  const TrackZone expected[5] = {TrackZone::straight, TrackZone::transition, TrackZone::small_radius_curve,
                                 TrackZone::transition, TrackZone::straight};
  const double starts[5] = {0, 50, 130, 530, 610}, ends[5] = {50, 130, 530, 610, 710};
  for (int i = 0; i < 5; ++i) {
    INFO("section " << i);
    CHECK(s[i].zone == expected[i]);
    CHECK(s[i].design_start == Approx(starts[i]));
    CHECK(s[i].design_end == Approx(ends[i]));
  }
  CHECK(std::isinf(s[0].start));  // open at both ends of the run
  CHECK(std::isinf(s[4].end));
  CHECK(s[2].radius == Approx(300.0));
  CHECK(s[1].radius == Approx(300.0));  // a transition carries its smallest radius
  CHECK(s[2].direction == "right");
  CHECK(s[2].cant == Approx(0.150));
  CHECK(test_zone_label(s[2].zone, s[2].radius) == "4");
  CHECK(std::string(zone_name(s[1].zone)) == "transition");
  // section_at: every distance, including before the start and past the end.
  CHECK(section_at(s, -100.0) == 0);
  CHECK(section_at(s, 49.99) == 0);
  CHECK(section_at(s, 50.0) == 1);
  CHECK(section_at(s, 300.0) == 2);
  CHECK(section_at(s, 609.9) == 3);
  CHECK(section_at(s, 5000.0) == 4);
}

TEST_CASE("zone boundaries by radius: 5000 / 600 / 250 m", "[safety][zones]") {
  CHECK(zone_of_radius(INFINITY) == TrackZone::straight);
  CHECK(zone_of_radius(5000.0) == TrackZone::straight);
  CHECK(zone_of_radius(4999.0) == TrackZone::large_radius_curve);
  CHECK(zone_of_radius(600.0) == TrackZone::large_radius_curve);
  CHECK(zone_of_radius(599.0) == TrackZone::small_radius_curve);
  CHECK(zone_of_radius(250.0) == TrackZone::small_radius_curve);
  CHECK(zone_of_radius(249.0) == TrackZone::very_small_radius_curve);
  ZoneLimits wider;
  wider.straight_min_radius = 10000.0;
  CHECK(zone_of_radius(8000.0, wider) == TrackZone::large_radius_curve);
  CHECK(test_zone_label(TrackZone::small_radius_curve, 450.0) == "3");
  CHECK(test_zone_label(TrackZone::very_small_radius_curve, 200.0) == "5");
  const track::Track t1000 = track::load_track(test::source_path("tracks/curve_R1000.yaml"));
  CHECK(track_sections(t1000)[2].zone == TrackZone::large_radius_curve);
  const track::Track tw = track::load_track(test::source_path("tracks/curve_twist.yaml"));
  CHECK(track_sections(tw)[2].zone == TrackZone::small_radius_curve);  // R = 250 m: still >= 250
}

TEST_CASE("consecutive straights merge, very small radius and defects are found", "[safety][zones]") {
  const track::Track t = inline_track(
      "name: t\nrail_spacing: 1.5\nsegments:\n"
      "  - {type: straight, length: 100}\n  - {type: straight, length: 50}\n"
      "  - {type: clothoid, length: 40}\n  - {type: circular, length: 100, radius: 200, direction: left}\n"
      "  - {type: clothoid, length: 40}\n  - {type: straight, length: 30}\n"
      "irregularities:\n  - {type: defect, channel: lateral, start: 120, wavelength: 10, amplitude_mm: 5}\n");
  const auto s = track_sections(t);
  REQUIRE(s.size() == 5);
  CHECK(s[0].zone == TrackZone::straight);
  CHECK(s[0].design_end == Approx(150.0));
  CHECK(s[2].zone == TrackZone::very_small_radius_curve);
  CHECK(s[2].direction == "left");
  const auto d = track_defects(t);
  REQUIRE(d.size() == 1);
  CHECK(d[0].start == Approx(120.0));
  CHECK(d[0].end == Approx(130.0));
  // The ERRI track's random irregularities are not "defects".
  CHECK(track_defects(track::load_track(test::source_path("tracks/straight_erri_low.yaml"))).empty());
  CHECK(single_section().size() == 1);
}
