// One EN 14363 assessment quantity of one item (a wheel, a wheelset, a bogie,
// a car-body point), evaluated per track section (track_zones.hpp) from its
// processed signal (filtered, and windowed where the standard says so), with
// its limit, margin and pass/fail, where and when.
//
// Statistics per section (EN 14363 / UIC 518 statistical evaluation of the
// processed signal, gensys.se course page [V], physics-reference §9.3):
//   two_sided   value = max(|F1|, |F2|), F1 = 0.15 %, F2 = 99.85 % percentile
//               ((Y/Q)_2m, (Sum Y)_2m, car-body accelerations);
//   upper       value = F2 (Q_max; wheel unloading from (Q0 - Q)/Q0);
//   median      value = |F0|, F0 = 50 % (quasi-static values in curves);
//   maximum     value = max |x| (sliding rms of the instability criteria);
//   rms         value = rms of the section's samples (ride rms values).
// Percentiles: linear interpolation between order statistics (results::
// percentiles, Hyndman & Fan type 7). A section whose samples are all outside
// the run, or that the quantity does not use (quasi-static values: circular
// curves only), is skipped. A sample belongs to the section holding its
// distance. The quantity passes when every evaluated section passes (value <=
// limit); margin = limit - value, utilisation = value / limit. Without a
// limit (reported only) limit, margin and utilisation are NaN and pass is true.
// Also kept: the peak |x| of the processed signal in each section with its
// distance and time (where and when), and the whole processed signal for charts.
#pragma once

#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "engine/analysis/track_zones.hpp"

namespace railsim::engine {

enum class Statistic { two_sided, upper, median, maximum, rms };
std::string statistic_description(Statistic s, double p_low, double p_high, double p_qst);

inline constexpr double kNoLimit = std::numeric_limits<double>::quiet_NaN();

struct SectionValue {
  std::size_t section = 0;  // index into the sections
  TrackZone zone = TrackZone::straight;
  double radius = std::numeric_limits<double>::infinity();
  std::size_t samples = 0;
  double p_low = kNoLimit, p_high = kNoLimit, p_mid = kNoLimit;  // F1, F2, F0 where used
  double value = 0.0;       // assessed value (statistic above)
  double limit = kNoLimit;
  bool pass = true;
  double peak = 0.0;        // max |x| in the section
  double peak_distance = 0.0, peak_time = 0.0;
};

struct Quantity {
  std::string name;        // key: "yq_2m", "q_max", ...
  std::string symbol;      // EN 14363 notation: "(Y/Q)_2m", "Q_max", ...
  std::string item;        // "ws1 left wheel", "ws1", "bogie1@ws1", ...
  std::string kind;        // "wheel", "wheelset", "bogie frame", "car body"
  std::string unit;        // "-", "N", "m/s^2"
  Statistic statistic = Statistic::two_sided;
  std::vector<std::string> processing;  // every step, in order
  std::string limit_source;             // where the limit comes from ("" = reported only)
  std::vector<SectionValue> sections;   // evaluated sections only
  // The deciding section (the one with the largest utilisation, or value without a limit).
  bool evaluated = false;  // at least one section
  double value = 0.0, limit = kNoLimit, margin = kNoLimit, utilisation = kNoLimit;
  double at_distance = 0.0, at_time = 0.0;  // peak of the deciding section
  std::size_t section = 0;
  TrackZone zone = TrackZone::straight;
  bool pass = true;
  // Processed signal (for charts, when QuantitySpec::keep_series; not written to summary.json).
  std::vector<double> x, t, y;
};

struct QuantitySpec {
  std::string name, symbol, item, kind, unit;
  Statistic statistic = Statistic::two_sided;
  std::vector<std::string> processing;
  std::string limit_source;
  double p_low = 0.15, p_high = 99.85, p_mid = 50.0;  // [%]
  // Limit of a section (NaN: none). Empty: no limit.
  std::function<double(const TrackSection&)> limit;
  // Whether a section is evaluated (empty: all).
  std::function<bool(const TrackSection&)> use_section;
  bool keep_series = false;  // keep the processed signal in Quantity::x, t, y
};

// Evaluate the processed signal y at distances x (strictly increasing for
// windowed series; non-decreasing otherwise) and times t over the sections.
// Throws std::invalid_argument on length mismatch.
Quantity assess(const QuantitySpec& spec, const std::vector<double>& x, const std::vector<double>& t,
                const std::vector<double>& y, const std::vector<TrackSection>& sections);

// Time at distance s of a non-decreasing distance series (linear interpolation, clamped).
double time_at_distance(const std::vector<double>& dist, const std::vector<double>& time, double s);

}  // namespace railsim::engine
