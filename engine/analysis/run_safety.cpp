// Running safety of a recorded run; see run_safety.hpp.
#include "engine/analysis/run_safety.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>

#include "results/iir_filter.hpp"
#include "results/sliding_window.hpp"
#include "results/spectrum.hpp"

namespace railsim::engine {

namespace {
constexpr double kDeg = 3.14159265358979323846 / 180.0;

bool strictly_increasing(const std::vector<double>& v) {
  for (std::size_t i = 1; i < v.size(); ++i)
    if (!(v[i] > v[i - 1])) return false;
  return v.size() >= 2;
}

std::string fmt(const char* f, double a, double b = 0.0, double c = 0.0) {
  char buf[256];
  std::snprintf(buf, sizeof buf, f, a, b, c);
  return buf;
}

bool is_curve(const TrackSection& s) {
  return s.zone == TrackZone::large_radius_curve || s.zone == TrackZone::small_radius_curve ||
         s.zone == TrackZone::very_small_radius_curve;
}

// A filter that may not be applicable at the run's sampling.
struct Filter {
  std::optional<results::IirFilter> f;
  std::vector<double> apply(const std::vector<double>& x) const { return f ? results::filtfilt(*f, x) : x; }
  std::string step(const std::string& what) const {
    return f ? what + ": " + f->description + ", forward-backward (zero phase)" : what + ": not applied";
  }
};

struct Windowed {
  std::vector<double> x, t, y;
};

Windowed sliding(bool rms, const std::vector<double>& dist, const std::vector<double>& time,
                 const std::vector<double>& y, double window, double step) {
  auto w = rms ? results::sliding_rms(dist, y, window, step) : results::sliding_mean(dist, y, window, step);
  Windowed out;
  out.t.reserve(w.centre.size());
  // Centres increase: walk the distance series once instead of a search per centre.
  std::size_t j = 1;
  for (double c : w.centre) {
    while (j + 1 < dist.size() && dist[j] < c) ++j;
    const double span = dist[j] - dist[j - 1];
    const double u = span > 0.0 ? std::clamp((c - dist[j - 1]) / span, 0.0, 1.0) : 0.0;
    out.t.push_back(time[j - 1] + u * (time[j] - time[j - 1]));
  }
  out.x = std::move(w.centre);
  out.y = std::move(w.value);
  return out;
}

std::vector<double> ratio(const std::vector<double>& y, const std::vector<double>& q) {
  std::vector<double> r(y.size());
  for (std::size_t i = 0; i < y.size(); ++i) r[i] = q[i] > 0.0 ? y[i] / q[i] : 0.0;
  return r;
}

}  // namespace

FlangeAngle flange_angle(const ContactGeometry& g, double fallback, double min_flank, int samples) {
  FlangeAngle f;
  const double lim = g.max_shift() * (1.0 - 1e-9);
  WheelGeometry wg;
  for (int k = 0; k < samples; ++k) {
    const double s = -lim + 2.0 * lim * k / std::max(1, samples - 1);
    g.evaluate(s, 0.0, wg);
    for (int p = 0; p < wg.n; ++p) f.geometry_max = std::max(f.geometry_max, wg.p[p].contact_angle);
  }
  char buf[256];
  if (f.geometry_max >= min_flank) {
    f.angle = f.geometry_max;
    std::snprintf(buf, sizeof buf, "largest contact angle of the contact geometry over +-%.4g mm: %.2f deg",
                  g.max_shift() * 1e3, f.angle / kDeg);
  } else {
    f.angle = fallback;
    f.fallback = true;
    std::snprintf(buf, sizeof buf,
                  "fallback %.1f deg (S1002 maximum flank angle): the contact geometry has no flange flank "
                  "(largest contact angle %.2f deg over +-%.4g mm)",
                  fallback / kDeg, f.geometry_max / kDeg, g.max_shift() * 1e3);
  }
  f.source = buf;
  return f;
}

std::string wheel_item(const std::string& wheelset, int side) { return wheelset + (side == 0 ? " left" : " right"); }

const Quantity* RunSafety::find(const std::string& name, const std::string& item) const {
  for (const auto& q : quantities)
    if (q.name == name && q.item == item) return &q;
  return nullptr;
}

RunSafety evaluate_run_safety(const RunHistory& h, double flange_angle_rad, double mu, const SafetySettings& s) {
  return evaluate_run_safety(h, single_section(), flange_angle_rad, mu, s);
}

RunSafety evaluate_run_safety(const RunHistory& h, const std::vector<TrackSection>& sections, double flange_angle_rad,
                              double mu, const SafetySettings& set) {
  if (h.size() == 0) throw std::invalid_argument("evaluate_run_safety: empty run history");
  if (sections.empty()) throw std::invalid_argument("evaluate_run_safety: no track sections");
  RunSafety out;
  out.flange_angle = flange_angle_rad;
  out.mu = mu;
  out.nadal = nadal_limit(flange_angle_rad, mu);
  out.settings = set;
  out.sections = sections;
  out.k1 = track_shift_factor(set.category);
  for (double v : h.speed) out.max_speed = std::max(out.max_speed, v);
  const std::size_t n = h.size();
  const std::vector<double>& time = h.time;

  // Nadal (instantaneous, unfiltered) and lateral shifts need no windows.
  std::vector<std::vector<double>> dist(h.wheelsets.size(), std::vector<double>(n));
  for (std::size_t w = 0; w < h.wheelsets.size(); ++w) {
    const WheelsetHistory& wh = h.wheelsets[w];
    WheelsetSafety ws;
    ws.name = wh.name;
    ws.static_wheel_load = wh.static_wheel_load;
    for (std::size_t i = 0; i < n; ++i) dist[w][i] = h.wheelset_distance(w, i);
    for (int side = 0; side < 2; ++side) {
      const WheelHistory& wl = wh.wheel[side];
      WheelSafety& s = ws.wheel[side];
      double stretch_start = 0.0;
      bool above = false;
      for (std::size_t i = 0; i < n; ++i) {
        const double yq = wl.Q[i] > 0.0 ? std::fabs(wl.Y[i] / wl.Q[i]) : 0.0;
        if (yq > s.max_abs_yq.value) s.max_abs_yq = {yq, dist[w][i], time[i]};
        if (yq > out.nadal && !above) stretch_start = dist[w][i];
        above = yq > out.nadal;
        if (above) s.longest_exceedance = std::max(s.longest_exceedance, std::fabs(dist[w][i] - stretch_start));
      }
      s.nadal_pass = s.max_abs_yq.value <= out.nadal;  // until the 2 m means are known (below)
    }
    for (std::size_t i = 0; i < n && i < wh.y.size(); ++i) {
      if (std::fabs(wh.y[i]) > ws.max_shift.value) ws.max_shift = {std::fabs(wh.y[i]), dist[w][i], time[i]};
      if (i < wh.y_absolute.size() && std::fabs(wh.y_absolute[i]) > ws.max_shift_absolute.value)
        ws.max_shift_absolute = {std::fabs(wh.y_absolute[i]), dist[w][i], time[i]};
    }
    ws.pass = ws.wheel[0].nadal_pass && ws.wheel[1].nadal_pass;
    out.wheelsets.push_back(std::move(ws));
  }

  out.en14363_evaluated = strictly_increasing(h.distance) && h.distance.back() - h.distance.front() >= set.window;
  if (out.en14363_evaluated) {  // Nadal on the 2 m sliding mean of the unfiltered |Y/Q| (see the header)
    for (std::size_t w = 0; w < h.wheelsets.size(); ++w) {
      WheelsetSafety& ws = out.wheelsets[w];
      for (int side = 0; side < 2; ++side) {
        const WheelHistory& wl = h.wheelsets[w].wheel[side];
        std::vector<double> yq(n);
        for (std::size_t i = 0; i < n; ++i) yq[i] = wl.Q[i] > 0.0 ? std::fabs(wl.Y[i] / wl.Q[i]) : 0.0;
        const Windowed m = sliding(false, dist[w], time, yq, set.window, set.step);
        WheelSafety& s = ws.wheel[side];
        for (std::size_t j = 0; j < m.y.size(); ++j)
          if (m.y[j] > s.max_yq_2m.value) s.max_yq_2m = {m.y[j], m.x[j], m.t[j]};
        s.nadal_on_2m = true;
        s.nadal_pass = s.max_yq_2m.value <= out.nadal;
        if (s.max_abs_yq.value > out.nadal && s.nadal_pass)
          out.notes.push_back(wheel_item(ws.name, side) +
                              fmt(": instantaneous |Y/Q| %.3g above Nadal's %.3g at %.5g m", s.max_abs_yq.value,
                                  out.nadal, s.max_abs_yq.distance) +
                              fmt("; longest stretch above it %.2f m, largest 2 m mean %.3g: an impact, not a climb",
                                  s.longest_exceedance, s.max_yq_2m.value));
      }
      ws.pass = ws.wheel[0].nadal_pass && ws.wheel[1].nadal_pass;
    }
  } else {
    out.notes.push_back("Nadal judged on the instantaneous |Y/Q| peak: no 2 m windows (the vehicle runs less than " +
                        fmt("%.3g", set.window) + " m or does not advance)");
  }
  if (!out.en14363_evaluated) {
    out.notes.push_back("EN 14363 quantities not evaluated: the vehicle runs less than " +
                        fmt("%.3g", set.window) + " m (or does not advance)");
    out.instability_evaluated = false;
    for (const auto& ws : out.wheelsets) out.pass = out.pass && ws.pass;
    return out;
  }
  const double run_length = h.distance.back() - h.distance.front();
  out.instability_evaluated = run_length >= set.rms_window;
  if (!out.instability_evaluated)
    out.notes.push_back("instability criteria not evaluated: the run covers " + fmt("%.4g", run_length) +
                        " m, less than the " + fmt("%.4g", set.rms_window) + " m rms window");

  // Sampling and filters.
  SafetyProcessing& pr = out.processing;
  try {
    pr.sample_rate = results::uniform_sample_rate(time);
  } catch (const std::invalid_argument& e) {
    pr.sample_rate = 0.0;
    out.notes.push_back(std::string("filters not applied: ") + e.what());
  }
  const double fs = pr.sample_rate;
  auto fits = [&](double f_high) { return fs > 0.0 && f_high < 0.45 * fs; };
  Filter lp, acc, hunt;
  if (!(set.force_lowpass > 0.0)) {
    pr.force_filter = "not applied: switched off (force_lowpass = 0)";
    out.notes.push_back("wheel-rail forces not low-passed: switched off");
  } else if (fits(set.force_lowpass)) {
    lp.f = results::butterworth_lowpass(set.lowpass_order, set.force_lowpass, fs);
    pr.force_filter = lp.f->description;
    pr.force_filter_applied = true;
  } else {
    pr.force_filter = fmt("not applied: %.4g Hz low-pass needs a sample rate above %.4g Hz (run: %.4g Hz)",
                          set.force_lowpass, set.force_lowpass / 0.45, fs);
    out.notes.push_back("wheel-rail forces not low-passed: " + pr.force_filter);
  }
  if (fits(set.accel_band_high)) {
    acc.f = results::butterworth_bandpass(set.bandpass_order, set.accel_band_low, set.accel_band_high, fs);
    pr.acceleration_filter = acc.f->description;
    pr.acceleration_filter_applied = true;
  } else {
    pr.acceleration_filter = fmt("not applied: %.4g..%.4g Hz band-pass needs a higher sample rate (run: %.4g Hz)",
                                 set.accel_band_low, set.accel_band_high, fs);
  }

  // Hunting frequency f0.
  if (set.hunting_frequency > 0.0) {
    pr.hunting_frequency = set.hunting_frequency;
    pr.hunting_frequency_source = "given (running_safety.hunting_frequency_hz)";
  } else if (fs > 0.0 && n >= 8) {
    double best_power = -1.0;
    std::string from;
    results::SpectralPeak peak;
    const double f_top = std::min(set.hunting_search_max, 0.45 * fs - set.hunting_half_band);
    if (f_top > set.hunting_search_min) {
      // Band-limit first, so quasi-static Sum Y in curves does not leak into the lowest bins.
      const auto search = results::butterworth_bandpass(set.bandpass_order, set.hunting_search_min, f_top, fs);
      for (std::size_t w = 0; w < h.wheelsets.size(); ++w) {
        std::vector<double> sy(n);
        for (std::size_t i = 0; i < n; ++i) sy[i] = h.wheelsets[w].wheel[0].Y[i] + h.wheelsets[w].wheel[1].Y[i];
        const auto pk = results::dominant_frequency(results::filtfilt(search, sy), fs, set.hunting_search_min, f_top);
        if (pk.power > best_power)
          best_power = pk.power, pr.hunting_frequency = pk.frequency, from = h.wheelsets[w].name, peak = pk;
      }
      if (peak.frequency < set.hunting_search_min + 2.0 * peak.resolution || peak.frequency > f_top - 2.0 * peak.resolution)
        out.notes.push_back(fmt("no oscillation peak inside %.3g..%.3g Hz: f0 = %.3g Hz is at the edge of the search "
                                "range (no hunting; the instability rms is evaluated around it anyway)",
                                set.hunting_search_min, f_top, peak.frequency));
      pr.hunting_frequency_source = fmt("dominant frequency of Sum Y band-passed %.3g..%.3g Hz (periodogram, Hann "
                                        "window, FFTW)",
                                        set.hunting_search_min, f_top) +
                                    ", strongest of all wheelsets: " + from;
    } else {
      pr.hunting_frequency_source = "not found: sample rate too low to search";
    }
  }
  const double f_lo = std::max(0.3, pr.hunting_frequency - set.hunting_half_band);
  const double f_hi = pr.hunting_frequency + set.hunting_half_band;
  if (pr.hunting_frequency > 0.0 && fits(f_hi)) {
    hunt.f = results::butterworth_bandpass(set.bandpass_order, f_lo, f_hi, fs);
    pr.instability_filter = hunt.f->description;
    pr.instability_filter_applied = true;
  } else {
    pr.instability_filter = "not applied: no hunting frequency or sample rate too low";
    if (out.instability_evaluated) out.notes.push_back("instability criteria not evaluated: " + pr.instability_filter);
    out.instability_evaluated = false;
  }

  const std::string lp_step = lp.step("low-pass");
  const std::string win_step = fmt("sliding mean over %.3g m, centres every %.3g m", set.window, set.step);
  const std::string rms_step = fmt("sliding rms over %.4g m, centres every %.3g m", set.rms_window, set.rms_step);
  auto spec = [&](const std::string& name, const std::string& symbol, const std::string& item,
                  const std::string& kind, const std::string& unit, Statistic st, std::vector<std::string> steps) {
    QuantitySpec q;
    q.name = name, q.symbol = symbol, q.item = item, q.kind = kind, q.unit = unit, q.statistic = st;
    q.processing = std::move(steps);
    q.p_low = set.percentile_low, q.p_high = set.percentile_high, q.p_mid = set.percentile_qst;
    return q;
  };

  // Wheels and wheelsets.
  for (std::size_t w = 0; w < h.wheelsets.size(); ++w) {
    const WheelsetHistory& wh = h.wheelsets[w];
    const double Q0 = wh.static_wheel_load;
    const std::vector<double>& d = dist[w];
    std::vector<double> Yf[2], Qf[2];
    for (int side = 0; side < 2; ++side) {
      Yf[side] = lp.apply(wh.wheel[side].Y);
      Qf[side] = lp.apply(wh.wheel[side].Q);
      const std::string item = wheel_item(wh.name, side);
      const std::vector<double> yq = ratio(Yf[side], Qf[side]);
      {
        auto q = spec("yq_2m", "(Y/Q)_2m", item, "wheel", "-", Statistic::two_sided,
                      {lp_step + " of Y and Q", "Y/Q", win_step});
        q.limit = [](const TrackSection& sec) { return yq_2m_limit(sec.radius); };
        q.limit_source = "EN 14363: 0.8 for R >= 250 m (and straight track), 1.2 for R < 250 m";
        q.keep_series = true;  // charted
        Windowed m = sliding(false, d, time, yq, set.window, set.step);
        out.quantities.push_back(assess(q, m.x, m.t, m.y, sections));
      }
      if (Q0 > 0.0) {
        auto q = spec("q_max", "Q_max", item, "wheel", "N", Statistic::upper, {lp_step + " of Q"});
        const double lim = qmax_limit(Q0, out.max_speed);
        q.limit = [lim](const TrackSection&) { return lim; };
        q.limit_source = fmt("UIC 518 / EN 14363 track loading: min(90 kN + Q0, speed cap) = %.4g kN "
                             "(Q0 %.4g kN, max speed %.4g km/h)",
                             lim / 1e3, Q0 / 1e3, out.max_speed * 3.6);
        out.quantities.push_back(assess(q, d, time, Qf[side], sections));
        auto u = spec("wheel_unloading", "dQ/Q0", item, "wheel", "-", Statistic::upper,
                      {lp_step + " of Q", "dQ/Q0 = (Q0 - Q)/Q0"});
        u.limit = [](const TrackSection&) { return kWheelUnloadingLimit; };
        u.limit_source = "twist-test limit dQ/Q0 <= 0.6 (EN 14363), applied to the run as a screening value";
        std::vector<double> dq(n);
        for (std::size_t i = 0; i < n; ++i) dq[i] = (Q0 - Qf[side][i]) / Q0;
        out.quantities.push_back(assess(u, d, time, dq, sections));
      }
      {
        auto q = spec("y_qst", "Y_qst", item, "wheel", "N", Statistic::median, {lp_step + " of Y"});
        q.use_section = is_curve;
        q.limit = [](const TrackSection&) { return kYqstLimit; };
        q.limit_source = "EN 14363 track loading: Y_qst <= 60 kN";
        out.quantities.push_back(assess(q, d, time, Yf[side], sections));
        auto r = spec("q_qst", "Q_qst", item, "wheel", "N", Statistic::median, {lp_step + " of Q"});
        r.use_section = is_curve;
        r.limit = [](const TrackSection&) { return kQqstLimit; };
        r.limit_source = "EN 14363 track loading: Q_qst <= 145 kN";
        out.quantities.push_back(assess(r, d, time, Qf[side], sections));
        auto t = spec("yq_qst", "(Y/Q)_qst", item, "wheel", "-", Statistic::median, {lp_step + " of Y and Q", "Y/Q"});
        t.use_section = is_curve;
        out.quantities.push_back(assess(t, d, time, yq, sections));
      }
    }
    std::vector<double> sy(n);
    for (std::size_t i = 0; i < n; ++i) sy[i] = Yf[0][i] + Yf[1][i];
    if (Q0 > 0.0) {
      const double lim = prudhomme_limit(2.0 * Q0, out.k1);
      auto q = spec("sum_y_2m", "(Sum Y)_2m", wh.name, "wheelset", "N", Statistic::two_sided,
                    {lp_step + " of Y", "Sum Y = Y_left + Y_right", win_step});
      q.limit = [lim](const TrackSection&) { return lim; };
      q.limit_source = fmt("Prud'homme / EN 14363: k1 (10 + 2 Q0/3) kN = %.4g kN (k1 = %.3g, Q0 = %.4g kN)", lim / 1e3,
                           out.k1, Q0 / 1e3) +
                       " (" + vehicle_category_name(set.category) + ")";
      Windowed m = sliding(false, d, time, sy, set.window, set.step);
      out.quantities.push_back(assess(q, m.x, m.t, m.y, sections));
      if (out.instability_evaluated) {
        std::vector<double> raw(n);
        for (std::size_t i = 0; i < n; ++i) raw[i] = wh.wheel[0].Y[i] + wh.wheel[1].Y[i];
        auto r = spec("sum_y_rms", "(Sum Y)_rms", wh.name, "wheelset", "N", Statistic::maximum,
                      {"Sum Y = Y_left + Y_right (unfiltered)",
                       hunt.step(fmt("band-pass f0 +- %.3g Hz (f0 = %.3g Hz)", set.hunting_half_band,
                                     pr.hunting_frequency)),
                       rms_step});
        const double ilim = instability_sum_y_limit(2.0 * Q0, out.k1);
        r.limit = [ilim](const TrackSection&) { return ilim; };
        r.limit_source = fmt("EN 14363 instability, normal method: (Sum Y)_2m,lim / 2 = %.4g kN", ilim / 1e3);
        r.keep_series = true;  // charted
        Windowed m2 = sliding(true, d, time, hunt.apply(raw), set.rms_window, set.rms_step);
        out.quantities.push_back(assess(r, m2.x, m2.t, m2.y, sections));
      }
    }
  }

  // Running gear: simplified method of the stability assessment.
  if (out.instability_evaluated) {
    for (const auto& g : h.bogies) {
      const double lim = bogie_frame_acceleration_limit(g.mass);
      for (const auto& p : h.points) {
        if (p.role != PointRole::bogie_frame_above_wheelset || p.group != g.name || p.ay.size() != n) continue;
        std::vector<double> d(n);
        for (std::size_t i = 0; i < n; ++i) d[i] = h.distance[i] + p.offset;
        auto q = spec("bogie_ay_rms", "y''+_rms", p.name, "bogie frame", "m/s^2", Statistic::maximum,
                      {"lateral acceleration of the bogie frame above the wheelset (accelerometer reading)",
                       hunt.step(fmt("band-pass f0 +- %.3g Hz (f0 = %.3g Hz)", set.hunting_half_band,
                                     pr.hunting_frequency)),
                       rms_step});
        q.limit = [lim](const TrackSection&) { return lim; };
        q.limit_source = fmt("EN 14363 instability, simplified method: (12 - m_b/5)/2 = %.3g m/s^2 (m_b = %.3g t, "
                             "frame and wheelsets; constants [U])",
                             lim, g.mass / 1e3);
        Windowed m = sliding(true, d, time, hunt.apply(p.ay), set.rms_window, set.rms_step);
        out.quantities.push_back(assess(q, m.x, m.t, m.y, sections));
      }
    }
  }

  // Car-body accelerations (ride characteristics; reported without limits).
  for (const auto& p : h.points) {
    if (p.role == PointRole::bogie_frame_above_wheelset || p.ay.size() != n) continue;
    std::vector<double> d(n);
    for (std::size_t i = 0; i < n; ++i) d[i] = h.distance[i] + p.offset;
    const std::string where = std::string(point_role_name(p.role));
    const std::string bp = acc.step(fmt("band-pass %.3g..%.3g Hz", set.accel_band_low, set.accel_band_high));
    const std::vector<double> ay = acc.apply(p.ay), az = acc.apply(p.az);
    out.quantities.push_back(assess(spec("car_ay", "y''*", p.name, "car body", "m/s^2", Statistic::two_sided,
                                         {"lateral acceleration, " + where + " (accelerometer reading)", bp}),
                                    d, time, ay, sections));
    out.quantities.push_back(assess(spec("car_az", "z''*", p.name, "car body", "m/s^2", Statistic::two_sided,
                                         {"vertical acceleration, " + where + " (static g removed)", bp}),
                                    d, time, az, sections));
    out.quantities.push_back(assess(spec("car_ay_rms", "s y''*", p.name, "car body", "m/s^2", Statistic::rms,
                                         {"lateral acceleration, " + where, bp}),
                                    d, time, ay, sections));
    out.quantities.push_back(assess(spec("car_az_rms", "s z''*", p.name, "car body", "m/s^2", Statistic::rms,
                                         {"vertical acceleration, " + where, bp}),
                                    d, time, az, sections));
    auto qst = spec("car_ay_qst", "y''*_qst", p.name, "car body", "m/s^2", Statistic::median,
                    {"lateral acceleration, " + where, lp_step});
    qst.use_section = is_curve;
    out.quantities.push_back(assess(qst, d, time, lp.apply(p.ay), sections));
  }

  // Pass/fail: Nadal and every limited quantity.
  for (auto& ws : out.wheelsets) {
    for (const auto& q : out.quantities)
      if (q.item == ws.name || q.item == wheel_item(ws.name, 0) || q.item == wheel_item(ws.name, 1))
        ws.pass = ws.pass && q.pass;
    out.pass = out.pass && ws.pass;
  }
  for (const auto& q : out.quantities) out.pass = out.pass && q.pass;
  return out;
}

}  // namespace railsim::engine
