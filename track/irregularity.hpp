// Track irregularities: the four measured channels, their values and
// s-derivatives at one distance, and the interface of an irregularity
// component (a defect, a synthesised PSD sample, a measured record).
//
// Channels (all in metres, deviations from the design alignment):
//   lateral     y_a : alignment of the track centre line, + to the left
//   vertical    z_v : level of the track centre line, + up
//   cross_level c   : z_right - z_left, the irregular part of the cant (same
//                     sign convention as the design cant, see alignment.hpp)
//   gauge       g   : gauge deviation, + wider
// Rails (fixed once here, physics-reference §10.4 with the signs chosen so that
// cross-level adds to cant and positive gauge widens the track):
//   y_left  = y_a + g/2      y_right  = y_a - g/2
//   z_left  = z_v - c/2      z_right  = z_v + c/2
// The total irregularity is the sum of all components (superposition).
// Slopes are d/ds (dimensionless); at speed V the rail velocity excitation of
// a wheel is V * slope.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace railsim::track {

enum class Channel : int { lateral = 0, vertical = 1, cross_level = 2, gauge = 3 };
inline constexpr int kChannelCount = 4;
inline constexpr std::array<Channel, kChannelCount> kAllChannels = {Channel::lateral, Channel::vertical,
                                                                   Channel::cross_level, Channel::gauge};

// "lateral", "vertical", "cross_level", "gauge".
const char* channel_name(Channel c);
// Inverse of channel_name; std::nullopt for an unknown name.
std::optional<Channel> channel_from_name(std::string_view name);
inline int index(Channel c) { return static_cast<int>(c); }

// Irregularity at one distance: value [m] and slope d/ds [-] per channel.
struct IrregularityState {
  std::array<double, kChannelCount> value{};
  std::array<double, kChannelCount> slope{};

  double operator[](Channel c) const { return value[index(c)]; }
  double slope_of(Channel c) const { return slope[index(c)]; }
  void add(Channel c, double v, double dv) {
    value[index(c)] += v;
    slope[index(c)] += dv;
  }

  // Rail positions (see the convention at the top of this file).
  double left_lateral() const { return value[0] + 0.5 * value[3]; }
  double right_lateral() const { return value[0] - 0.5 * value[3]; }
  double left_vertical() const { return value[1] - 0.5 * value[2]; }
  double right_vertical() const { return value[1] + 0.5 * value[2]; }
  double left_lateral_slope() const { return slope[0] + 0.5 * slope[3]; }
  double right_lateral_slope() const { return slope[0] - 0.5 * slope[3]; }
  double left_vertical_slope() const { return slope[1] - 0.5 * slope[2]; }
  double right_vertical_slope() const { return slope[1] + 0.5 * slope[2]; }
};

// One irregularity component. Built once (all tables precomputed), immutable;
// add_to() is const, thread-safe and does not allocate. Outside its range
// [s_begin, s_end] a component contributes zero.
class IrregularityComponent {
 public:
  virtual ~IrregularityComponent() = default;
  // Add this component's value and slope at distance s to `out`.
  virtual void add_to(double s, IrregularityState& out) const = 0;
  virtual double s_begin() const = 0;
  virtual double s_end() const = 0;
  // One line for logs: "defect lateral 10 mm, 20 m at s = 80 m".
  virtual std::string describe() const = 0;
  // The files this component was read from (none for a synthesised one):
  // inputs that a result file must not overwrite.
  virtual std::vector<std::string> input_files() const { return {}; }
};

// The sum of components: what Track evaluates.
class IrregularitySet {
 public:
  IrregularitySet() = default;
  void add(std::unique_ptr<IrregularityComponent> c) { components_.push_back(std::move(c)); }
  IrregularityState at(double s) const {
    IrregularityState out;
    for (const auto& c : components_)
      if (s >= c->s_begin() && s <= c->s_end()) c->add_to(s, out);
    return out;
  }
  const std::vector<std::unique_ptr<IrregularityComponent>>& components() const { return components_; }
  bool empty() const { return components_.empty(); }

 private:
  std::vector<std::unique_ptr<IrregularityComponent>> components_;
};

}  // namespace railsim::track
