// Charts of critical-speed analyses; see bifurcation_chart.hpp.
#include "engine/analysis/bifurcation_chart.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "engine/analysis/critical_speed_study.hpp"

namespace railsim::engine {

namespace {

constexpr double kKmh = 3.6;

results::ChartSeries series(const std::string& label, const std::string& color, const std::string& marker,
                            const std::string& linestyle, bool open = false, double size = 0.0) {
  results::ChartSeries s;
  s.label = label;
  s.color = color;
  s.style = results::custom_style(marker, linestyle, open, size);
  return s;
}

std::string kmh_text(double v) {
  if (!std::isfinite(v)) return "none found";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.0f km/h", v * kKmh);
  return buf;
}

// The series of one branch of one sweep. `main` adds the legend entry of the
// curve (its settled line); markers for the other states carry no label.
void add_branch(results::Chart& c, const std::vector<BifurcationPoint>& pts, Branch branch,
                const BifurcationOptions& o, const std::string& label, const std::string& color, double critical,
                double fold_amplitude, bool down) {
  std::vector<const BifurcationPoint*> b;
  for (const auto& p : pts)
    if (p.branch == branch) b.push_back(&p);
  std::sort(b.begin(), b.end(), [](auto* x, auto* y) { return x->speed < y->speed; });
  if (b.empty()) return;
  // Hunting branch: settled limit cycles, joined only between neighbouring settled speeds.
  results::ChartSeries settled = series(label, color, "o", "-", false, 5);
  results::ChartSeries growing = series("", color, "^", "", true, 6);
  results::ChartSeries decaying = series("", color, "v", "", true, 6);
  results::ChartSeries centred = series("", color, ".", ":", false, 5);
  results::ChartSeries stopped = series("", "k", "x", "", false, 6);
  results::ChartSeries failed = series("", "r", "X", "", false, 7);  // numerical failure or too short: no verdict
  const double nan = std::nan("");
  PointState prev = PointState::centred;
  for (const BifurcationPoint* p : b) {
    const PointState s = point_state(*p, o);
    const double x = given_kmh(p->speed), y = p->amplitude * 1e3;
    if (s == PointState::settled) {
      if (!settled.x.empty() && prev != PointState::settled) settled.x.push_back(nan), settled.y.push_back(nan);
      settled.x.push_back(x), settled.y.push_back(y);
    } else if (s == PointState::growing) {
      growing.x.push_back(x), growing.y.push_back(y);
    } else if (s == PointState::decaying) {
      decaying.x.push_back(x), decaying.y.push_back(y);
    } else if (s == PointState::stopped) {
      stopped.x.push_back(x), stopped.y.push_back(y);
    } else if (s == PointState::failed || s == PointState::too_short) {
      failed.x.push_back(x), failed.y.push_back(y);
    }
    if (s == PointState::centred) {
      if (!centred.x.empty() && prev != PointState::centred) centred.x.push_back(nan), centred.y.push_back(nan);
      centred.x.push_back(x), centred.y.push_back(y);
    }
    prev = s;
  }
  // The legend entry of the curve always exists, even without a settled point.
  c.series.push_back(settled);
  for (auto* s : {&growing, &decaying, &centred, &stopped, &failed})
    if (!s->x.empty()) c.series.push_back(*s);
  if (down && std::isfinite(critical) && std::isfinite(fold_amplitude)) {
    // The fold: the branch ends at the critical speed; below it the run falls back to the centred running.
    results::ChartSeries jump = series("", color, "", "--");
    jump.x = {given_kmh(critical), given_kmh(critical)};
    jump.y = {fold_amplitude * 1e3, 0.0};
    c.series.push_back(jump);
    results::ChartSeries foot = series("", color, "v", "", false, 5);
    foot.x = {given_kmh(critical)};
    foot.y = {0.0};
    c.series.push_back(foot);
  }
}

void add_legend_keys(results::Chart& c, const BifurcationOptions& o) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "filled: settled limit cycle (|growth| <= %.0f %% over the tail)",
                100.0 * o.decay_tolerance);
  c.series.push_back(series(buf, "0.3", "o", "-", false, 5));
  c.series.push_back(series("hollow: still decaying at the end of the run", "0.3", "v", "", true, 6));
  c.series.push_back(series("hollow: still growing at the end of the run", "0.3", "^", "", true, 6));
  std::snprintf(buf, sizeof buf, "dots: back to centred running (amplitude <= %.2g mm)", o.threshold * 1e3);
  c.series.push_back(series(buf, "0.3", ".", ":", false, 5));
  c.series.push_back(series("dashed drop: fold, jump to centred running", "0.3", "v", "--", false, 5));
  c.series.push_back(series("x: run derailed or stopped after its motion grew, counted as hunting", "k", "x", "", false, 6));
  c.series.push_back(series("red X: numerical failure or run too short: no verdict", "r", "X", "", false, 7));
}

}  // namespace

std::string critical_speed_rule(const BifurcationOptions& o) {
  char buf[640];
  std::snprintf(buf, sizeof buf,
                "Critical speed: the lowest speed of the down branch (from a %.3g mm shift%s) from which every "
                "speed up to %.0f km/h hunts: settled amplitude above %.2g mm, not decaying by more than %.0f %% "
                "over the last %.0f %% of a %.3g s run, or a stopped run. Step %.3g km/h: the fold lies within one "
                "step below it.",
                o.large_disturbance * 1e3,
                o.continuation ? ", then each speed from the limit cycle of the one above" : "", o.v_max * kKmh,
                o.threshold * 1e3, 100.0 * o.decay_tolerance, 100.0 * o.tail_fraction, o.duration,
                o.v_step * kKmh);
  return buf;
}

results::Chart bifurcation_chart(const std::vector<BifurcationCurve>& curves, const BifurcationOptions& o,
                                 const std::string& title, bool up_branch) {
  results::Chart c;
  c.title = title;
  c.xlabel = "speed [km/h]";
  c.ylabel = "lateral amplitude over the tail of each run [mm]";
  c.y_from_zero = true;
  c.note = critical_speed_rule(o);
  c.width = curves.size() > 2 ? 11.0 : 9.0;
  c.height = curves.size() > 2 ? 6.5 : 6.0;
  for (const auto& cv : curves) {
    if (!cv.result) continue;
    const std::string label = cv.label + ": critical speed " + kmh_text(cv.result->nonlinear_critical_speed);
    add_branch(c, cv.result->points, Branch::down, o, label, cv.color, cv.result->nonlinear_critical_speed,
               cv.result->fold_amplitude, true);
    if (up_branch && curves.size() == 1)
      add_branch(c, cv.result->points, Branch::up, o, cv.label + ", up branch (small disturbance)", "0.55", std::nan(""),
                 std::nan(""), false);
  }
  add_legend_keys(c, o);
  if (curves.size() == 1 && curves.front().result) {
    const auto& cv = curves.front();
    if (std::isfinite(cv.linear_critical_speed))
      c.lines.push_back({cv.linear_critical_speed * kKmh, "linear critical speed " + kmh_text(cv.linear_critical_speed),
                         "r", true});
    if (std::isfinite(cv.result->nonlinear_critical_speed))
      c.lines.push_back({given_kmh(cv.result->nonlinear_critical_speed),
                         "nonlinear critical speed " + kmh_text(cv.result->nonlinear_critical_speed), "g", true});
  }
  char buf[64];
  std::snprintf(buf, sizeof buf, "hunting threshold %.2g mm", o.threshold * 1e3);
  c.lines.push_back({o.threshold * 1e3, buf, "0.5", false});
  return c;
}

void ramping_envelope(const RampingResult& r, std::vector<double>& speed_kmh, std::vector<double>& peak_mm,
                      double window) {
  speed_kmh.clear();
  peak_mm.clear();
  const auto& m = r.max_lateral;
  // The largest value in consecutive windows of `window` seconds (a few cycles
  // of the hunting motion: the beat between wheelsets does not show as a band).
  std::size_t i = 0;
  while (i < m.size()) {
    std::size_t best = i, j = i;
    for (; j < m.size() && r.time[j] < r.time[i] + window; ++j)
      if (m[j] > m[best]) best = j;
    speed_kmh.push_back(r.speed[best] * kKmh);
    peak_mm.push_back(m[best] * 1e3);
    i = std::max(j, i + 1);
  }
}

results::Chart ramping_chart(const RampingResult& r, double linear, double threshold, const std::string& title) {
  results::Chart c;
  c.title = title;
  c.xlabel = "speed [km/h]";
  c.ylabel = "max |lateral shift| of the wheelsets over 0.5 s [mm]";
  c.y_from_zero = true;
  char buf[200];
  std::snprintf(buf, sizeof buf, "ramp from %.1f km/h (settled there first), decelerating", r.start_speed * kKmh);
  results::ChartSeries s = series(buf, "tab:blue", "", "-");
  ramping_envelope(r, s.x, s.y);
  c.series.push_back(s);
  if (std::isfinite(r.critical_speed) && std::isfinite(r.critical_amplitude)) {
    std::snprintf(buf, sizeof buf, "critical speed read here: %.1f km/h (start of the final collapse)",
                  r.critical_speed * kKmh);
    results::ChartSeries at = series(buf, "g", "*", "", false, 12);
    at.x = {r.critical_speed * kKmh};
    at.y = {r.critical_amplitude * 1e3};
    c.series.push_back(at);
    c.lines.push_back({r.critical_speed * kKmh, "", "g", true});
  }
  if (std::isfinite(linear)) {
    std::snprintf(buf, sizeof buf, "linear critical speed %.1f km/h", linear * kKmh);
    c.lines.push_back({linear * kKmh, buf, "r", true});
  }
  std::snprintf(buf, sizeof buf, "threshold %.2g mm", threshold * 1e3);
  c.lines.push_back({threshold * 1e3, buf, "0.5", false});
  c.note = "Critical speed: the speed where the envelope of the lateral motion starts its final collapse (its "
           "half-cycle peaks decay faster than the collapse rate down to below the threshold). The speed falls "
           "from right to left.";
  if (r.hunting_at_end) c.note += " Still hunting at the end of the ramp: no critical speed in the range.";
  if (!r.hunting_at_start) c.note += " No hunting at the start speed: no critical speed.";
  return c;
}

}  // namespace railsim::engine
