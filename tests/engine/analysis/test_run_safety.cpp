// Running safety of recorded runs (engine/analysis/run_safety.hpp) on
// synthetic histories with hand-computed values: Nadal, the 2 m sliding means
// and their 0.15 / 99.85 % percentiles, the 20 Hz low-pass (attenuation of a
// 40 Hz component), the quasi-static medians in curves, the zone-dependent
// (Y/Q)_2m limit, the instability criteria (band-pass around the detected
// hunting frequency, 100 m sliding rms) on wheelsets and bogie frames, the
// car-body accelerations (band-pass 0.4..10 Hz percentiles and rms); and the
// curve-body statistics of curving.hpp.
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>

#include "engine/analysis/curving.hpp"
#include "engine/analysis/run_safety.hpp"
#include "engine/wheel_rail/conical_geometry.hpp"
#include "engine/wheel_rail/geometry_table.hpp"
#include "test_support.hpp"

using namespace railsim::engine;

namespace {
constexpr double kDeg = M_PI / 180.0;

// Single-pass |H|^2 of the bilinear Butterworth designs (results/iir_filter.hpp),
// which filtfilt applies as the gain.
double lowpass_h2(double f, double fc, double fs, int n) {
  return 1.0 / (1.0 + std::pow(std::tan(M_PI * f / fs) / std::tan(M_PI * fc / fs), 2 * n));
}
double bandpass_h2(double f, double f1, double f2, double fs, int n) {
  const double w = 2 * fs * std::tan(M_PI * f / fs), w1 = 2 * fs * std::tan(M_PI * f1 / fs),
               w2 = 2 * fs * std::tan(M_PI * f2 / fs);
  return 1.0 / (1.0 + std::pow((w * w - w1 * w2) / (w * (w2 - w1)), 2 * n));
}

// A history of one wheelset at `offset` (track distance = vehicle distance + offset),
// vehicle at speed V from distance 0, n samples every dt; forces from `fill(t, x, Yl, Ql, Yr, Qr)`.
using Fill = std::function<void(double t, double x, double& Yl, double& Ql, double& Yr, double& Qr)>;
RunHistory history(int n, double dt, double V, double offset, const Fill& fill, double Q0 = 50e3) {
  RunHistory h;
  h.vehicle = "synthetic";
  h.total_mass = 10000;
  WheelsetHistory w;
  w.name = "ws1";
  w.offset = offset;
  w.static_wheel_load = Q0;
  h.wheelsets.push_back(w);
  auto& ws = h.wheelsets[0];
  for (int i = 0; i < n; ++i) {
    const double t = dt * i, s = V * t;
    h.time.push_back(t);
    h.distance.push_back(s);
    h.speed.push_back(V);
    for (auto* v : {&ws.y, &ws.y_absolute, &ws.yaw, &ws.curvature, &ws.curvature_rate, &ws.cant}) v->push_back(0.0);
    double yl = 0, ql = Q0, yr = 0, qr = Q0;
    fill(t, s + offset, yl, ql, yr, qr);
    ws.wheel[0].Y.push_back(yl);
    ws.wheel[0].Q.push_back(ql);
    ws.wheel[1].Y.push_back(yr);
    ws.wheel[1].Q.push_back(qr);
    for (auto& wl : ws.wheel)
      for (auto* v : {&wl.Fx, &wl.Fy, &wl.Mz, &wl.xi, &wl.eta, &wl.spin, &wl.Tgamma}) v->push_back(0.0);
  }
  return h;
}

// The synthetic run of the original evaluation: one wheelset at +1 m, 10 m/s, samples every
// 0.01 s (0.1 m), 1.0 .. 101.0 m. Loads 50 kN, Y = 0, then:
//  left wheel:  Y = 30 kN on the wheelset distances [40, 41] m (a 1 m plateau);
//               Q = 25 kN at the single sample 80 m (unloading 0.5);
//  right wheel: Y = 80 kN at the single sample 70 m (|Y/Q| = 1.6 > Nadal).
RunHistory plateau_history() {
  return history(1001, 0.01, 10.0, 1.0, [](double, double x, double& yl, double& ql, double& yr, double&) {
    if (x >= 40.0 - 1e-9 && x <= 41.0 + 1e-9) yl = 30e3;
    if (std::abs(x - 80.0) < 1e-6) ql = 25e3;
    if (std::abs(x - 70.0) < 1e-6) yr = 80e3;
  });
}

std::vector<TrackSection> straight_then_curve(double at, double radius) {
  std::vector<TrackSection> s(2);
  s[0].end = at;
  s[1].start = at;
  s[1].radius = radius;
  s[1].kind = "circular";
  s[1].zone = zone_of_radius(radius);
  return s;
}

const Quantity& get(const RunSafety& r, const std::string& name, const std::string& item) {
  const Quantity* q = r.find(name, item);
  REQUIRE(q != nullptr);
  return *q;
}
}  // namespace

TEST_CASE("run safety of a synthetic history: Nadal, 2 m means, percentiles, where and when", "[safety][run]") {
  const RunHistory h = plateau_history();
  SafetySettings set;
  set.force_lowpass = 0.0;  // the hand values below are of the unfiltered forces
  const RunSafety r = evaluate_run_safety(h, 70.0 * kDeg, 0.3, set);
  // Nadal (tan 70 - 0.3) / (1 + 0.3 tan 70) = 1.342 (physics-reference §9.1 table).
  CHECK(r.nadal == Approx(1.342).margin(5e-4));
  REQUIRE(r.en14363_evaluated);
  REQUIRE(r.wheelsets.size() == 1);
  const WheelsetSafety& w = r.wheelsets[0];
  // Left: instantaneous |Y/Q| = 30/50 = 0.6 first reached at 40 m (t = 3.9 s): below Nadal.
  CHECK(w.wheel[0].max_abs_yq.value == Approx(0.6));
  CHECK(w.wheel[0].max_abs_yq.distance == Approx(40.0).margin(1e-9));
  CHECK(w.wheel[0].max_abs_yq.time == Approx(3.9).margin(1e-9));
  CHECK(w.wheel[0].nadal_pass);
  // (Y/Q)_2m: 197 windows (centres 2.0 .. 100.0 m). The linearly interpolated plateau (0.6 on
  // 40..41 m, ramps over 0.1 m) gives the windows centred at 39.0 .. 42.0 m the means
  // 0.015, 0.165, 0.315, 0.33, 0.315, 0.165, 0.015; all others are 0. F2 (99.85 %) sits at
  // position 0.9985 x 196 = 195.706 of the sorted means: 0.315 + 0.706 x 0.015 = 0.32559.
  const Quantity& yql = get(r, "yq_2m", "ws1 left");
  CHECK(yql.value == Approx(0.32559).epsilon(1e-9));
  CHECK(yql.sections[0].p_high == Approx(0.32559).epsilon(1e-9));
  CHECK(yql.sections[0].p_low == Approx(0.0).margin(1e-12));
  CHECK(yql.sections[0].samples == 197);
  CHECK(yql.sections[0].peak == Approx(0.33).epsilon(1e-9));  // the maximum window, at 40.5 m, t = 3.95 s
  CHECK(yql.at_distance == Approx(40.5).margin(1e-9));
  CHECK(yql.at_time == Approx(3.95).margin(1e-9));
  CHECK(yql.limit == 0.8);
  CHECK(yql.margin == Approx(0.8 - 0.32559).epsilon(1e-9));
  CHECK(yql.pass);
  // Right: one sample of Y/Q = 1.6 at 70 m (t = 6.9 s), above Nadal for one sample (0 m);
  // its 2 m means are the triangle 1.6 x 0.2 / 2 = 0.16 m over 2 m = 0.08 (three windows)
  // and 0.04 (two): F2 = 0.08. The Nadal verdict is on the largest unfiltered 2 m mean,
  // 0.08: an impact, not a climb (pass, with a note naming the instantaneous peak).
  CHECK(w.wheel[1].max_abs_yq.value == Approx(1.6));
  CHECK(w.wheel[1].max_abs_yq.distance == Approx(70.0).margin(1e-9));
  CHECK(w.wheel[1].max_abs_yq.time == Approx(6.9).margin(1e-9));
  CHECK(w.wheel[1].longest_exceedance == Approx(0.0).margin(1e-12));
  CHECK(w.wheel[1].nadal_on_2m);
  CHECK(w.wheel[1].max_yq_2m.value == Approx(0.08).epsilon(1e-9));
  CHECK(w.wheel[1].nadal_pass);
  bool noted = false;
  for (const auto& n : r.notes) noted = noted || (n.find("ws1 right") != std::string::npos && n.find("1.6") != std::string::npos);
  CHECK(noted);
  CHECK(get(r, "yq_2m", "ws1 right").value == Approx(0.08).epsilon(1e-9));
  // Sum Y: plateau windows 50 kN x the left means (0.75 .. 16.5 kN) and the spike's
  // 2, 4, 4, 4, 2 kN: F2 = 15.75 + 0.706 x 0.75 = 16.2795 kN; Prud'homme 10 + 100/3 kN.
  const Quantity& sy = get(r, "sum_y_2m", "ws1");
  CHECK(sy.value == Approx(16279.5).epsilon(1e-9));
  CHECK(sy.sections[0].peak == Approx(16.5e3).epsilon(1e-9));
  CHECK(sy.at_time == Approx(3.95).margin(1e-9));
  CHECK(sy.limit == Approx(43333.33).epsilon(1e-6));
  CHECK(sy.pass);
  // Unloading (50 - 25)/50 = 0.5 at one sample of 1001: the 99.85 % value is 0 (the
  // statistics of the standard ignore a single-sample dip); the peak is kept with where/when.
  const Quantity& u = get(r, "wheel_unloading", "ws1 left");
  CHECK(u.value == Approx(0.0).margin(1e-12));
  CHECK(u.sections[0].peak == Approx(0.5));
  CHECK(u.at_distance == Approx(80.0).margin(1e-9));
  CHECK(u.at_time == Approx(7.9).margin(1e-9));
  CHECK(u.pass);
  // Q_max: constant 50 kN against min(90 + 50, 200) kN at 36 km/h.
  CHECK(get(r, "q_max", "ws1 right").value == Approx(50e3));
  CHECK(get(r, "q_max", "ws1 right").limit == Approx(140e3));
  // Straight track only: no quasi-static values.
  CHECK_FALSE(get(r, "y_qst", "ws1 left").evaluated);
  // Every quantity within its limit: the wheelset and the run pass.
  CHECK(w.pass);
  CHECK(r.pass);
}

TEST_CASE("Nadal's flange-climb check is on the 2 m mean of |Y/Q|: sustained above it fails, short passes",
          "[safety][run]") {
  // Right wheel Y/Q = 1.4 (> Nadal 1.342 at 70 deg, mu 0.3) on wheelset distances [60, 60 + L]
  // (0.1 m samples, the ramps at both ends over one sample). L = 1 m: the largest 2 m mean is
  // (1 m + 0.1 m ramp) x 1.4 / 2 m = 0.77, pass, exceedance 1 m ((Y/Q)_2m 0.77 < 0.8 too);
  // L = 3 m: 1.4, fail, exceedance 3 m.
  SafetySettings set;
  set.force_lowpass = 0.0;
  for (const double L : {1.0, 3.0}) {
    const RunHistory h = history(1001, 0.01, 10.0, 1.0, [L](double, double x, double&, double&, double& yr, double&) {
      if (x >= 60.0 - 1e-9 && x <= 60.0 + L + 1e-9) yr = 70e3;
    });
    const RunSafety r = evaluate_run_safety(h, 70.0 * kDeg, 0.3, set);
    const WheelSafety& s = r.wheelsets[0].wheel[1];
    INFO("plateau length " << L << " m");
    CHECK(s.max_abs_yq.value == Approx(1.4));
    CHECK(s.longest_exceedance == Approx(L).margin(1e-9));
    CHECK(s.max_yq_2m.value == Approx(L < 2.0 ? 0.77 : 1.4).epsilon(1e-9));
    CHECK(s.nadal_pass == (L < 2.0));
    CHECK(r.wheelsets[0].pass == (L < 2.0));
    // The mirror case: the same on the left wheel, Y of the other sign.
    const RunHistory m = history(1001, 0.01, 10.0, 1.0, [L](double, double x, double& yl, double&, double&, double&) {
      if (x >= 60.0 - 1e-9 && x <= 60.0 + L + 1e-9) yl = -70e3;
    });
    const RunSafety rm = evaluate_run_safety(m, 70.0 * kDeg, 0.3, set);  // kept: sm refers into it
    const WheelSafety& sm = rm.wheelsets[0].wheel[0];
    CHECK(sm.max_yq_2m.value == Approx(s.max_yq_2m.value).epsilon(1e-12));
    CHECK(sm.nadal_pass == s.nadal_pass);
  }
}

TEST_CASE("run safety: a vehicle that does not advance has no 2 m windows", "[safety][run]") {
  RunHistory h = plateau_history();
  for (auto& s : h.distance) s = 5.0;
  const RunSafety r = evaluate_run_safety(h, 70.0 * kDeg, 0.3);
  CHECK_FALSE(r.en14363_evaluated);
  CHECK_FALSE(r.notes.empty());
  CHECK(r.quantities.empty());
  CHECK(r.wheelsets[0].wheel[1].max_abs_yq.value == Approx(1.6));
  // Without 2 m windows Nadal is judged on the instantaneous peak (conservative), and says so.
  CHECK_FALSE(r.wheelsets[0].wheel[1].nadal_on_2m);
  CHECK_FALSE(r.wheelsets[0].wheel[1].nadal_pass);
  CHECK_FALSE(r.pass);
  CHECK_THROWS(evaluate_run_safety(RunHistory{}, 1.0, 0.3));
}

TEST_CASE("20 Hz low-pass of the wheel forces: a 40 Hz component is attenuated by |H(40)|^2", "[safety][run]") {
  // 200 Hz sampling, 20 m/s for 10 s. Right wheel Q = 50 kN + 20 kN sin(2 pi 40 t): the samples
  // of the sine take the values 0, +-sin 72, +-sin 144 deg, so the unfiltered F2 is
  // 50 + 20 sin 72 = 69.02 kN; low-passed (4th order at 20 Hz, forward-backward) the sine
  // keeps |H(40)|^2 = 1 / (1 + (tan(0.2 pi) / tan(0.1 pi))^8) = 0.0016 of its amplitude.
  // Left wheel Y = 10 kN + 30 kN sin(2 pi 40 t) on Q = 50 kN: the 2 m means hold 4 whole
  // periods (0.5 m wavelength), so (Y/Q)_2m = 0.2 exactly, filtered or not.
  const RunHistory h = history(2001, 0.005, 20.0, 0.0, [](double t, double, double& yl, double&, double&, double& qr) {
    yl = 10e3 + 30e3 * std::sin(2 * M_PI * 40 * t);
    qr = 50e3 + 20e3 * std::sin(2 * M_PI * 40 * t);
  });
  const double h40 = lowpass_h2(40.0, 20.0, 200.0, 4);
  CHECK(h40 == Approx(0.0016).margin(1e-4));
  const RunSafety r = evaluate_run_safety(h, 70.0 * kDeg, 0.3);
  REQUIRE(r.processing.force_filter_applied);
  CHECK(r.processing.sample_rate == Approx(200.0));
  const Quantity& q = get(r, "q_max", "ws1 right");
  CHECK(q.value == Approx(50e3 + 20e3 * h40 * std::sin(72 * kDeg)).epsilon(1e-6));
  CHECK(q.processing.front().find("low-pass") != std::string::npos);
  CHECK(q.processing.front().find("20 Hz") != std::string::npos);
  // Without the filter: the raw 99.85 % value.
  SafetySettings raw;
  raw.force_lowpass = 0.0;
  const RunSafety u = evaluate_run_safety(h, 70.0 * kDeg, 0.3, raw);
  CHECK(get(u, "q_max", "ws1 right").value == Approx(50e3 + 20e3 * std::sin(72 * kDeg)).epsilon(1e-9));
  CHECK(get(r, "yq_2m", "ws1 left").value == Approx(0.2).epsilon(1e-6));
  CHECK(get(u, "yq_2m", "ws1 left").value == Approx(0.2).epsilon(1e-6));
  // Unloading from the filtered Q: F2 of (Q0 - Q)/Q0 = 0.4 h40 sin 72 (the sine is symmetric).
  CHECK(get(r, "wheel_unloading", "ws1 right").value == Approx(0.4 * h40 * std::sin(72 * kDeg)).epsilon(1e-5));
}

TEST_CASE("(Y/Q)_2m limit follows the zone: 0.8 on straight track and R >= 250 m, 1.2 below", "[safety][run]") {
  // Y/Q = 1.0 throughout; the straight (to 50 m) fails, the R 200 m curve passes.
  const RunHistory h = history(1001, 0.01, 10.0, 0.0, [](double, double, double& yl, double&, double&, double&) {
    yl = 50e3;
  });
  const RunSafety r = evaluate_run_safety(h, straight_then_curve(50.0, 200.0), 70.0 * kDeg, 0.3);
  const Quantity& q = get(r, "yq_2m", "ws1 left");
  REQUIRE(q.sections.size() == 2);
  CHECK(q.sections[0].limit == 0.8);
  CHECK_FALSE(q.sections[0].pass);
  CHECK(q.sections[1].zone == TrackZone::very_small_radius_curve);
  CHECK(q.sections[1].limit == 1.2);
  CHECK(q.sections[1].value == Approx(1.0).epsilon(1e-9));
  CHECK(q.sections[1].pass);
  CHECK_FALSE(q.pass);
  CHECK(q.section == 0);  // the failing straight decides
  CHECK(q.zone == TrackZone::straight);
  CHECK_FALSE(r.pass);
  // In an R 300 m curve the limit is 0.8 as well.
  const RunSafety r3 = evaluate_run_safety(h, straight_then_curve(50.0, 300.0), 70.0 * kDeg, 0.3);
  CHECK(get(r3, "yq_2m", "ws1 left").sections[1].limit == 0.8);
  CHECK_FALSE(get(r3, "yq_2m", "ws1 left").sections[1].pass);
}

TEST_CASE("quasi-static values: 50 % values of Y, Q and Y/Q in the curve only", "[safety][run]") {
  // Straight to 250 m, R 800 m from 250 m; 50 m/s, 200 Hz, 10 s. In the curve the outer (left)
  // wheel has Y = 20 kN, Q = 60 kN (steps at 250 m, smoothed by the low-pass over a few
  // samples, far fewer than half of the curve's 1001): Y_qst = 20 kN, Q_qst = 60 kN, 1/3.
  // The right wheel carries Q = 150 kN in the curve: Q_qst fails 145 kN.
  const RunHistory h = history(2001, 0.005, 50.0, 0.0, [](double, double x, double& yl, double& ql, double&,
                                                          double& qr) {
    if (x >= 250.0) yl = 20e3, ql = 60e3, qr = 150e3;
  });
  const RunSafety r = evaluate_run_safety(h, straight_then_curve(250.0, 800.0), 70.0 * kDeg, 0.3);
  const Quantity& y = get(r, "y_qst", "ws1 left");
  REQUIRE(y.sections.size() == 1);
  CHECK(y.sections[0].zone == TrackZone::large_radius_curve);
  CHECK(y.value == Approx(20e3).epsilon(1e-9));
  CHECK(y.limit == 60e3);
  CHECK(y.pass);
  CHECK(get(r, "q_qst", "ws1 left").value == Approx(60e3).epsilon(1e-9));
  CHECK(get(r, "yq_qst", "ws1 left").value == Approx(1.0 / 3.0).epsilon(1e-9));
  CHECK(std::isnan(get(r, "yq_qst", "ws1 left").limit));
  const Quantity& qr = get(r, "q_qst", "ws1 right");
  CHECK(qr.value == Approx(150e3).epsilon(1e-9));
  CHECK_FALSE(qr.pass);
  CHECK_FALSE(r.pass);
}

TEST_CASE("instability: Sum Y band-passed around the detected f0, 100 m sliding rms, half Prud'homme",
          "[safety][run]") {
  // 50 m/s, 200 Hz, 10 s (500 m). Sum Y = A sin(2 pi 4.5 t), half on each wheel. f0 is found
  // at 4.5 Hz; the band 2.5..6.5 Hz keeps |H(4.5)|^2 of it; a 100 m window is 2 s = 9 whole
  // periods of 400 sample intervals, and the square of the linearly interpolated samples
  // (step d = 2 pi 4.5 / 200) averages (2 + cos d) / 6: rms = A |H|^2 sqrt((2 + cos d) / 6).
  // Limit (10 + 100/3) / 2 = 21.67 kN: A = 40 kN fails, A = 20 kN passes.
  const double d = 2 * M_PI * 4.5 / 200.0;
  for (double A : {40e3, 20e3}) {
    const RunHistory h = history(2001, 0.005, 50.0, 0.0, [A](double t, double, double& yl, double&, double& yr,
                                                             double&) {
      yl = yr = 0.5 * A * std::sin(2 * M_PI * 4.5 * t);
    });
    const RunSafety r = evaluate_run_safety(h, 70.0 * kDeg, 0.3);
    INFO("A = " << A);
    CHECK(r.processing.hunting_frequency == Approx(4.5).margin(0.02));
    REQUIRE(r.processing.instability_filter_applied);
    REQUIRE(r.instability_evaluated);
    const double f0 = r.processing.hunting_frequency;
    const double expected = A * bandpass_h2(4.5, f0 - 2.0, f0 + 2.0, 200.0, 2) * std::sqrt((2 + std::cos(d)) / 6.0);
    const Quantity& q = get(r, "sum_y_rms", "ws1");
    CHECK(q.limit == Approx(0.5 * 43333.33).epsilon(1e-6));
    CHECK(q.value == Approx(expected).epsilon(1e-4));
    CHECK(q.x.size() == 41);  // centres 50, 60, ..., 450 m
    CHECK(q.pass == (A < 30e3));
    // (Sum Y)_2m of the same signal passes: the 2 m mean of an 11.1 m wave keeps sin(u)/u, u = 0.566.
    const double u = 2 * M_PI / (50.0 / 4.5);
    CHECK(get(r, "sum_y_2m", "ws1").value ==
          Approx(A * lowpass_h2(4.5, 20.0, 200.0, 4) * std::sin(u) / u).epsilon(2e-3));
    CHECK(get(r, "sum_y_2m", "ws1").pass);
  }
  // A given f0 is used as it is.
  SafetySettings s;
  s.hunting_frequency = 3.0;
  const RunHistory h = history(2001, 0.005, 50.0, 0.0, [](double t, double, double& yl, double&, double&, double&) {
    yl = 1e3 * std::sin(2 * M_PI * 4.5 * t);
  });
  const RunSafety r = evaluate_run_safety(h, 70.0 * kDeg, 0.3, s);
  CHECK(r.processing.hunting_frequency == 3.0);
  CHECK(r.processing.hunting_frequency_source.find("given") != std::string::npos);
  // A run shorter than the 100 m window does not evaluate the criterion, and says so.
  const RunHistory short_run = history(101, 0.005, 50.0, 0.0, [](double, double, double&, double&, double&, double&) {});
  const RunSafety rs = evaluate_run_safety(short_run, 70.0 * kDeg, 0.3);
  CHECK_FALSE(rs.instability_evaluated);
  CHECK(rs.find("sum_y_rms", "ws1") == nullptr);
}

TEST_CASE("bogie-frame and car-body accelerations: band-passes, percentiles, rms, quasi-static", "[safety][run]") {
  // 50 m/s, 200 Hz, 10 s; straight to 250 m, R 800 m after. A bogie frame of 5 t (limit
  // (12 - 1)/2 = 5.5 m/s^2) with a point reading a sin(2 pi 4.5 t) (f0 found in Sum Y);
  // a car-body point reading 0.5 + 1.0 sin(2 pi 5 t) laterally and 0.8 sin(2 pi 2.5 t) vertically.
  const double fs = 200.0, d = 2 * M_PI * 4.5 / fs;
  for (double a : {8.0, 6.0}) {
    RunHistory h = history(2001, 0.005, 50.0, 0.0, [](double t, double, double& yl, double&, double&, double&) {
      yl = 5e3 * std::sin(2 * M_PI * 4.5 * t);
    });
    RunningGear g;
    g.name = "bogie1";
    g.mass = 5000.0;
    g.wheelsets = {0};
    h.bogies.push_back(g);
    AccelerationPoint fp;
    fp.name = "bogie1@ws1";
    fp.body = "bogie1";
    fp.role = PointRole::bogie_frame_above_wheelset;
    fp.group = "bogie1";
    AccelerationPoint cp;
    cp.name = "car@bogie1";
    cp.body = "car";
    cp.role = PointRole::car_body_above_bogie;
    cp.group = "car";
    for (double t : h.time) {
      fp.ay.push_back(a * std::sin(2 * M_PI * 4.5 * t));
      fp.az.push_back(0.0);
      cp.ay.push_back(0.5 + std::sin(2 * M_PI * 5.0 * t));
      cp.az.push_back(0.8 * std::sin(2 * M_PI * 2.5 * t));
    }
    h.points = {fp, cp};
    const RunSafety r = evaluate_run_safety(h, straight_then_curve(250.0, 800.0), 70.0 * kDeg, 0.3);
    INFO("a = " << a);
    const double f0 = r.processing.hunting_frequency;
    CHECK(f0 == Approx(4.5).margin(0.02));
    const Quantity& b = get(r, "bogie_ay_rms", "bogie1@ws1");
    CHECK(b.limit == Approx(5.5));
    CHECK(b.value == Approx(a * bandpass_h2(4.5, f0 - 2, f0 + 2, fs, 2) * std::sqrt((2 + std::cos(d)) / 6.0))
                         .epsilon(1e-4));
    CHECK(b.pass == (a < 7.0));
    // Car body, band-pass 0.4..10 Hz: the offset goes, the 5 Hz sine (40 samples a period,
    // one of them at the crest) keeps |H(5)|^2: F1 = -|H|^2, F2 = +|H|^2.
    const double h5 = bandpass_h2(5.0, 0.4, 10.0, fs, 2), h25 = bandpass_h2(2.5, 0.4, 10.0, fs, 2);
    const Quantity& ay = get(r, "car_ay", "car@bogie1");
    CHECK(ay.sections[0].p_high == Approx(h5).epsilon(1e-5));
    CHECK(ay.sections[0].p_low == Approx(-h5).epsilon(1e-5));
    CHECK(ay.value == Approx(h5).epsilon(1e-5));
    CHECK(std::isnan(ay.limit));  // ride characteristics: reported only
    CHECK(get(r, "car_az", "car@bogie1").value == Approx(0.8 * h25).epsilon(1e-5));
    // rms per section: 25 whole periods on the straight (1000 samples): |H|^2 / sqrt 2; the
    // curve has one more sample (at a zero): |H|^2 sqrt(500 / 1001).
    const Quantity& rms = get(r, "car_ay_rms", "car@bogie1");
    CHECK(rms.sections[0].value == Approx(h5 / std::sqrt(2.0)).epsilon(1e-5));
    CHECK(rms.sections[1].value == Approx(h5 * std::sqrt(500.0 / 1001.0)).epsilon(1e-5));
    // Quasi-static lateral acceleration in the curve: the 50 % value of the low-passed signal,
    // a symmetric sine about 0.5 m/s^2.
    const Quantity& qst = get(r, "car_ay_qst", "car@bogie1");
    REQUIRE(qst.sections.size() == 1);
    CHECK(qst.value == Approx(0.5).epsilon(1e-6));
  }
}

TEST_CASE("flange angle: conical wheels fall back to 70 deg, the S1002/UIC60 table has its flank", "[safety][run]") {
  ConicalParams p;
  p.flange_clearance = 0.009;
  p.flange_stiffness = 1.5e7;
  const FlangeAngle c = flange_angle(ConicalGeometry(p));
  CHECK(c.fallback);
  CHECK(c.angle == Approx(70.0 * kDeg));
  CHECK(c.source.find("fallback") != std::string::npos);
  const FlangeAngle t = flange_angle(GeometryTable(railsim::test::data_path("engine/rsgeo_1in10.dat")));
  INFO(t.source);
  CHECK_FALSE(t.fallback);
  // S1002 flank on UIC60 at 1:40: about 70 deg (physics-reference §9.1, "S1002 max flank angle").
  CHECK(t.angle / kDeg > 65.0);
  CHECK(t.angle / kDeg < 75.0);
}

TEST_CASE("curving statistics over the body of a circular curve", "[curving][run]") {
  // Two wheelsets at +-1 m, reference at 10 m/s from 0 to 200 m (0.5 m samples). Track at
  // track distance x: straight to 50 m, transition 50..70 m, circle R = 500 m left from 70 m.
  // Both wheelsets are in the circle from reference distance 71 m; with 50 m settling the
  // body starts at 121 m. Leading wheelset yaw -2 mrad (heads right = toward the outer
  // rail: angle of attack +2 mrad), trailing +0.5 mrad (-0.5 mrad); the leading right
  // (outer) wheel has Y/Q 0.3 and T-gamma 100 N in the circle, 0 elsewhere.
  RunHistory h;
  h.total_mass = 20000;
  for (double off : {1.0, -1.0}) {
    WheelsetHistory w;
    w.name = off > 0 ? "lead" : "trail";
    w.offset = off;
    w.static_wheel_load = 50e3;
    h.wheelsets.push_back(w);
  }
  for (int i = 0; i <= 400; ++i) {
    const double s = 0.5 * i;
    h.time.push_back(s / 10.0);
    h.distance.push_back(s);
    h.speed.push_back(10.0);
    for (auto& w : h.wheelsets) {
      const double x = s + w.offset;
      const bool circle = x >= 70.0;
      w.curvature.push_back(circle ? 1.0 / 500.0 : (x > 50.0 ? (x - 50.0) / (20.0 * 500.0) : 0.0));
      w.curvature_rate.push_back(!circle && x > 50.0 ? 1.0 / (20.0 * 500.0) : 0.0);
      w.cant.push_back(0.0);
      const bool lead = w.offset > 0;
      w.yaw.push_back(circle ? (lead ? -2e-3 : 0.5e-3) : 0.0);
      w.y.push_back(circle ? -4e-3 : 0.0);
      for (int k = 0; k < 2; ++k) {
        const bool hot = circle && lead && k == 1;
        w.wheel[k].Q.push_back(50e3);
        w.wheel[k].Y.push_back(hot ? 15e3 : 0.0);
        w.wheel[k].Tgamma.push_back(hot ? 100.0 : 0.0);
        for (auto* v : {&w.wheel[k].Fx, &w.wheel[k].Fy, &w.wheel[k].Mz, &w.wheel[k].xi, &w.wheel[k].eta,
                        &w.wheel[k].spin})
          v->push_back(0.0);
      }
    }
  }
  const auto curves = evaluate_curving(h);
  REQUIRE(curves.size() == 1);
  const CurveResult& c = curves[0];
  CHECK(c.curvature == Approx(1.0 / 500.0));
  CHECK(c.start == Approx(121.0));
  CHECK(c.end == Approx(200.0));
  CHECK(c.samples == 159);
  CHECK(c.unbalanced_acceleration == Approx(100.0 / 500.0));
  CHECK(c.expected_sum_Y == Approx(20000 * 0.2));
  CHECK(c.sum_Y == Approx(15e3));
  REQUIRE(c.wheelsets.size() == 2);
  CHECK(c.wheelsets[0].angle_of_attack.mean == Approx(2e-3));
  CHECK(c.wheelsets[1].angle_of_attack.mean == Approx(-0.5e-3));
  CHECK(c.wheelsets[0].lateral_shift.mean == Approx(4e-3));
  CHECK(c.wheelsets[0].wheel[1].outer);
  CHECK_FALSE(c.wheelsets[0].wheel[0].outer);
  CHECK(c.wheelsets[0].wheel[1].yq.mean == Approx(0.3));
  CHECK(c.wheelsets[0].wheel[1].yq.max == Approx(0.3));
  CHECK(c.wheelsets[0].wheel[1].Tgamma.mean == Approx(100.0));
  CHECK(c.wheelsets[1].wheel[1].Tgamma.max == Approx(0.0));
  // Straight track: no curves.
  for (auto& w : h.wheelsets) std::fill(w.curvature.begin(), w.curvature.end(), 0.0);
  CHECK(evaluate_curving(h).empty());
}
