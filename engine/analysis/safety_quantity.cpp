// One EN 14363 assessment quantity per track section; see safety_quantity.hpp.
#include "engine/analysis/safety_quantity.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "results/sliding_window.hpp"

namespace railsim::engine {

std::string statistic_description(Statistic s, double p_low, double p_high, double p_qst) {
  char buf[160] = "";
  switch (s) {
    case Statistic::two_sided:
      std::snprintf(buf, sizeof buf, "max(|F1|, |F2|) per track section, F1 = %.4g %%, F2 = %.4g %% percentile", p_low,
                    p_high);
      break;
    case Statistic::upper:
      std::snprintf(buf, sizeof buf, "F2 = %.4g %% percentile per track section", p_high);
      break;
    case Statistic::median:
      std::snprintf(buf, sizeof buf, "|F0|, F0 = %.4g %% percentile per circular-curve section", p_qst);
      break;
    case Statistic::maximum: std::snprintf(buf, sizeof buf, "maximum per track section"); break;
    case Statistic::rms: std::snprintf(buf, sizeof buf, "rms over each track section"); break;
  }
  return buf;
}

double time_at_distance(const std::vector<double>& dist, const std::vector<double>& time, double s) {
  if (dist.empty()) return 0.0;
  const auto it = std::lower_bound(dist.begin(), dist.end(), s);
  if (it == dist.begin()) return time.front();
  if (it == dist.end()) return time.back();
  const std::size_t j = static_cast<std::size_t>(it - dist.begin());
  const double span = dist[j] - dist[j - 1];
  const double u = span > 0.0 ? (s - dist[j - 1]) / span : 0.0;
  return time[j - 1] + u * (time[j] - time[j - 1]);
}

Quantity assess(const QuantitySpec& spec, const std::vector<double>& x, const std::vector<double>& t,
                const std::vector<double>& y, const std::vector<TrackSection>& sections) {
  if (x.size() != y.size() || t.size() != y.size())
    throw std::invalid_argument("assess " + spec.name + ": distance, time and value differ in length");
  if (sections.empty()) throw std::invalid_argument("assess " + spec.name + ": no track sections");
  Quantity q;
  q.name = spec.name;
  q.symbol = spec.symbol;
  q.item = spec.item;
  q.kind = spec.kind;
  q.unit = spec.unit;
  q.statistic = spec.statistic;
  q.processing = spec.processing;
  q.processing.push_back(statistic_description(spec.statistic, spec.p_low, spec.p_high, spec.p_mid));
  q.limit_source = spec.limit_source;
  const std::size_t n = y.size();
  std::size_t i = 0;
  std::vector<double> vals;
  double best = -std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < sections.size() && i < n; ++k) {
    const TrackSection& sec = sections[k];
    while (i < n && x[i] < sec.start) ++i;
    const std::size_t i0 = i;
    while (i < n && x[i] < sec.end) ++i;
    if (i == i0) continue;
    if (spec.use_section && !spec.use_section(sec)) continue;
    SectionValue v;
    v.section = k;
    v.zone = sec.zone;
    v.radius = sec.radius;
    v.samples = i - i0;
    vals.assign(y.begin() + static_cast<std::ptrdiff_t>(i0), y.begin() + static_cast<std::ptrdiff_t>(i));
    std::size_t peak = i0;
    for (std::size_t j = i0; j < i; ++j)
      if (std::fabs(y[j]) > std::fabs(y[peak])) peak = j;
    v.peak = std::fabs(y[peak]);
    v.peak_distance = x[peak];
    v.peak_time = t[peak];
    switch (spec.statistic) {
      case Statistic::two_sided: {
        const auto p = results::percentiles(vals, {spec.p_low, spec.p_high});
        v.p_low = p[0], v.p_high = p[1];
        v.value = std::max(std::fabs(p[0]), std::fabs(p[1]));
        break;
      }
      case Statistic::upper:
        v.p_high = results::percentiles(vals, {spec.p_high})[0];
        v.value = v.p_high;
        break;
      case Statistic::median:
        v.p_mid = results::percentiles(vals, {spec.p_mid})[0];
        v.value = std::fabs(v.p_mid);
        break;
      case Statistic::maximum: v.value = v.peak; break;
      case Statistic::rms: {
        double s2 = 0.0;
        for (double a : vals) s2 += a * a;
        v.value = std::sqrt(s2 / static_cast<double>(vals.size()));
        break;
      }
    }
    v.limit = spec.limit ? spec.limit(sec) : kNoLimit;
    v.pass = std::isnan(v.limit) || v.value <= v.limit;
    q.pass = q.pass && v.pass;
    const double score = std::isnan(v.limit) ? v.value : v.value / v.limit;
    if (score > best) {
      best = score;
      q.evaluated = true;
      q.value = v.value;
      q.limit = v.limit;
      q.margin = v.limit - v.value;
      q.utilisation = v.value / v.limit;
      q.at_distance = v.peak_distance;
      q.at_time = v.peak_time;
      q.section = k;
      q.zone = sec.zone;
    }
    q.sections.push_back(v);
  }
  if (spec.keep_series) q.x = x, q.t = t, q.y = y;
  return q;
}

}  // namespace railsim::engine
