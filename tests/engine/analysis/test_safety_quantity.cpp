// One assessment quantity per track section (engine/analysis/safety_quantity.hpp):
// percentiles, medians, maxima and rms of hand-made series with hand-computed
// values, per-section limits, the deciding section, where and when.
#include <catch2/catch.hpp>

#include <cmath>

#include "engine/analysis/safety_quantity.hpp"

using namespace railsim::engine;

namespace {
// Straight up to 10 m, then a circular curve of R 300 m.
std::vector<TrackSection> two_sections() {
  std::vector<TrackSection> s(2);
  s[0].zone = TrackZone::straight;
  s[0].end = 10.0;
  s[1].zone = TrackZone::small_radius_curve;
  s[1].start = 10.0;
  s[1].radius = 300.0;
  return s;
}
// x = 0, 0.5, ..., 19.5 m; t = x / 10; y = i on the straight (i = 0..19), -2 i in the curve.
struct Series {
  std::vector<double> x, t, y;
};
Series series() {
  Series s;
  for (int k = 0; k < 40; ++k) {
    s.x.push_back(0.5 * k);
    s.t.push_back(0.05 * k);
    s.y.push_back(k < 20 ? double(k) : -2.0 * (k - 20));
  }
  return s;
}
QuantitySpec spec(Statistic st) {
  QuantitySpec q;
  q.name = "test";
  q.symbol = "T";
  q.item = "item";
  q.statistic = st;
  q.processing = {"none"};
  return q;
}
}  // namespace

TEST_CASE("two-sided percentiles per section, section limits, the deciding section", "[safety][quantity]") {
  auto q = spec(Statistic::two_sided);
  q.limit = [](const TrackSection& sec) { return sec.zone == TrackZone::straight ? 20.0 : 30.0; };
  q.limit_source = "hand-made";
  const Series s = series();
  const Quantity r = assess(q, s.x, s.t, s.y, two_sections());
  REQUIRE(r.sections.size() == 2);
  // 20 values 0..19: F1 at position 19 x 0.0015 = 0.0285, F2 at 19 x 0.9985 = 18.9715.
  CHECK(r.sections[0].samples == 20);
  CHECK(r.sections[0].p_low == Approx(0.0285));
  CHECK(r.sections[0].p_high == Approx(18.9715));
  CHECK(r.sections[0].value == Approx(18.9715));
  CHECK(r.sections[0].pass);
  // Curve: -2 i: F1 = -37.943, F2 = -0.057, value 37.943 > 30: fails.
  CHECK(r.sections[1].p_low == Approx(-37.943));
  CHECK(r.sections[1].p_high == Approx(-0.057));
  CHECK(r.sections[1].value == Approx(37.943));
  CHECK_FALSE(r.sections[1].pass);
  CHECK(r.sections[1].peak == Approx(38.0));
  CHECK(r.sections[1].peak_distance == Approx(19.5));
  CHECK(r.sections[1].peak_time == Approx(1.95));
  // Deciding: the curve (utilisation 37.943 / 30), where and when of its peak.
  CHECK_FALSE(r.pass);
  CHECK(r.evaluated);
  CHECK(r.section == 1);
  CHECK(r.zone == TrackZone::small_radius_curve);
  CHECK(r.value == Approx(37.943));
  CHECK(r.limit == 30.0);
  CHECK(r.margin == Approx(30.0 - 37.943));
  CHECK(r.utilisation == Approx(37.943 / 30.0));
  CHECK(r.at_distance == Approx(19.5));
  CHECK(r.at_time == Approx(1.95));
  CHECK(r.processing.back().find("0.15 %") != std::string::npos);
  // With a looser curve limit both pass and the decision is the larger utilisation (straight 18.97/20).
  q.limit = [](const TrackSection& sec) { return sec.zone == TrackZone::straight ? 20.0 : 60.0; };
  const Quantity p = assess(q, s.x, s.t, s.y, two_sections());
  CHECK(p.pass);
  CHECK(p.section == 0);
  CHECK(p.utilisation == Approx(18.9715 / 20.0));
}

TEST_CASE("upper percentile, median in curves only, maximum and rms", "[safety][quantity]") {
  const Series s = series();
  const auto secs = two_sections();
  const Quantity up = assess(spec(Statistic::upper), s.x, s.t, s.y, secs);
  CHECK(up.sections[0].value == Approx(18.9715));
  CHECK(up.sections[1].value == Approx(-0.057));  // F2 keeps its sign
  auto med = spec(Statistic::median);
  med.use_section = [](const TrackSection& sec) { return sec.zone != TrackZone::straight; };
  const Quantity m = assess(med, s.x, s.t, s.y, secs);
  REQUIRE(m.sections.size() == 1);  // the straight is skipped
  CHECK(m.sections[0].p_mid == Approx(-19.0));
  CHECK(m.value == Approx(19.0));
  const Quantity mx = assess(spec(Statistic::maximum), s.x, s.t, s.y, secs);
  CHECK(mx.sections[0].value == Approx(19.0));
  CHECK(mx.value == Approx(38.0));  // no limit: the largest value decides
  CHECK(std::isnan(mx.limit));
  CHECK(std::isnan(mx.margin));
  CHECK(mx.pass);
  auto rs = spec(Statistic::rms);
  rs.keep_series = true;
  const Quantity rms = assess(rs, s.x, s.t, s.y, secs);
  // sum i^2 (0..19) = 2470: sqrt(2470 / 20); the curve has 4 x that.
  CHECK(rms.sections[0].value == Approx(std::sqrt(123.5)));
  CHECK(rms.sections[1].value == Approx(2.0 * std::sqrt(123.5)));
  // The processed series is kept for charts when asked for.
  CHECK(rms.y.size() == 40);
  CHECK(mx.y.empty());
}

TEST_CASE("samples outside every evaluated section, bad input", "[safety][quantity]") {
  auto q = spec(Statistic::maximum);
  q.use_section = [](const TrackSection&) { return false; };
  const Series s = series();
  const Quantity r = assess(q, s.x, s.t, s.y, two_sections());
  CHECK_FALSE(r.evaluated);
  CHECK(r.pass);
  CHECK(r.sections.empty());
  CHECK_THROWS_AS(assess(q, {0.0, 1.0}, {0.0}, {0.0, 1.0}, two_sections()), std::invalid_argument);
  CHECK_THROWS_AS(assess(q, {0.0}, {0.0}, {0.0}, {}), std::invalid_argument);
  CHECK(time_at_distance({0.0, 10.0}, {0.0, 1.0}, 2.5) == Approx(0.25));
  CHECK(time_at_distance({0.0, 10.0}, {0.0, 1.0}, -5.0) == 0.0);
  CHECK(time_at_distance({0.0, 10.0}, {0.0, 1.0}, 50.0) == 1.0);
}
