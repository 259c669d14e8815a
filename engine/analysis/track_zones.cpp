// Track sections and EN 14363 zones; see track_zones.hpp.
#include "engine/analysis/track_zones.hpp"

#include <algorithm>
#include <cmath>

#include "track/defects.hpp"

namespace railsim::engine {

const char* zone_name(TrackZone z) {
  switch (z) {
    case TrackZone::straight: return "straight";
    case TrackZone::large_radius_curve: return "large_radius_curve";
    case TrackZone::small_radius_curve: return "small_radius_curve";
    case TrackZone::very_small_radius_curve: return "very_small_radius_curve";
    case TrackZone::transition: return "transition";
  }
  return "unknown";
}

std::string test_zone_label(TrackZone z, double radius) {
  switch (z) {
    case TrackZone::straight: return "1";
    case TrackZone::large_radius_curve: return "2";
    case TrackZone::small_radius_curve: return radius >= 400.0 ? "3" : "4";
    case TrackZone::very_small_radius_curve: return "5";
    case TrackZone::transition: return "transition";
  }
  return "unknown";
}

TrackZone zone_of_radius(double radius, const ZoneLimits& lim) {
  if (!(radius < lim.straight_min_radius)) return TrackZone::straight;
  if (radius >= lim.large_min_radius) return TrackZone::large_radius_curve;
  if (radius >= lim.small_min_radius) return TrackZone::small_radius_curve;
  return TrackZone::very_small_radius_curve;
}

std::vector<TrackSection> track_sections(const track::Track& track, const ZoneLimits& lim) {
  const track::Alignment& a = track.alignment();
  std::vector<TrackSection> out;
  for (int i = 0; i < a.segment_count(); ++i) {
    const track::Segment& seg = a.segment(i);
    TrackSection s;
    s.kind = seg.kind();
    s.design_start = a.segment_start(i);
    s.design_end = a.segment_start(i + 1);
    const double k0 = std::fabs(seg.curvature_start()), k1 = std::fabs(seg.curvature_end());
    const double kmax = std::max(k0, k1);
    s.radius = kmax > 0.0 ? 1.0 / kmax : std::numeric_limits<double>::infinity();
    s.cant = std::max(std::fabs(seg.cant_start()), std::fabs(seg.cant_end()));
    const double ksigned = std::fabs(seg.curvature_end()) >= std::fabs(seg.curvature_start()) ? seg.curvature_end()
                                                                                              : seg.curvature_start();
    s.direction = ksigned > 0 ? "left" : (ksigned < 0 ? "right" : "");
    const bool varying = seg.curvature_start() != seg.curvature_end() || seg.cant_start() != seg.cant_end();
    if (s.kind == "clothoid" || varying)
      s.zone = TrackZone::transition;
    else
      s.zone = zone_of_radius(s.radius, lim);
    s.start = s.design_start;
    s.end = s.design_end;
    if (!out.empty() && out.back().zone == TrackZone::straight && s.zone == TrackZone::straight &&
        out.back().kind == s.kind && s.kind == "straight") {
      out.back().end = s.end;
      out.back().design_end = s.design_end;
      continue;
    }
    out.push_back(s);
  }
  if (out.empty()) return single_section();
  out.front().start = -std::numeric_limits<double>::infinity();
  out.back().end = std::numeric_limits<double>::infinity();
  return out;
}

std::vector<TrackSection> single_section(TrackZone zone, double radius) {
  TrackSection s;
  s.zone = zone;
  s.radius = radius;
  s.kind = zone == TrackZone::straight ? "straight" : "circular";
  return {s};
}

std::size_t section_at(const std::vector<TrackSection>& sections, double s) {
  // First section whose end is beyond s.
  const auto it = std::upper_bound(sections.begin(), sections.end(), s,
                                   [](double v, const TrackSection& sec) { return v < sec.end; });
  if (it == sections.end()) return sections.size() - 1;
  return static_cast<std::size_t>(it - sections.begin());
}

std::vector<DefectRange> track_defects(const track::Track& track) {
  std::vector<DefectRange> out;
  for (const auto& c : track.irregularities().components()) {
    if (dynamic_cast<const track::CosineDefect*>(c.get()) || dynamic_cast<const track::TwistDefect*>(c.get()))
      out.push_back({c->s_begin(), c->s_end(), c->describe()});
  }
  return out;
}

}  // namespace railsim::engine
