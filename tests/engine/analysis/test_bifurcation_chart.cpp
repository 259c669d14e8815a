// Honest charts (engine/analysis/bifurcation_chart.cpp): what every run did by
// its end decides its marker, no line runs through an unsettled point, the
// fold is a jump from the limit cycle to the centred running, the rule is on
// the chart; ramping charts name the start speed and mark where the critical
// speed was read. Also the point states and the fold of a real sweep.
#include <catch2/catch.hpp>

#include <cmath>

#include "engine/analysis/bifurcation_chart.hpp"
#include "flange_sweep.hpp"
#include "test_support.hpp"

using namespace railsim::engine;

namespace {

BifurcationPoint point(double v, double amp_mm, double growth, bool failed = false) {
  BifurcationPoint p;
  p.speed = v;
  p.branch = Branch::down;
  p.amplitude = amp_mm * 1e-3;
  p.growth = growth;
  p.failed = failed;
  p.frequency = 2.0;
  return p;
}

const railsim::results::ChartSeries* find_style(const railsim::results::Chart& c, const std::string& part,
                                                const std::string& color) {
  for (const auto& s : c.series)
    if (s.style.find(part) != std::string::npos && s.color == color && !s.x.empty()) return &s;
  return nullptr;
}

}  // namespace

TEST_CASE("point states: settled, growing, decaying, centred, stopped, failed, too short", "[chart][critical_speed]") {
  BifurcationOptions o;  // threshold 0.5 mm, decay tolerance 5 %
  CHECK(point_state(point(60, 6.0, 0.01), o) == PointState::settled);
  CHECK(point_state(point(60, 6.0, -0.049), o) == PointState::settled);
  CHECK(point_state(point(60, 6.0, 0.2), o) == PointState::growing);
  CHECK(point_state(point(60, 2.0, -0.3), o) == PointState::decaying);
  CHECK(point_state(point(60, 0.4, -0.3), o) == PointState::centred);
  CHECK(point_state(point(60, 0.4, 0.0, true), o) == PointState::stopped);
  // A numerical failure and a run with no cycle in its tail have no verdict: not hunting.
  BifurcationPoint failed = point(60, 6.0, 0.0);
  failed.numerical_failure = true;
  CHECK(point_state(failed, o) == PointState::failed);
  CHECK_FALSE(is_hunting(failed, o));
  BifurcationPoint short_run = point(60, 6.0, 0.0);
  short_run.frequency = 0.0;
  CHECK(point_state(short_run, o) == PointState::too_short);
  CHECK_FALSE(is_hunting(short_run, o));
  CHECK(point_state(point(60, 0.4, 0.0), o) == PointState::centred);  // below the threshold: no cycle needed
  CHECK(is_hunting(point(60, 0.4, 0.0, true), o));  // a derailment counts as hunting
  // Hunting as before: settled or growing above the threshold, or stopped.
  CHECK(is_hunting(point(60, 6.0, 0.2), o));
  CHECK_FALSE(is_hunting(point(60, 2.0, -0.3), o));
}

TEST_CASE("bifurcation chart: markers by state, no line through unsettled points, the fold as a jump",
          "[chart][critical_speed]") {
  BifurcationOptions o;
  o.v_min = 50;
  o.v_max = 80;
  o.v_step = 5;
  BifurcationResult r;
  r.points = {point(50, 0.1, -0.5), point(55, 2.0, -0.3), point(60, 6.0, 0.01), point(65, 7.0, 0.2),
              point(70, 8.0, 0.0),  point(75, 8.5, 0.0, true), point(80, 9.0, 0.0)};
  r.nonlinear_critical_speed = 60;
  r.fold_amplitude = 6e-3;
  const auto c = bifurcation_chart({{"k = 1", "tab:blue", &r, 70.0}}, o, "test", false);
  const auto* settled = find_style(c, "marker=o;line=-", "tab:blue");
  REQUIRE(settled != nullptr);
  // Settled points at 60, 70, 80 m/s, the line broken at the growing (65) and stopped (75) runs.
  REQUIRE(settled->x.size() == 5);
  CHECK(settled->x[0] == Approx(216.0));
  CHECK(std::isnan(settled->x[1]));
  CHECK(settled->x[2] == Approx(252.0));
  CHECK(std::isnan(settled->x[3]));
  CHECK(settled->x[4] == Approx(288.0));
  CHECK(settled->label.find("critical speed 216 km/h") != std::string::npos);
  const auto* decaying = find_style(c, "marker=v;line=;open", "tab:blue");
  REQUIRE(decaying != nullptr);
  CHECK(decaying->x == std::vector<double>{55 * 3.6});
  const auto* growing = find_style(c, "marker=^;line=;open", "tab:blue");
  REQUIRE(growing != nullptr);
  CHECK(growing->x == std::vector<double>{65 * 3.6});
  const auto* stopped = find_style(c, "marker=x", "k");
  REQUIRE(stopped != nullptr);
  CHECK(stopped->x == std::vector<double>{75 * 3.6});
  const auto* centred = find_style(c, "marker=.;line=:", "tab:blue");
  REQUIRE(centred != nullptr);
  CHECK(centred->x == std::vector<double>{50 * 3.6});
  // The jump: a dashed drop at the critical speed from the fold's limit cycle to zero.
  const auto* jump = find_style(c, "marker=;line=--", "tab:blue");
  REQUIRE(jump != nullptr);
  CHECK(jump->x == std::vector<double>{216.0, 216.0});
  CHECK(jump->y == std::vector<double>{6.0, 0.0});
  // The rule and the legend keys are on the chart; the reference lines with one curve.
  CHECK(c.note.find("lowest speed of the down branch") != std::string::npos);
  CHECK(c.note.find("0.5 mm") != std::string::npos);
  CHECK(c.note.find("Step 18 km/h") != std::string::npos);
  bool key = false, linear = false;
  for (const auto& s : c.series) key |= s.label.find("still decaying at the end") != std::string::npos;
  for (const auto& l : c.lines) linear |= l.label.find("linear critical speed 252 km/h") != std::string::npos;
  CHECK(key);
  CHECK(linear);
}

TEST_CASE("ramping chart names the start speed and marks where the critical speed was read", "[chart][critical_speed]") {
  RampingResult r;
  r.start_speed = 300 / 3.6;
  r.critical_speed = 250 / 3.6;
  r.critical_amplitude = 6e-3;
  r.hunting_at_start = true;
  r.time = {0, 1, 2};
  r.speed = {300 / 3.6, 280 / 3.6, 260 / 3.6};
  r.max_lateral = {7e-3, 6.5e-3, 6e-3};
  const auto c = ramping_chart(r, 310 / 3.6, 0.5e-3, "ramp");
  REQUIRE(c.series.size() == 2);
  CHECK(c.series[0].label.find("ramp from 300.0 km/h") != std::string::npos);
  CHECK(c.series[1].label.find("critical speed read here: 250.0 km/h") != std::string::npos);
  REQUIRE(c.series[1].x.size() == 1);
  CHECK(c.series[1].x[0] == Approx(250.0));
  CHECK(c.series[1].y[0] == Approx(6.0));
  CHECK(c.note.find("final collapse") != std::string::npos);
  // The envelope: the largest value in each window (here 2 s: samples 0-1, 2-3, 4).
  r.time = {0, 1, 2, 3, 4};
  r.speed = {50, 49, 48, 47, 46};
  r.max_lateral = {1e-3, 3e-3, 1e-3, 2e-3, 1e-3};
  std::vector<double> v, peak;
  ramping_envelope(r, v, peak, 2.0);
  const double want_v[] = {176.4, 169.2, 165.6}, want_peak[] = {3.0, 2.0, 1.0};
  REQUIRE(v.size() == 3);
  REQUIRE(peak.size() == 3);
  for (int i = 0; i < 3; ++i) {
    CHECK(v[static_cast<std::size_t>(i)] == Approx(want_v[i]));
    CHECK(peak[static_cast<std::size_t>(i)] == Approx(want_peak[i]));
  }
}

TEST_CASE("a sweep reports the limit cycle at its fold", "[chart][critical_speed]") {
  const Scenario sc = load_scenario(railsim::test::data_path("scenarios/single_wheelset_flange.yaml"));
  BifurcationOptions o = railsim::test::flange_sweep_options();
  const auto r = bifurcation_sweep(sc, o, railsim::test::temp_dir("fold") + "/points.csv");
  REQUIRE(std::isfinite(r.nonlinear_critical_speed));
  for (const auto& p : r.points)
    if (p.speed == r.nonlinear_critical_speed) {
      CHECK(r.fold_amplitude == p.amplitude);
      CHECK(r.fold_frequency == p.frequency);
    }
  CHECK(r.fold_amplitude > o.threshold);
  CHECK(r.undetermined.empty());
}
