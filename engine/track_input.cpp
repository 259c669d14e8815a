// track::Track as an engine TrackReference; see track_input.hpp.
#include "engine/track_input.hpp"

namespace railsim::engine {

namespace {
// The alignment's part of a sample (curvature, cant angle, their rates along s,
// heading, ground position).
void copy_alignment(const track::AlignmentState& t, TrackSample& out) {
  out.curvature = t.curvature;
  out.curvature_rate = t.dcurvature;
  out.cant = t.cant_angle;
  out.cant_rate = t.dcant_angle;
  out.heading = t.heading;
  out.x = t.x;
  out.y = t.y;
}
}  // namespace

void TrackInput::sample(double s, TrackSample& out) const {
  const track::TrackState t = track_->at(s);
  copy_alignment(t, out);
  const auto& ir = t.irregularity;
  out.lat_left = ir.left_lateral();
  out.lat_right = ir.right_lateral();
  out.dlat_left = ir.left_lateral_slope();
  out.dlat_right = ir.right_lateral_slope();
  out.vert_left = ir.left_vertical();
  out.vert_right = ir.right_vertical();
  out.dvert_left = ir.left_vertical_slope();
  out.dvert_right = ir.right_vertical_slope();
}

void TrackInput::sample_alignment(double s, TrackSample& out) const {
  const track::AlignmentState t = track_->alignment_at(s);
  out = TrackSample{};
  copy_alignment(t, out);
}

std::string TrackInput::describe() const {
  std::string s = "track '" + track_->name() + "', " + std::to_string(track_->length()) + " m";
  for (const auto& c : track_->irregularities().components()) s += "; " + c->describe();
  return s;
}

}  // namespace railsim::engine
