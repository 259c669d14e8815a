// Deterministic single defects.
//
// CosineDefect: n full cosine waves of wavelength lambda and peak amplitude A
// in one channel, starting at s0 (u = s - s0 in [0, n lambda]):
//   r(u) = A/2 (1 - cos(2 pi u / lambda)),   r'(u) = A pi / lambda sin(2 pi u / lambda)
// value and slope are continuous at both ends (zero there). With n = 1 this is
// the classic isolated "cosine bump" used as the excitation in critical-speed
// studies (e.g. a 10 mm lateral alignment defect).
//
// TwistDefect: the cross-level c = z_right - z_left changes by h over the base
// length l_b (twist h / l_b, e.g. mm/m, the quantity limited by EN 13848-5 and
// used in EN 14363 twist tests), holds for `hold` metres, and returns over l_b:
//   c(u) = h r(u / l_b) rising, h on the hold, h r(1 - (u - l_b - hold)/l_b) falling,
// with r(t) = t (linear ramp, default) or (1 - cos pi t)/2 (cosine ramp).
// `rail` says which rail moves: both (each by c/2, level unchanged), right
// (z_right = c, level z_v = c/2) or left (z_left = -c, level z_v = -c/2).
// Units: m inside; YAML gives amplitudes in mm.
#pragma once

#include <memory>

#include "config/yaml_input.hpp"
#include "track/irregularity.hpp"
#include "track/irregularity_registry.hpp"

namespace railsim::track {

class CosineDefect final : public IrregularityComponent {
 public:
  CosineDefect(Channel channel, double start, double wavelength, double amplitude, int periods = 1);
  void add_to(double s, IrregularityState& out) const override;
  double s_begin() const override { return start_; }
  double s_end() const override { return start_ + periods_ * wavelength_; }
  std::string describe() const override;

 private:
  Channel channel_;
  double start_, wavelength_, amplitude_;
  int periods_;
};

enum class TwistRail { both, left, right };
enum class TwistRamp { linear, cosine };

class TwistDefect final : public IrregularityComponent {
 public:
  TwistDefect(double start, double base_length, double amplitude, double hold = 0.0,
              TwistRail rail = TwistRail::both, TwistRamp ramp = TwistRamp::linear);
  void add_to(double s, IrregularityState& out) const override;
  double s_begin() const override { return start_; }
  double s_end() const override { return start_ + 2.0 * base_ + hold_; }
  std::string describe() const override;
  // Mean twist over the base length, h / l_b [m/m].
  double twist() const { return amplitude_ / base_; }

 private:
  double start_, base_, amplitude_, hold_;
  TwistRail rail_;
  TwistRamp ramp_;
};

// Registry parsers ("defect", "twist").
std::unique_ptr<IrregularityComponent> parse_cosine_defect(const config::InputNode& node,
                                                           const IrregularityContext& context);
std::unique_ptr<IrregularityComponent> parse_twist_defect(const config::InputNode& node,
                                                          const IrregularityContext& context);

}  // namespace railsim::track
