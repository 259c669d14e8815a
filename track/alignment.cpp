// Horizontal alignment: chain of segments evaluated by distance; see alignment.hpp.
#include "track/alignment.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "config/yaml_input.hpp"
#include "core/errors.hpp"
#include "track/circular_curve.hpp"

namespace railsim::track {

namespace {

constexpr double kCurvatureJoinTol = 1e-9;  // [1/m]
constexpr double kCantJoinTol = 1e-6;       // [m]

std::string seg_name(int i, const Segment& s) {
  return "segments[" + std::to_string(i) + "] (" + s.kind() + ")";
}

// Pose after moving by a local offset (dx, dy) and turning by dpsi from `p`.
Pose advance(const Pose& p, const std::array<double, 2>& d, double dpsi) {
  const double c = std::cos(p.heading), s = std::sin(p.heading);
  return {p.x + c * d[0] - s * d[1], p.y + s * d[0] + c * d[1], p.heading + dpsi};
}

}  // namespace

Alignment::Alignment(std::vector<std::unique_ptr<Segment>> segments, double rail_spacing, Pose start)
    : segments_(std::move(segments)), rail_spacing_(rail_spacing) {
  using config::format_number;
  if (segments_.empty()) throw InputError("track alignment: no segments");
  if (!(rail_spacing_ > 0.0)) throw InputError("track alignment: rail_spacing must be positive");
  starts_.reserve(segments_.size() + 1);
  poses_.reserve(segments_.size() + 1);
  starts_.push_back(0.0);
  poses_.push_back(start);
  for (std::size_t k = 0; k < segments_.size(); ++k) {
    const int i = static_cast<int>(k);
    const Segment& seg = *segments_[k];
    if (!(seg.length() > 0.0) || !std::isfinite(seg.length()))
      throw InputError(seg_name(i, seg) + ": length must be a positive number (got " + format_number(seg.length()) +
                       ")");
    for (double u : {0.0, seg.length()}) {
      const double E = seg.cant(u).v;
      if (!(std::abs(E) < 0.5 * rail_spacing_))
        throw InputError(seg_name(i, seg) + ": cant " + format_number(E * 1e3) +
                         " mm is not below half the rail spacing (" + format_number(0.5e3 * rail_spacing_) + " mm)");
    }
    if (k > 0) {
      const Segment& prev = *segments_[k - 1];
      const double dk = seg.curvature_start() - prev.curvature_end();
      const double dE = seg.cant_start() - prev.cant_end();
      if (std::abs(dk) > kCurvatureJoinTol)
        throw InputError(seg_name(i, seg) + ": curvature jumps from " + format_number(prev.curvature_end()) + " to " +
                         format_number(seg.curvature_start()) + " 1/m at its start (s = " +
                         format_number(starts_.back()) + " m); join different curvatures with a clothoid");
      if (std::abs(dE) > kCantJoinTol)
        throw InputError(seg_name(i, seg) + ": cant jumps from " + format_number(prev.cant_end() * 1e3) + " to " +
                         format_number(seg.cant_start() * 1e3) + " mm at its start (s = " +
                         format_number(starts_.back()) + " m); ramp the cant in a clothoid");
    }
    poses_.push_back(advance(poses_.back(), seg.offset(seg.length()), seg.heading_change(seg.length())));
    starts_.push_back(starts_.back() + seg.length());
  }
  length_ = starts_.back();
}

void Alignment::fill_cant(AlignmentState& st, const Derivs& E) const {
  st.cant = E.v;
  st.dcant = E.d1;
  const double q = rail_spacing_ * rail_spacing_ - E.v * E.v;  // (2b)^2 - E^2 > 0 (checked)
  const double r = std::sqrt(q);
  st.cant_angle = std::asin(E.v / rail_spacing_);
  st.dcant_angle = E.d1 / r;
  st.d2cant_angle = E.d2 / r + E.v * E.d1 * E.d1 / (q * r);
}

AlignmentState Alignment::at(double s) const {
  AlignmentState st;
  st.s = s;
  const int n = segment_count();
  if (s < 0.0 || s > length_) {
    // Continue with the end curvature and cant (a circular arc).
    const bool before = s < 0.0;
    const Segment& seg = before ? *segments_.front() : *segments_.back();
    const double u = before ? s : s - length_;
    const double kappa = before ? seg.curvature_start() : seg.curvature_end();
    const double E = before ? seg.cant_start() : seg.cant_end();
    const Pose p = advance(before ? poses_.front() : poses_.back(), arc_offset(kappa, u), kappa * u);
    st.x = p.x;
    st.y = p.y;
    st.heading = p.heading;
    st.curvature = kappa;
    fill_cant(st, Derivs{E, 0.0, 0.0});
    st.segment = before ? -1 : n;
    return st;
  }
  auto it = std::upper_bound(starts_.begin(), starts_.end(), s);
  int i = static_cast<int>(it - starts_.begin()) - 1;
  i = std::clamp(i, 0, n - 1);
  const Segment& seg = *segments_[static_cast<std::size_t>(i)];
  const double u = s - starts_[static_cast<std::size_t>(i)];
  const Pose p = advance(poses_[static_cast<std::size_t>(i)], seg.offset(u), seg.heading_change(u));
  st.x = p.x;
  st.y = p.y;
  st.heading = p.heading;
  const Derivs k = seg.curvature(u);
  st.curvature = k.v;
  st.dcurvature = k.d1;
  st.d2curvature = k.d2;
  fill_cant(st, seg.cant(u));
  st.segment = i;
  return st;
}

}  // namespace railsim::track
