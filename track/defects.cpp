// Cosine bump and twist defects; see defects.hpp.
#include "track/defects.hpp"

#include <cmath>
#include <cstdio>
#include <string>

namespace railsim::track {

namespace {
constexpr double kPi = 3.14159265358979323846;

std::string fmt(const char* f, double a, double b = 0, double c = 0, double d = 0) {
  char buf[160];
  std::snprintf(buf, sizeof buf, f, a, b, c, d);
  return buf;
}

// The defect must lie on the track.
void check_on_track(const config::InputNode& node, double begin, double end, double length) {
  if (begin < 0.0 || end > length + 1e-9)
    node.fail("the defect spans s = " + config::format_number(begin) + " .. " + config::format_number(end) +
              " m, outside the track (0 .. " + config::format_number(length) + " m)");
}
}  // namespace

// ---------------------------------------------------------------- cosine ----
CosineDefect::CosineDefect(Channel channel, double start, double wavelength, double amplitude, int periods)
    : channel_(channel), start_(start), wavelength_(wavelength), amplitude_(amplitude), periods_(periods) {}

void CosineDefect::add_to(double s, IrregularityState& out) const {
  const double u = s - start_;
  if (u < 0.0 || u > periods_ * wavelength_) return;
  const double w = 2.0 * kPi / wavelength_;
  out.add(channel_, 0.5 * amplitude_ * (1.0 - std::cos(w * u)), 0.5 * amplitude_ * w * std::sin(w * u));
}

std::string CosineDefect::describe() const {
  return std::string("defect ") + channel_name(channel_) +
         fmt(" %.4g mm, wavelength %.4g m x %.0f at s = %.6g m", amplitude_ * 1e3, wavelength_, periods_, start_);
}

std::unique_ptr<IrregularityComponent> parse_cosine_defect(const config::InputNode& node,
                                                           const IrregularityContext& context) {
  node.allow_only({"type", "channel", "start", "wavelength", "amplitude_mm", "periods"});
  const config::InputNode ch = node.at("channel");
  const auto channel = channel_from_name(ch.as_string());
  if (!channel) ch.fail("unknown channel '" + ch.as_string() + "' (allowed: lateral, vertical, cross_level, gauge)");
  const double start = node.non_negative("start");
  const double wavelength = node.in_range("wavelength", 0.1, 1000.0);
  const double amplitude = node.in_range("amplitude_mm", -200.0, 200.0) * 1e-3;
  long periods = 1;
  if (auto p = node.find("periods")) {
    periods = p->as_integer();
    if (periods < 1 || periods > 1000) p->fail("expected an integer in [1, 1000] (got " + p->text() + ")");
  }
  check_on_track(node, start, start + static_cast<double>(periods) * wavelength, context.track_length);
  return std::make_unique<CosineDefect>(*channel, start, wavelength, amplitude, static_cast<int>(periods));
}

// ----------------------------------------------------------------- twist ----
TwistDefect::TwistDefect(double start, double base_length, double amplitude, double hold, TwistRail rail,
                         TwistRamp ramp)
    : start_(start), base_(base_length), amplitude_(amplitude), hold_(hold), rail_(rail), ramp_(ramp) {}

void TwistDefect::add_to(double s, IrregularityState& out) const {
  const double u = s - start_;
  if (u < 0.0 || u > 2.0 * base_ + hold_) return;
  // Ramp fraction t in [0, 1] and dt/du.
  double t = 1.0, dt = 0.0;
  if (u < base_) {
    t = u / base_;
    dt = 1.0 / base_;
  } else if (u > base_ + hold_) {
    t = 1.0 - (u - base_ - hold_) / base_;
    dt = -1.0 / base_;
  }
  double r = t, dr = dt;
  if (ramp_ == TwistRamp::cosine) {
    r = 0.5 * (1.0 - std::cos(kPi * t));
    dr = 0.5 * kPi * std::sin(kPi * t) * dt;
  }
  const double c = amplitude_ * r, dc = amplitude_ * dr;
  out.add(Channel::cross_level, c, dc);
  // z_right = z_v + c/2, z_left = z_v - c/2: moving one rail only shifts the level by +-c/2.
  if (rail_ == TwistRail::right) out.add(Channel::vertical, 0.5 * c, 0.5 * dc);
  if (rail_ == TwistRail::left) out.add(Channel::vertical, -0.5 * c, -0.5 * dc);
}

std::string TwistDefect::describe() const {
  const char* rail = rail_ == TwistRail::both ? "both rails" : rail_ == TwistRail::left ? "left rail" : "right rail";
  return fmt("twist %.4g mm over %.4g m (%.3g mm/m), hold %.4g m", amplitude_ * 1e3, base_, twist() * 1e3, hold_) +
         ", " + rail + fmt(" at s = %.6g m", start_);
}

std::unique_ptr<IrregularityComponent> parse_twist_defect(const config::InputNode& node,
                                                          const IrregularityContext& context) {
  node.allow_only({"type", "start", "base_length", "amplitude_mm", "hold", "rail", "ramp"});
  const double start = node.non_negative("start");
  const double base = node.in_range("base_length", 0.5, 100.0);
  const double amplitude = node.in_range("amplitude_mm", -100.0, 100.0) * 1e-3;
  const double hold = node.has("hold") ? node.at("hold").as_non_negative() : 0.0;
  TwistRail rail = TwistRail::both;
  if (auto r = node.find("rail")) {
    const std::string v = r->as_string();
    if (v == "both") rail = TwistRail::both;
    else if (v == "left") rail = TwistRail::left;
    else if (v == "right") rail = TwistRail::right;
    else r->fail("expected one of: both, left, right (got '" + v + "')");
  }
  TwistRamp ramp = TwistRamp::linear;
  if (auto r = node.find("ramp")) {
    const std::string v = r->as_string();
    if (v == "linear") ramp = TwistRamp::linear;
    else if (v == "cosine") ramp = TwistRamp::cosine;
    else r->fail("expected one of: linear, cosine (got '" + v + "')");
  }
  check_on_track(node, start, start + 2.0 * base + hold, context.track_length);
  return std::make_unique<TwistDefect>(start, base, amplitude, hold, rail, ramp);
}

}  // namespace railsim::track
