// One run of a scenario with its report; see scenario_run.hpp. (Moved from
// cli/cmd_run.cpp so that the program and the Python module share it.)
#include "engine/analysis/scenario_run.hpp"

#include <spdlog/spdlog.h>
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <memory>

#include "core/errors.hpp"
#include "engine/analysis/curving.hpp"
#include "engine/analysis/run_history.hpp"
#include "engine/analysis/run_safety.hpp"
#include "engine/analysis/safety_settings.hpp"
#include "engine/analysis/track_zones.hpp"
#include "engine/analysis/wheel_load_sanity.hpp"
#include "engine/track_input.hpp"
#include "results/chart.hpp"
#include "results/csv_writer.hpp"

namespace railsim::engine {

namespace {
constexpr double kDeg = 180.0 / 3.14159265358979323846;

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

results::Json peak_json(double value, double distance, double time) {
  results::Json j = results::Json::object();
  j.set("max", value);
  j.set("distance", distance);
  j.set("time", time);
  return j;
}

results::Json strings(const std::vector<std::string>& v) {
  results::Json a = results::Json::array();
  for (const auto& s : v) a.push(s);
  return a;
}

std::string zone_of(const engine::RunSafety& rs, std::size_t section) {
  return engine::zone_name(rs.sections[section].zone);
}

// The deciding value of a quantity: value, limit, margin, where, when, zone.
results::Json verdict_json(const engine::Quantity& q, const engine::RunSafety& rs) {
  results::Json j = results::Json::object();
  j.set("item", q.item);
  j.set("evaluated", q.evaluated);
  j.set("value", q.evaluated ? results::Json(q.value) : results::Json());
  j.set("limit", q.limit);
  j.set("margin", q.margin);
  j.set("utilisation", q.utilisation);
  j.set("pass", q.pass);
  if (q.evaluated) {
    const auto& sec = rs.sections[q.section];
    j.set("zone", zone_of(rs, q.section));
    j.set("test_zone", engine::test_zone_label(sec.zone, sec.radius));
    j.set("section", static_cast<long>(q.section));
    j.set("at_distance", q.at_distance);
    j.set("at_time", q.at_time);
  }
  return j;
}

results::Json quantity_json(const engine::Quantity& q, const engine::RunSafety& rs) {
  results::Json j = verdict_json(q, rs);
  j.set("processing", strings(q.processing));
  results::Json secs = results::Json::array();
  for (const auto& v : q.sections) {
    results::Json s = results::Json::object();
    s.set("section", static_cast<long>(v.section));
    s.set("zone", engine::zone_name(v.zone));
    s.set("samples", static_cast<long>(v.samples));
    if (!std::isnan(v.p_low)) s.set("F1", v.p_low);
    if (!std::isnan(v.p_high)) s.set("F2", v.p_high);
    if (!std::isnan(v.p_mid)) s.set("F0", v.p_mid);
    s.set("value", v.value);
    s.set("limit", v.limit);
    s.set("pass", v.pass);
    s.set("peak", v.peak);
    s.set("peak_distance", v.peak_distance);
    s.set("peak_time", v.peak_time);
    secs.push(s);
  }
  j.set("sections", secs);
  return j;
}

// Worst item of a list of quantities (largest utilisation, or value without limits).
const engine::Quantity* worst_of(const std::vector<const engine::Quantity*>& qs) {
  const engine::Quantity* w = nullptr;
  double best = -INFINITY;
  for (const auto* q : qs) {
    if (!q->evaluated) continue;
    const double score = std::isnan(q->limit) ? q->value : q->utilisation;
    if (score > best || (!q->pass && w && w->pass)) best = score, w = q;
  }
  return w;
}

results::Json sections_json(const engine::RunSafety& rs) {
  results::Json a = results::Json::array();
  for (std::size_t k = 0; k < rs.sections.size(); ++k) {
    const auto& s = rs.sections[k];
    results::Json j = results::Json::object();
    j.set("section", static_cast<long>(k));
    j.set("zone", engine::zone_name(s.zone));
    j.set("test_zone", engine::test_zone_label(s.zone, s.radius));
    j.set("kind", s.kind);
    j.set("direction", s.direction);
    j.set("start", s.design_start);
    j.set("end", s.design_end);
    j.set("radius_m", std::isfinite(s.radius) ? results::Json(s.radius) : results::Json());
    j.set("cant_mm", s.cant * 1e3);
    a.push(j);
  }
  return a;
}

// Every quantity name in order of first appearance, with its items.
std::vector<std::pair<std::string, std::vector<const engine::Quantity*>>> by_name(const engine::RunSafety& rs) {
  std::vector<std::pair<std::string, std::vector<const engine::Quantity*>>> out;
  for (const auto& q : rs.quantities) {
    auto it = std::find_if(out.begin(), out.end(), [&](const auto& p) { return p.first == q.name; });
    if (it == out.end()) out.push_back({q.name, {&q}});
    else it->second.push_back(&q);
  }
  return out;
}

results::Json quantities_json(const engine::RunSafety& rs) {
  results::Json a = results::Json::array();
  for (const auto& [name, items] : by_name(rs)) {
    const engine::Quantity& first = *items.front();
    results::Json j = results::Json::object();
    j.set("quantity", name);
    j.set("symbol", first.symbol);
    j.set("kind", first.kind);
    j.set("unit", first.unit);
    j.set("limit_source", first.limit_source.empty() ? "none: reported only" : first.limit_source);
    bool pass = true;
    for (const auto* q : items) pass = pass && q->pass;
    j.set("pass", pass);
    const engine::Quantity* w = worst_of(items);
    j.set("worst", w ? verdict_json(*w, rs) : results::Json());
    results::Json arr = results::Json::array();
    for (const auto* q : items) arr.push(quantity_json(*q, rs));
    j.set("items", arr);
    a.push(j);
  }
  return a;
}

// Per zone: the worst item of every quantity within the zone's sections.
results::Json zone_summary_json(const engine::RunSafety& rs) {
  results::Json a = results::Json::array();
  for (int z = 0; z < engine::kZoneCount; ++z) {
    const auto zone = static_cast<engine::TrackZone>(z);
    double length = 0.0;
    long count = 0;
    for (const auto& s : rs.sections)
      if (s.zone == zone) length += s.design_end - s.design_start, ++count;
    if (count == 0) continue;
    results::Json zj = results::Json::object();
    zj.set("zone", engine::zone_name(zone));
    zj.set("sections", count);
    zj.set("design_length_m", length);
    bool zpass = true;
    results::Json qa = results::Json::array();
    for (const auto& [name, items] : by_name(rs)) {
      const engine::Quantity* worst = nullptr;
      const engine::SectionValue* wv = nullptr;
      double best = -INFINITY;
      bool pass = true;
      for (const auto* q : items)
        for (const auto& v : q->sections) {
          if (v.zone != zone) continue;
          pass = pass && v.pass;
          const double score = std::isnan(v.limit) ? v.value : v.value / v.limit;
          if (score > best) best = score, worst = q, wv = &v;
        }
      if (!worst) continue;
      zpass = zpass && pass;
      results::Json j = results::Json::object();
      j.set("quantity", name);
      j.set("symbol", worst->symbol);
      j.set("item", worst->item);
      j.set("value", wv->value);
      j.set("limit", wv->limit);
      j.set("margin", wv->limit - wv->value);
      j.set("pass", pass);
      j.set("at_distance", wv->peak_distance);
      j.set("at_time", wv->peak_time);
      j.set("section", static_cast<long>(wv->section));
      qa.push(j);
    }
    zj.set("pass", zpass);
    zj.set("by_quantity", qa);
    a.push(zj);
  }
  return a;
}

results::Json safety_json(const engine::RunSafety& rs, const engine::FlangeAngle& fa) {
  results::Json j = results::Json::object();
  j.set("pass", rs.pass);
  j.set("standard", "EN 14363:2016 / UIC 518 on-track assessment quantities, as in the public summaries named in "
                    "engine/analysis/run_safety.hpp and safety_limits.hpp; pass = Nadal and every quantity "
                    "with a limit within it in every track section");
  j.set("flange_angle_deg", rs.flange_angle * kDeg);
  j.set("flange_angle_source", fa.source);
  j.set("flange_angle_fallback", fa.fallback);
  j.set("mu", rs.mu);
  j.set("nadal_limit", rs.nadal);
  j.set("vehicle_category", engine::vehicle_category_name(rs.settings.category));
  j.set("track_shift_factor_k1", rs.k1);
  j.set("max_speed_kmh", rs.max_speed * 3.6);
  results::Json lim = results::Json::object();
  lim.set("yq_2m", "0.8 (R >= 250 m), 1.2 (R < 250 m)");
  lim.set("wheel_unloading", engine::kWheelUnloadingLimit);
  lim.set("y_qst_N", engine::kYqstLimit);
  lim.set("q_qst_N", engine::kQqstLimit);
  lim.set("window_m", rs.settings.window);
  lim.set("step_m", rs.settings.step);
  lim.set("rms_window_m", rs.settings.rms_window);
  lim.set("rms_step_m", rs.settings.rms_step);
  results::Json pc = results::Json::array();
  for (double v : {rs.settings.percentile_low, rs.settings.percentile_high, rs.settings.percentile_qst}) pc.push(v);
  lim.set("percentiles", pc);
  j.set("limits", lim);
  const auto& p = rs.processing;
  results::Json pj = results::Json::object();
  pj.set("sample_rate_hz", p.sample_rate);
  pj.set("force_lowpass", p.force_filter);
  pj.set("force_lowpass_applied", p.force_filter_applied);
  pj.set("acceleration_bandpass", p.acceleration_filter);
  pj.set("acceleration_bandpass_applied", p.acceleration_filter_applied);
  pj.set("hunting_frequency_hz", p.hunting_frequency);
  pj.set("hunting_frequency_source", p.hunting_frequency_source);
  pj.set("instability_bandpass", p.instability_filter);
  pj.set("instability_bandpass_applied", p.instability_filter_applied);
  pj.set("zero_phase", "every filter is applied forward then backward (magnitude |H|^2, no phase shift)");
  j.set("processing", pj);
  j.set("en14363_evaluated", rs.en14363_evaluated);
  j.set("instability_evaluated", rs.instability_evaluated);
  j.set("distances", "track distance of the item (wheelset or measuring point) [m]; times [s]; forces [N]");
  j.set("notes", strings(rs.notes));
  j.set("zones", sections_json(rs));
  j.set("zone_summary", zone_summary_json(rs));
  j.set("quantities", quantities_json(rs));
  results::Json arr = results::Json::array();
  for (const auto& w : rs.wheelsets) {
    results::Json a = results::Json::object();
    a.set("name", w.name);
    a.set("pass", w.pass);
    a.set("static_wheel_load", w.static_wheel_load);
    results::Json wheels = results::Json::object();
    for (int side = 0; side < 2; ++side) {
      const auto& ws = w.wheel[side];
      results::Json wj = results::Json::object();
      results::Json inst = peak_json(ws.max_abs_yq.value, ws.max_abs_yq.distance, ws.max_abs_yq.time);
      inst.set("nadal_limit", rs.nadal);
      inst.set("exceeds_nadal", ws.max_abs_yq.value > rs.nadal);
      inst.set("longest_exceedance_m", ws.longest_exceedance);
      inst.set("processing", "unfiltered, instantaneous (reported; the verdict is 'nadal')");
      wj.set("yq_instantaneous", inst);
      results::Json nad = ws.nadal_on_2m ? peak_json(ws.max_yq_2m.value, ws.max_yq_2m.distance, ws.max_yq_2m.time)
                                         : peak_json(ws.max_abs_yq.value, ws.max_abs_yq.distance, ws.max_abs_yq.time);
      nad.set("limit", rs.nadal);
      nad.set("pass", ws.nadal_pass);
      nad.set("processing", ws.nadal_on_2m ? "unfiltered |Y/Q|, 2 m sliding mean every 0.5 m (flange climb takes metres)"
                                           : "unfiltered |Y/Q|, instantaneous (no 2 m windows: the vehicle does not "
                                             "advance 2 m)");
      wj.set("nadal", nad);
      const std::string item = engine::wheel_item(w.name, side);
      for (const char* name : {"yq_2m", "q_max", "wheel_unloading", "y_qst", "q_qst", "yq_qst"})
        if (const auto* q = rs.find(name, item)) wj.set(name, verdict_json(*q, rs));
      wheels.set(side == 0 ? "left" : "right", wj);
    }
    a.set("wheels", wheels);
    if (const auto* q = rs.find("sum_y_2m", w.name)) a.set("sum_y_2m", verdict_json(*q, rs));
    if (const auto* q = rs.find("sum_y_rms", w.name)) a.set("sum_y_rms", verdict_json(*q, rs));
    results::Json u = results::Json::object();
    for (int side = 0; side < 2; ++side)
      if (const auto* q = rs.find("wheel_unloading", engine::wheel_item(w.name, side)))
        u.set(side == 0 ? "left" : "right", verdict_json(*q, rs));
    a.set("wheel_unloading", u);
    results::Json sh = peak_json(w.max_shift.value, w.max_shift.distance, w.max_shift.time);
    sh.set("definition", "relative to the rails (wheelset lateral position minus the mean lateral irregularity "
                         "of its rails)");
    a.set("max_lateral_shift", sh);
    results::Json sa = peak_json(w.max_shift_absolute.value, w.max_shift_absolute.distance, w.max_shift_absolute.time);
    sa.set("definition", "absolute: relative to the design centre line of the track");
    a.set("max_lateral_shift_absolute", sa);
    bool en = true;
    for (const auto& q : rs.quantities)
      if (q.item == w.name || q.item == engine::wheel_item(w.name, 0) || q.item == engine::wheel_item(w.name, 1))
        en = en && q.pass;
    a.set("en14363_pass", en);
    arr.push(a);
  }
  j.set("wheelsets", arr);
  results::Json bog = results::Json::array();
  for (const auto& q : rs.quantities)
    if (q.name == "bogie_ay_rms") bog.push(verdict_json(q, rs));
  j.set("bogie_frames", bog);
  return j;
}

results::Json stat_json(const engine::Stat& s, double scale = 1.0) {
  results::Json j = results::Json::object();
  j.set("mean", s.mean * scale);
  j.set("min", s.min * scale);
  j.set("max", s.max * scale);
  return j;
}

results::Json curving_json(const std::vector<engine::CurveResult>& curves, const engine::CurvingOptions& opt) {
  results::Json j = results::Json::object();
  j.set("settle_distance_m", opt.settle_distance);
  j.set("angle_of_attack_sign", "wheelset yaw relative to the track, > 0 heading toward the outer rail");
  j.set("lateral_shift_sign", "relative to the rails, > 0 toward the outer rail");
  j.set("tgamma_definition", "-(Fx xi + Fy eta + Mz spin) [N], spin term included");
  results::Json arr = results::Json::array();
  for (const auto& c : curves) {
    results::Json cj = results::Json::object();
    cj.set("radius_m", 1.0 / std::fabs(c.curvature));
    cj.set("direction", c.curvature > 0 ? "left" : "right");
    cj.set("cant_angle_rad", c.cant);
    cj.set("start_distance", c.start);
    cj.set("end_distance", c.end);
    cj.set("samples", static_cast<long>(c.samples));
    cj.set("mean_speed", c.mean_speed);
    cj.set("unbalanced_lateral_acceleration", c.unbalanced_acceleration);
    cj.set("sum_Y_mean", c.sum_Y);
    cj.set("sum_Y_expected_M_a_nc", c.expected_sum_Y);
    results::Json ws = results::Json::array();
    for (const auto& w : c.wheelsets) {
      results::Json wj = results::Json::object();
      wj.set("name", w.name);
      wj.set("angle_of_attack_mrad", stat_json(w.angle_of_attack, 1e3));
      wj.set("lateral_shift_mm", stat_json(w.lateral_shift, 1e3));
      results::Json wheels = results::Json::object();
      for (int s = 0; s < 2; ++s) {
        const auto& wc = w.wheel[s];
        results::Json x = results::Json::object();
        x.set("outer", wc.outer);
        x.set("YQ", stat_json(wc.yq));
        x.set("Y", stat_json(wc.Y));
        x.set("Q", stat_json(wc.Q));
        x.set("Tgamma", stat_json(wc.Tgamma));
        wheels.set(s == 0 ? "left" : "right", x);
      }
      wj.set("wheels", wheels);
      ws.push(wj);
    }
    cj.set("wheelsets", ws);
    arr.push(cj);
  }
  j.set("curves", arr);
  return j;
}

// What the charts need besides the evaluation.
struct ChartContext {
  std::string title_tail;  // "vehicle, speed, contact model"
  std::vector<engine::DefectRange> defects;
};

// Curves, transitions and defects as shaded spans over [x0, x1].
void shade_track(results::Chart& c, const engine::RunSafety& rs, const ChartContext& ctx, double x0, double x1) {
  for (const auto& s : rs.sections) {
    if (s.zone == engine::TrackZone::straight) continue;
    const double a = std::max(x0, s.design_start), b = std::min(x1, s.design_end);
    if (!(b > a)) continue;
    results::ChartSpan sp;
    sp.x0 = a, sp.x1 = b;
    if (s.zone == engine::TrackZone::transition) {
      sp.label = "transition";
      sp.color = "tab:orange";
      sp.alpha = 0.12;
    } else {
      sp.label = "circular curve";
      sp.color = "tab:blue";
      sp.alpha = 0.10;
    }
    c.spans.push_back(sp);
  }
  for (const auto& d : ctx.defects) {
    if (d.end < x0 || d.start > x1) continue;
    results::ChartSpan sp;
    sp.x0 = d.start, sp.x1 = d.end;
    sp.label = "defect";
    sp.color = "tab:red";
    sp.alpha = 0.6;
    sp.hatch = "//";
    c.spans.push_back(sp);
  }
}

double interp(const std::vector<double>& x, const std::vector<double>& y, double s) {
  const auto it = std::lower_bound(x.begin(), x.end(), s);
  if (it == x.begin() || it == x.end()) return NAN;
  const std::size_t j = static_cast<std::size_t>(it - x.begin());
  const double u = (s - x[j - 1]) / (x[j] - x[j - 1]);
  return y[j - 1] + u * (y[j] - y[j - 1]);
}

// At most this many points per chart series (the PNG is ~1000 px wide);
// longer series keep the minimum and the maximum of every bucket, so peaks stay.
constexpr std::size_t kChartPoints = 4000;

void decimate(std::vector<double>& x, std::vector<double>& y) {
  const std::size_t n = x.size();
  if (n <= kChartPoints) return;
  const std::size_t bucket = (n + kChartPoints / 2 - 1) / (kChartPoints / 2);
  std::vector<double> xo, yo;
  xo.reserve(kChartPoints + 2);
  yo.reserve(kChartPoints + 2);
  for (std::size_t b = 0; b < n; b += bucket) {
    const std::size_t e = std::min(n, b + bucket);
    std::size_t lo = b, hi = b;
    for (std::size_t i = b; i < e; ++i) {
      if (y[i] < y[lo]) lo = i;
      if (y[i] > y[hi]) hi = i;
    }
    for (std::size_t i : {std::min(lo, hi), std::max(lo, hi)}) {
      if (!xo.empty() && xo.back() == x[i]) continue;
      xo.push_back(x[i]);
      yo.push_back(y[i]);
    }
  }
  x = std::move(xo);
  y = std::move(yo);
}

// (Y/Q)_2m of both wheels of the worst wheelset, the envelope over all
// wheelsets, the section limits, Nadal; curves, transitions, defects shaded.
bool chart_yq(const engine::RunHistory& h, const engine::RunSafety& rs, const ChartContext& ctx, results::Chart& c) {
  if (h.wheelsets.empty() || h.size() < 2 || !rs.en14363_evaluated) return false;
  std::size_t worst = 0;
  double best = -INFINITY;
  for (std::size_t w = 0; w < h.wheelsets.size(); ++w)
    for (int side = 0; side < 2; ++side)
      if (const auto* q = rs.find("yq_2m", engine::wheel_item(h.wheelsets[w].name, side)))
        if (q->evaluated && q->utilisation > best) best = q->utilisation, worst = w;
  const auto& wh = h.wheelsets[worst];
  c.title = "(Y/Q)_2m, worst wheelset " + wh.name + ": " + ctx.title_tail;
  c.xlabel = "track distance of the wheelset [m]";
  c.ylabel = "Y/Q [-]";
  c.legend = "outside";
  // Envelope of all wheelsets on a 0.5 m grid.
  double x0 = INFINITY, x1 = -INFINITY;
  std::vector<const engine::Quantity*> all;
  for (const auto& q : rs.quantities)
    if (q.name == "yq_2m" && !q.x.empty()) {
      all.push_back(&q);
      x0 = std::min(x0, q.x.front());
      x1 = std::max(x1, q.x.back());
    }
  if (all.empty()) return false;
  results::ChartBand env;
  env.label = "(Y/Q)_2m envelope of all wheelsets";
  // Extremes over all wheels on the window grid (0.5 m), gathered into at most
  // kChartPoints / 2 buckets (lowest low, highest high of each).
  const double step = rs.settings.step;
  const auto cells = static_cast<std::size_t>(std::floor((x1 - x0) / step)) + 1;
  const std::size_t per = std::max<std::size_t>(1, (cells + kChartPoints / 2 - 1) / (kChartPoints / 2));
  double lo = INFINITY, hi = -INFINITY, xs = 0.0;
  std::size_t in_bucket = 0;
  for (std::size_t k = 0; k < cells; ++k) {
    const double s = x0 + static_cast<double>(k) * step;
    for (const auto* q : all) {
      const double v = interp(q->x, q->y, s);
      if (std::isnan(v)) continue;
      lo = std::min(lo, v), hi = std::max(hi, v);
    }
    xs += s;
    if (++in_bucket == per || k + 1 == cells) {
      if (std::isfinite(lo)) {
        env.x.push_back(xs / static_cast<double>(in_bucket));
        env.y_low.push_back(lo);
        env.y_high.push_back(hi);
      }
      lo = INFINITY, hi = -INFINITY, xs = 0.0, in_bucket = 0;
    }
  }
  c.bands.push_back(env);
  const char* names[2] = {"left", "right"};
  const char* colors[2] = {"tab:blue", "tab:red"};
  const char* styles[2] = {"line", "dashed"};
  for (int side = 0; side < 2; ++side) {
    // Instantaneous (unfiltered) Y/Q, thin and light.
    results::ChartSeries raw;
    raw.label = wh.name + " " + names[side] + ", instantaneous";
    raw.color = colors[side];
    raw.style = "faint";
    for (std::size_t i = 0; i < h.size(); ++i) {
      raw.x.push_back(h.wheelset_distance(worst, i));
      raw.y.push_back(wh.wheel[side].Q[i] > 0.0 ? wh.wheel[side].Y[i] / wh.wheel[side].Q[i] : 0.0);
    }
    decimate(raw.x, raw.y);
    c.series.push_back(std::move(raw));
  }
  for (int side = 0; side < 2; ++side)
    if (const auto* q = rs.find("yq_2m", engine::wheel_item(wh.name, side))) {
      results::ChartSeries m;
      m.label = wh.name + " " + names[side] + ", (Y/Q)_2m";
      m.x = q->x;
      m.y = q->y;
      decimate(m.x, m.y);
      m.color = side == 0 ? "navy" : "darkred";
      m.style = styles[side];
      c.series.push_back(std::move(m));
    }
  // Limits along the track (they change with the radius).
  results::ChartSeries up, dn;
  up.label = "(Y/Q)_2m limit";
  up.style = "step";
  up.color = "tab:orange";
  dn.style = "step";
  dn.color = "tab:orange";
  for (const auto& s : rs.sections) {
    const double a = std::max(x0, s.start), b = std::min(x1, s.end);
    if (!(b > a)) continue;
    const double lim = engine::yq_2m_limit(s.radius);
    for (double x : {a, b}) {
      up.x.push_back(x), up.y.push_back(lim);
      dn.x.push_back(x), dn.y.push_back(-lim);
    }
  }
  c.series.push_back(up);
  c.series.push_back(dn);
  char buf[96];
  std::snprintf(buf, sizeof buf, "Nadal %.3g (%.1f deg, mu %.2g)", rs.nadal, rs.flange_angle * kDeg, rs.mu);
  c.lines.push_back({rs.nadal, buf, "k", false});
  c.lines.push_back({-rs.nadal, "", "k", false});
  shade_track(c, rs, ctx, x0, x1);
  return true;
}

// Instability: sliding rms of the band-passed Sum Y of every wheelset, with the limit.
bool chart_sum_y_rms(const engine::RunSafety& rs, const ChartContext& ctx, results::Chart& c) {
  if (!rs.instability_evaluated) return false;
  c.title = "instability (Sum Y)_rms, f0 " + config::format_number(std::round(rs.processing.hunting_frequency * 100) / 100) +
            " Hz: " + ctx.title_tail;
  c.xlabel = "track distance of the wheelset [m]";
  c.ylabel = "rms of Sum Y, band-passed f0 +- 2 Hz, 100 m windows [kN]";
  c.legend = "outside";
  double x0 = INFINITY, x1 = -INFINITY, lim = INFINITY;
  for (const auto& q : rs.quantities) {
    if (q.name != "sum_y_rms" || q.x.empty()) continue;
    results::ChartSeries s;
    s.label = q.item;
    s.x = q.x;
    for (double v : q.y) s.y.push_back(v / 1e3);
    decimate(s.x, s.y);
    s.style = q.x.size() > 150 ? "line" : "line+markers";
    c.series.push_back(std::move(s));
    x0 = std::min(x0, q.x.front()), x1 = std::max(x1, q.x.back());
    lim = std::min(lim, q.limit);
  }
  if (c.series.empty()) return false;
  char buf[96];
  std::snprintf(buf, sizeof buf, "limit (Sum Y)_2m,lim / 2 = %.3g kN", lim / 1e3);
  c.lines.push_back({lim / 1e3, buf, "tab:orange", false});
  shade_track(c, rs, ctx, x0, x1);
  return true;
}

// The contact audit of the recorded states into the summary, the CSV and the chart.
void audit_run(const engine::Scenario& sc, const ContactStateRecorder& rec, const ScenarioRunOptions& o,
               ScenarioRunResult& out) {
  const auto& m = sc.model;
  spdlog::info("contact audit: {} of the run's {} contact states, MIM grid {}, every registered model ({} threads)",
               std::min<std::size_t>(static_cast<std::size_t>(o.contact_audit.samples), rec.states().size()),
               rec.states().size(), o.contact_audit.mim_grid, o.contact_audit.threads);
  RunContactAuditOptions ao = o.contact_audit;
  ao.stop = o.stop;
  try {
    out.contact_audit = run_contact_audit(rec, m.coupling.options(), ao);
  } catch (const InterruptedError& e) {
    // The run's results stand; the audit is marked as stopped.
    out.summary.set("contact_audit", std::string("not completed: ") + e.what());
    if (!o.out_dir.empty()) out.summary.write_file(o.out_dir + "/summary.json");
    throw;
  }
  out.audited = true;
  const RunContactAudit& a = out.contact_audit;
  out.summary.set("contact_audit", contact_audit_json(a, m));
  if (!o.out_dir.empty()) {
    write_contact_audit_csv(a, m, o.out_dir + "/contact_audit.csv");
    const std::string tail = m.vehicle_name + ", " + config::format_number(std::round(m.speed.v0 * 3.6 * 10) / 10) +
                             " km/h, " + sc.name;
    results::draw(contact_audit_chart(a, tail), o.out_dir + "/contact_audit.png");
  }
  for (const auto& ma : a.result.models)
    spdlog::info("  {:<22} max {:>7.3f} %  p95 {:>7.3f} % of mu N  {:>10.3f} us/call (median){}{}", ma.model,
                 100 * ma.max_error, 100 * ma.p95_error, ma.median_cost_ns * 1e-3, ma.meets_tolerance ? "  meets" : "",
                 ma.model == a.run_model ? "  <- the run's model" : "");
  const auto& v = a.verdict;
  spdlog::info("contact audit: the run's model {} {} the tolerance {:.3g} % of mu N (max {:.3g} %); cheapest meeting "
               "it: {}; most accurate: {} ({:.3g} s)",
               a.run_model, v.run_meets ? "meets" : "misses", 100 * a.result.tolerance,
               100 * a.result.models[static_cast<std::size_t>(v.run_index)].max_error,
               v.cheapest_meeting.empty() ? "none" : v.cheapest_meeting, v.most_accurate, a.wall_seconds);
}

struct Evaluation {
  double seconds = 0.0, cpu_seconds = 0.0, chart_seconds = 0.0;
  bool pass = true;
};

// Running safety and curving of the recorded history into the summary, and the charts.
// `failure`: the message of a run stopped by a numerical failure ("" for a complete run).
Evaluation evaluate_history(const engine::Scenario& sc, const engine::SafetySettings& settings,
                            const engine::RunHistory& history, results::Json& summary, const std::string& out,
                            const std::string& failure = "") {
  Evaluation ev;
  const auto& m = sc.model;
  if (m.wheelsets.empty() || history.size() == 0) return ev;
  const auto t0 = std::chrono::steady_clock::now();
  const double c0 = thread_cpu_seconds();
  // Nadal's flange angle from the contact geometry of the first wheelset.
  const engine::FlangeAngle fa = engine::flange_angle(*m.wheelsets.front().geometry);
  std::vector<engine::TrackSection> sections = engine::single_section();
  ChartContext ctx;
  if (const auto* ti = dynamic_cast<const engine::TrackInput*>(m.track.get())) {
    sections = engine::track_sections(ti->track(), settings.zones);
    ctx.defects = engine::track_defects(ti->track());
  }
  engine::RunSafety safety =
      engine::evaluate_run_safety(history, sections, fa.angle, m.coupling.options().material.mu, settings);
  if (!failure.empty()) {
    // A run that stopped (wheel lift, derailment, numerical breakdown) is not a pass, whatever it showed before.
    safety.pass = false;
    safety.notes.push_back("the run stopped before its end (" + failure +
                           "): the quantities cover the run up to the failure and the verdict is FAIL");
  }
  const engine::CurvingOptions copt;
  const auto curves = engine::evaluate_curving(history, copt);
  ev.seconds = seconds_since(t0);
  ev.cpu_seconds = thread_cpu_seconds() - c0;
  ev.pass = safety.pass;
  summary.set("running_safety", safety_json(safety, fa));
  summary.set("curving", curving_json(curves, copt));
  const auto t1 = std::chrono::steady_clock::now();
  ctx.title_tail = m.vehicle_name + ", " + config::format_number(std::round(m.speed.v0 * 3.6 * 10) / 10) + " km/h, " +
                   m.coupling.options().tangential + " (mu " + config::format_number(m.coupling.options().material.mu) +
                   ")";
  results::Chart yq, rms;
  std::vector<std::pair<const results::Chart*, std::string>> charts;
  // Which charts the run has, and why one is missing (the same keys with or without an output folder).
  results::Json drawn = results::Json::object();
  const bool has_yq = chart_yq(history, safety, ctx, yq), has_rms = chart_sum_y_rms(safety, ctx, rms);
  const char* no_folder = "not written: no output folder";
  if (has_yq && !out.empty()) charts.emplace_back(&yq, out + "/yq.png");
  if (has_rms && !out.empty()) charts.emplace_back(&rms, out + "/sum_y_rms.png");
  drawn.set("yq.png", !has_yq ? results::Json("not drawn: no Y/Q samples")
                              : results::Json(out.empty() ? no_folder : "written"));
  drawn.set("sum_y_rms.png", !has_rms ? results::Json("not drawn: no (Sum Y)_rms window (the run covers less than "
                                                      "one 100 m window, or the instability evaluation was skipped: "
                                                      "see running_safety.notes)")
                                      : results::Json(out.empty() ? no_folder : "written"));
  summary.set("charts", drawn);
  results::draw_all(charts);
  ev.chart_seconds = seconds_since(t1);
  spdlog::info("running safety: {} (Nadal limit {:.3g} at {:.1f} deg, mu {:.2g}{}; f0 {:.3g} Hz)",
               safety.pass ? "pass" : "FAIL", safety.nadal, safety.flange_angle * kDeg, safety.mu,
               fa.fallback ? ", fallback flange angle" : "", safety.processing.hunting_frequency);
  for (const auto& [name, items] : by_name(safety)) {
    const engine::Quantity* w = worst_of(items);
    if (!w || std::isnan(w->limit)) continue;
    spdlog::info("  {:<14} {:<11} {:>10.4g} / limit {:<10.4g} {} at {:.1f} m, {:.2f} s ({})", w->symbol, w->item,
                 w->value, w->limit, w->pass ? "pass" : "FAIL", w->at_distance, w->at_time,
                 engine::zone_name(safety.sections[w->section].zone));
  }
  {  // Nadal: the wheel nearest its limit, and the largest instantaneous ratio beside it
    const engine::WheelSafety* worst = nullptr;
    std::string item;
    double inst = 0.0;
    for (const auto& w : safety.wheelsets)
      for (int side = 0; side < 2; ++side) {
        const engine::WheelSafety& s = w.wheel[side];
        const double v = s.nadal_on_2m ? s.max_yq_2m.value : s.max_abs_yq.value;
        if (!worst || v > (worst->nadal_on_2m ? worst->max_yq_2m.value : worst->max_abs_yq.value))
          worst = &s, item = engine::wheel_item(w.name, side);
        inst = std::max(inst, s.max_abs_yq.value);
      }
    if (worst) {
      const engine::Peak& p = worst->nadal_on_2m ? worst->max_yq_2m : worst->max_abs_yq;
      spdlog::info("  {:<14} {:<11} {:>10.4g} / limit {:<10.4g} {} at {:.1f} m, {:.2f} s (largest instantaneous "
                   "|Y/Q| {:.3g})",
                   worst->nadal_on_2m ? "Nadal (2 m)" : "Nadal (inst.)", item, p.value, safety.nadal,
                   worst->nadal_pass ? "pass" : "FAIL", p.distance, p.time, inst);
    }
  }
  for (const auto& n : safety.notes) spdlog::info("  note: {}", n);
  for (const auto& c : curves)
    for (const auto& w : c.wheelsets) {
      const int o = w.wheel[0].outer ? 0 : 1;
      const auto peak = [](const engine::Stat& s) { return std::max(std::fabs(s.min), std::fabs(s.max)); };
      spdlog::info("curve R {:.0f} m: {} angle of attack {:.2f} mrad, |Y/Q| max outer {:.3f} inner {:.3f}, "
                   "mean T-gamma outer {:.1f} N inner {:.1f} N", 1.0 / std::fabs(c.curvature), w.name,
                   w.angle_of_attack.mean * 1e3, peak(w.wheel[o].yq), peak(w.wheel[1 - o].yq),
                   w.wheel[o].Tgamma.mean, w.wheel[1 - o].Tgamma.mean);
    }
  return ev;
}

// The scenario reader's warnings (implausible inputs, no equilibrium at the start) as a JSON array.
results::Json scenario_warnings(const Scenario& sc) {
  results::Json warn = results::Json::array();
  for (const std::string& w : sc.warnings) warn.push(w);
  for (const std::string& w : sc.run_warnings) warn.push(w);
  return warn;
}

}  // namespace

ScenarioRunResult run_scenario(const Scenario& sc, const ScenarioRunOptions& o) {
  namespace fs = std::filesystem;
  // The evaluation's settings first: a bad running_safety section is bad input before any work.
  const SafetySettings settings = sc.running_safety ? load_safety_settings(*sc.running_safety) : SafetySettings{};
  for (const std::string& w : sc.run_warnings) spdlog::warn("{}", w);
  const bool files = !o.out_dir.empty();
  if (files) {
    std::error_code ec;
    fs::create_directories(o.out_dir, ec);
    if (ec) throw InputError(o.out_dir + ": cannot create the output folder (" + ec.message() + ")");
    // A previous run's files in the folder would be read as this run's when
    // this one writes fewer (a failure, a shorter run): they go first.
    for (const char* f : {"channels.csv", "summary.json", "yq.png", "yq.png.json", "sum_y_rms.png",
                          "sum_y_rms.png.json", "contact_audit.csv", "contact_audit.png", "contact_audit.png.json"}) {
      const fs::path p = fs::path(o.out_dir) / f;
      if (!fs::is_regular_file(fs::symlink_status(p, ec))) continue;  // links and devices are the user's
      if (!fs::remove(p, ec) || ec)
        throw InputError(p.string() + ": cannot remove the previous run's file (" + ec.message() + ")");
    }
  }
  const auto& m = sc.model;
  const bool audit = o.contact_audit.samples != 0;
  if (audit) {  // bad audit options are bad input before any work
    const auto& ca = o.contact_audit;
    if (ca.samples < kMinAuditSamples || ca.samples > kMaxAuditSamples)
      throw InputError("contact audit: samples " + std::to_string(ca.samples) + " outside [1, 10000]");
    if (!(ca.tolerance > 0.0 && ca.tolerance <= 1.0))
      throw InputError("contact audit: tolerance must lie in (0, 1] of mu N");
    if (ca.threads < 1 || ca.threads > 64) throw InputError("contact audit: threads outside [1, 64]");
    if (ca.mim_grid < 8 || ca.mim_grid > 400) throw InputError("contact audit: MIM grid outside [8, 400]");
    // Creep coefficients without a patch shape (conical wheels without a
    // patch or Hertz curvatures) leave nothing to audit: said before the run,
    // not after it (distributed contact makes its patches, a table carries
    // them at its reference load, or the coupling has one).
    const bool patches = m.coupling.options().patch_a > 0.0 ||
                         std::any_of(m.wheelsets.begin(), m.wheelsets.end(), [](const auto& w) {
                           if (w.geometry->distributed()) return true;
                           const ContactPointGeometry c = w.geometry->main_point(0.0);
                           return c.semi_a > 0.0 && c.N0 > 0.0;
                         });
    if (!patches)
      throw InputError("contact audit: the run's contact gives creep coefficients without a patch shape (conical "
                       "wheels without patch_a, patch_b), so its contact states have no patch to solve");
  }
  ContactStateRecorder contacts;
  spdlog::info("scenario '{}': vehicle '{}', {} states, {} wheelset model, {}, {:.4g} km/h", sc.name, m.vehicle_name,
               m.n_states, wheelset_model_name(m.wheelset_model), sc.integrator.method, m.speed.v0 * 3.6);
  for (const auto& ov : o.overrides) spdlog::info("  override {}", ov);

  ScenarioRunResult out;
  AccelerationOptions aopt;
  aopt.body_ends = settings.body_ends;
  RunHistory history(m, aopt);
  out.channel_names = channel_names(m);
  for (auto& c : history.channel_names()) out.channel_names.push_back(c);
  std::unique_ptr<results::CsvWriter> csv;
  if (files) csv = std::make_unique<results::CsvWriter>(o.out_dir + "/channels.csv", out.channel_names, false, 50);
  std::vector<double> row;
  const auto expected_rows = static_cast<std::size_t>(std::max(1L, std::lround(sc.duration / sc.output_interval))) + 1;
  history.reserve(expected_rows);
  if (o.keep_channels) out.channels.reserve(expected_rows * out.channel_names.size());
  results::Json& summary = out.summary;
  summary = results::Json::object();
  summary.set("scenario", sc.name);
  summary.set("scenario_file", sc.file);
  results::Json ov = results::Json::array();
  for (const auto& s : o.overrides) ov.push(s);
  summary.set("overrides", ov);
  summary.set("vehicle", m.vehicle_name);
  results::Json choices = results::Json::object();
  choices.set("wheelset_model", wheelset_model_name(m.wheelset_model));
  choices.set("geometry", sc.geometry_description);
  choices.set("equivalent_conicity_3mm", sc.equivalent_conicity_3mm);
  choices.set("tangential", m.coupling.describe());
  choices.set("track", m.track->describe());
  {  // rigid rails, or the flexible track (wheel_rail/track_flexibility.hpp): the parts that have states
    const TrackFlexibility& tf = m.track_flexibility;
    results::Json flex = results::Json::object();
    auto support = [](const TrackSupport& t) {
      results::Json j = results::Json::object();
      j.set("mass_kg", t.mass);
      j.set("stiffness_N_per_m", t.stiffness);
      j.set("damping_Ns_per_m", t.damping);
      if (t.bending_stiffness > 0.0) j.set("rail_bending_stiffness_Nm2", t.bending_stiffness);
      return j;
    };
    const std::array<int, 3> states = m.wheelsets.empty() ? std::array<int, 3>{-1, -1, -1}
                                                             : m.wheelsets.front().track_states();
    if (states[0] >= 0) flex.set("lateral", support(tf.lateral));
    if (states[1] >= 0) flex.set("vertical", support(tf.vertical));
    if (states[0] >= 0 || states[1] >= 0)
      choices.set("track_flexibility", flex);
    else
      choices.set("track_flexibility", "rigid rails");
  }
  choices.set("integrator", sc.integrator.method);
  choices.set("rtol", sc.integrator.rtol);
  choices.set("atol", sc.integrator.atol);
  choices.set("max_step", sc.integrator.max_step);
  choices.set("jacobian", sc.integrator.jacobian);
  choices.set("linear_solver", sc.integrator.linear_solver);
  choices.set("atol_contact_modes", sc.integrator.atol_contact_modes);
  if (sc.integrator.method == "cvode_bdf") choices.set("jacobian_max_age", sc.integrator.jacobian_max_age);
  summary.set("model_choices", choices);
  summary.set("speed_initial", m.speed.v0);
  summary.set("duration", sc.duration);
  summary.set("output_interval", sc.output_interval);
  summary.set("states", m.n_states);

  RunSummary& rs = out.run;
  try {
    rs = simulate(m, sc.integrator, sc.x0, sc.duration, sc.output_interval,
                  [&](double t, const Eigen::VectorXd& x, const Data& d) {
                    channel_row(m, t, x, d, row);
                    history.record(m, t, x, d);
                    history.last_channel_values(row);
                    if (csv) csv->row(row);
                    if (o.keep_channels) out.channels.insert(out.channels.end(), row.begin(), row.end());
                    if (audit) contacts.record(m, t, d);
                    ++out.rows;
                  },
                  o.stop);
  } catch (const InterruptedError& e) {
    // Stopped by the user: the rows so far are whole in channels.csv; nothing is judged.
    if (csv) csv->close();
    summary.set("status", "interrupted");
    summary.set("interrupted", std::string(e.what()) + "; channels.csv holds the run up to it");
    summary.set("warnings", scenario_warnings(sc));
    summary.set("running_safety", "not evaluated: the run was interrupted");
    if (!files) throw;
    summary.write_file(o.out_dir + "/summary.json");
    throw InterruptedError(std::string(e.what()) + "; " + o.out_dir + "/channels.csv holds the run up to it, " +
                           o.out_dir + "/summary.json says so");
  } catch (const DerailmentError& e) {
    // Physics: the running safety up to the derailment, failed because of it.
    if (csv) csv->close();
    summary.set("status", "derailed");
    summary.set("derailment", e.what());
    summary.set("warnings", scenario_warnings(sc));
    evaluate_history(sc, settings, history, summary, o.out_dir, e.what());  // up to the derailment: FAIL
    summary["running_safety"].set("pass", false);
    summary["running_safety"].set("derailment", e.what());
    spdlog::warn("{}", e.what());
    if (audit && !contacts.states().empty()) audit_run(sc, contacts, o, out);  // the states up to the derailment
    if (files) summary.write_file(o.out_dir + "/summary.json");
    out.derailed = true;
    out.derailment = e.what();
    return out;
  } catch (const NumericalError& e) {
    // Numerics, not physics: no running-safety verdict.
    if (csv) csv->close();
    summary.set("status", "failed");
    summary.set("error", e.what());
    summary.set("warnings", scenario_warnings(sc));  // e.g. no equilibrium at the start
    summary.set("running_safety", "not evaluated: the run failed numerically");
    if (files) summary.write_file(o.out_dir + "/summary.json");
    throw;
  }
  if (csv) csv->close();
  summary.set("status", "ok");
  summary.set("integrator", rs.integrator);
  results::Json st = results::Json::object();
  st.set("steps", rs.stats.steps);
  st.set("rhs_calls", rs.stats.rhs_calls);
  st.set("failed_steps", rs.stats.failed_steps);
  st.set("jacobian_evaluations", rs.stats.jacobian_evals);
  st.set("last_step", rs.stats.last_step);
  summary.set("integrator_statistics", st);
  summary.set("wall_time", rs.wall_time);
  summary.set("real_time_factor", rs.real_time_factor);
  summary.set("cpu_time", rs.cpu_time);
  summary.set("real_time_factor_cpu", rs.real_time_factor_cpu);
  // Lateral shifts: relative to the rails (what flange contact depends on), and absolute.
  results::Json maxy = results::Json::object(), maxa = results::Json::object();
  double overall = 0.0, overall_abs = 0.0;
  for (const auto& w : history.wheelsets) {
    double r = 0.0, ab = 0.0;
    for (double v : w.y) r = std::max(r, std::fabs(v));
    for (double v : w.y_absolute) ab = std::max(ab, std::fabs(v));
    maxy.set(w.name, r);
    maxa.set(w.name, ab);
    overall = std::max(overall, r);
    overall_abs = std::max(overall_abs, ab);
  }
  summary.set("max_lateral_shift", overall);
  summary.set("max_lateral_shift_definition", "relative to the rails [m] (wheelset lateral position minus the mean "
                                              "lateral irregularity of its rails)");
  summary.set("max_lateral_shift_per_wheelset", maxy);
  summary.set("max_lateral_shift_absolute", overall_abs);
  summary.set("max_lateral_shift_absolute_definition", "relative to the design centre line of the track [m]");
  summary.set("max_lateral_shift_absolute_per_wheelset", maxa);
  results::Json warn = scenario_warnings(sc);
  for (const std::string& w : wheel_load_warnings(history)) {  // legal but implausible results
    spdlog::warn("{}", w);
    warn.push(w);
  }
  if (rs.invalid_contact_calls > 0)
    warn.push("contact model used outside its validity domain in " + std::to_string(rs.invalid_contact_calls) +
              " evaluations (first: " + rs.first_invalid_reason + ")");
  if (m.wheelset_model == WheelsetModel::lateral && overall > 0.006)
    warn.push("lateral wheelset model with lateral shifts relative to the rails above 6 mm: flange contact with "
              "quasi-static loads");
  const Evaluation ev = evaluate_history(sc, settings, history, summary, o.out_dir);
  summary.set("warnings", warn);
  results::Json et = results::Json::object();
  et.set("evaluation_wall_time", ev.seconds);
  et.set("evaluation_share_of_run", rs.wall_time > 0 ? ev.seconds / rs.wall_time : 0.0);
  et.set("evaluation_cpu_time", ev.cpu_seconds);
  et.set("evaluation_share_of_run_cpu", rs.cpu_time > 0 ? ev.cpu_seconds / rs.cpu_time : 0.0);
  et.set("charts_wall_time", ev.chart_seconds);
  summary.set("post_processing", et);
  if (audit) {
    // The run's summary first (its verdict stands whatever becomes of the
    // audit, which may take minutes): an interrupted audit leaves it, marked.
    if (files) {
      results::Json pending = results::Json::object();
      pending.set("status", "running (interrupted if this remains: the run's results above stand)");
      summary.set("contact_audit", pending);
      summary.write_file(o.out_dir + "/summary.json");
    }
    audit_run(sc, contacts, o, out);
  }
  if (files) summary.write_file(o.out_dir + "/summary.json");
  spdlog::info("done: {:.3g} s simulated in {:.3g} s wall ({:.3g}x real time; {:.3g}x on CPU time), {} steps, {} rhs "
               "calls, max |y| relative to the rails {:.3g} mm (absolute {:.3g} mm)",
               sc.duration, rs.wall_time, rs.real_time_factor, rs.real_time_factor_cpu, rs.stats.steps,
               rs.stats.rhs_calls, overall * 1e3, overall_abs * 1e3);
  spdlog::info("evaluation {:.3g} s wall, {:.3g} s CPU ({:.2g} % of the run's wall time, {:.2g} % of its CPU time), "
               "charts {:.3g} s",
               ev.seconds, ev.cpu_seconds, rs.wall_time > 0 ? 100.0 * ev.seconds / rs.wall_time : 0.0,
               rs.cpu_time > 0 ? 100.0 * ev.cpu_seconds / rs.cpu_time : 0.0, ev.chart_seconds);
  return out;
}

}  // namespace railsim::engine
