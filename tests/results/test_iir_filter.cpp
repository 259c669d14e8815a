// Butterworth filters and zero-phase filtering (results/iir_filter.hpp)
// against the closed-form Butterworth magnitude of the bilinear design and
// hand-computed filtered sines: attenuation at known frequencies, zero phase,
// steady edges.
#include <catch2/catch.hpp>

#include <cmath>

#include "results/iir_filter.hpp"

using namespace railsim::results;

namespace {
// Single-pass |H|^2 of the pre-warped bilinear Butterworth designs (see iir_filter.hpp).
double lowpass_h2(double f, double fc, double fs, int n) {
  return 1.0 / (1.0 + std::pow(std::tan(M_PI * f / fs) / std::tan(M_PI * fc / fs), 2 * n));
}
double bandpass_h2(double f, double f1, double f2, double fs, int n) {
  const double w = 2 * fs * std::tan(M_PI * f / fs), w1 = 2 * fs * std::tan(M_PI * f1 / fs),
               w2 = 2 * fs * std::tan(M_PI * f2 / fs);
  return 1.0 / (1.0 + std::pow((w * w - w1 * w2) / (w * (w2 - w1)), 2 * n));
}
std::vector<double> sine(double amp, double f, double fs, int n, double phase = 0.0) {
  std::vector<double> x(n);
  for (int i = 0; i < n; ++i) x[i] = amp * std::sin(2 * M_PI * f * i / fs + phase);
  return x;
}
}  // namespace

TEST_CASE("Butterworth low-pass: magnitude is the closed form, -3 dB at the cut-off", "[results][filter]") {
  for (int order : {1, 2, 3, 4, 6}) {
    const auto f = butterworth_lowpass(order, 20.0, 200.0);
    INFO("order " << order);
    CHECK(f.sections.size() == static_cast<std::size_t>((order + 1) / 2));
    CHECK(f.magnitude(0.0) == Approx(1.0).epsilon(1e-12));
    CHECK(f.magnitude(20.0) == Approx(std::sqrt(0.5)).epsilon(1e-10));
    for (double fr : {1.0, 5.0, 10.0, 15.0, 25.0, 40.0, 60.0, 90.0})
      CHECK(f.magnitude(fr) == Approx(std::sqrt(lowpass_h2(fr, 20.0, 200.0, order))).epsilon(1e-9));
  }
  // At 100 Hz sampling (the coach runs' 10 ms outputs) the same closed form holds.
  const auto g = butterworth_lowpass(4, 20.0, 100.0);
  CHECK(g.magnitude(30.0) == Approx(std::sqrt(lowpass_h2(30.0, 20.0, 100.0, 4))).epsilon(1e-9));
}

TEST_CASE("Butterworth band-pass: unit gain at the centre, -3 dB at both edges, closed form", "[results][filter]") {
  for (int order : {1, 2, 3}) {
    const double fs = 200.0, f1 = 2.5, f2 = 6.5;
    const auto f = butterworth_bandpass(order, f1, f2, fs);
    INFO("order " << order);
    CHECK(f.sections.size() == static_cast<std::size_t>(order));
    // Digital centre: W0 = sqrt(W1 W2) mapped back.
    const double w0 = std::sqrt(2 * fs * std::tan(M_PI * f1 / fs) * 2 * fs * std::tan(M_PI * f2 / fs));
    const double fc = fs / M_PI * std::atan(w0 / (2 * fs));
    CHECK(f.magnitude(fc) == Approx(1.0).epsilon(1e-10));
    CHECK(f.magnitude(f1) == Approx(std::sqrt(0.5)).epsilon(1e-9));
    CHECK(f.magnitude(f2) == Approx(std::sqrt(0.5)).epsilon(1e-9));
    CHECK(f.magnitude(0.0) == Approx(0.0).margin(1e-12));
    CHECK(f.magnitude(100.0) == Approx(0.0).margin(1e-9));
    for (double fr : {0.5, 1.0, 3.0, 4.5, 8.0, 12.0, 30.0})
      CHECK(f.magnitude(fr) == Approx(std::sqrt(bandpass_h2(fr, f1, f2, fs, order))).epsilon(1e-8));
  }
  // The ride band 0.4..10 Hz (wide: real analog poles) obeys the same form.
  const auto r = butterworth_bandpass(2, 0.4, 10.0, 200.0);
  for (double fr : {0.1, 0.4, 2.0, 10.0, 30.0})
    CHECK(r.magnitude(fr) == Approx(std::sqrt(bandpass_h2(fr, 0.4, 10.0, 200.0, 2))).epsilon(1e-8));
}

TEST_CASE("filtfilt: a sine comes out scaled by |H|^2 with no phase shift", "[results][filter]") {
  const double fs = 200.0;
  const auto lp = butterworth_lowpass(4, 20.0, fs);
  // 10 Hz passes (|H|^2 = 0.9968), 40 Hz is attenuated to 0.0016 (closed form: 1 / (1 + 2.236^8)).
  const double h10 = lowpass_h2(10.0, 20.0, fs, 4), h40 = lowpass_h2(40.0, 20.0, fs, 4);
  CHECK(h40 == Approx(1.0 / (1.0 + std::pow(std::tan(M_PI * 0.2) / std::tan(M_PI * 0.1), 8))));
  CHECK(h40 == Approx(0.0016).margin(1e-4));
  CHECK(h10 == Approx(0.9968).margin(1e-4));
  const int n = 4000;
  for (auto [f, h2] : {std::pair{10.0, h10}, std::pair{40.0, h40}}) {
    const auto x = sine(3.0, f, fs, n, 0.3);
    const auto y = filtfilt(lp, x);
    REQUIRE(y.size() == x.size());
    double err = 0.0;
    for (int i = 500; i < n - 500; ++i) err = std::max(err, std::fabs(y[i] - h2 * x[i]));
    INFO("f = " << f << " Hz");
    CHECK(err < 1e-6 * 3.0);  // same phase (zero-phase), amplitude 3 |H|^2
  }
  // Band-pass around a hunting frequency: 4.5 Hz within 2.5..6.5 Hz.
  const auto bp = butterworth_bandpass(2, 2.5, 6.5, fs);
  const double hb = bandpass_h2(4.5, 2.5, 6.5, fs, 2);
  const auto x = sine(10e3, 4.5, fs, n);
  const auto y = filtfilt(bp, x);
  double err = 0.0;
  for (int i = 800; i < n - 800; ++i) err = std::max(err, std::fabs(y[i] - hb * x[i]));
  CHECK(err < 1e-5 * 10e3);
}

TEST_CASE("filtfilt: steady edges (constant in, constant out), zero for a band-pass", "[results][filter]") {
  const std::vector<double> c(300, 7.5);
  const auto lp = filtfilt(butterworth_lowpass(4, 20.0, 200.0), c);
  for (double v : lp) CHECK(v == Approx(7.5).epsilon(1e-10));
  const auto bp = filtfilt(butterworth_bandpass(2, 2.5, 6.5, 200.0), c);
  for (double v : bp) CHECK(v == Approx(0.0).margin(1e-9));
  // A ramp keeps its slope through the low-pass (odd reflection at both ends;
  // the start-up transient of the padding has decayed to ~1e-6 of the slope).
  std::vector<double> r(400);
  for (int i = 0; i < 400; ++i) r[i] = 0.01 * i;
  const auto rf = filtfilt(butterworth_lowpass(4, 20.0, 200.0), r);
  for (int i = 0; i < 400; ++i) CHECK(rf[i] == Approx(r[i]).margin(1e-7));
  // Fewer than two samples come back unchanged.
  CHECK(filtfilt(butterworth_lowpass(2, 1.0, 10.0), {3.0}) == std::vector<double>{3.0});
}

TEST_CASE("filter designs and sampling checks refuse bad input", "[results][filter]") {
  CHECK_THROWS_AS(butterworth_lowpass(4, 120.0, 200.0), std::invalid_argument);  // above Nyquist
  CHECK_THROWS_AS(butterworth_lowpass(0, 20.0, 200.0), std::invalid_argument);
  CHECK_THROWS_AS(butterworth_bandpass(2, 6.0, 5.0, 200.0), std::invalid_argument);
  CHECK_THROWS_AS(butterworth_bandpass(2, 0.0, 5.0, 200.0), std::invalid_argument);
  // Uniform sampling: the last step may be shorter (end of a run), others may not differ.
  CHECK(uniform_sample_rate({0.0, 0.005, 0.010, 0.015, 0.0175}) == Approx(200.0));
  CHECK_THROWS_AS(uniform_sample_rate({0.0, 0.005, 0.011, 0.015, 0.020}), std::invalid_argument);
  CHECK_THROWS_AS(uniform_sample_rate({0.0, 0.005}), std::invalid_argument);
  CHECK(butterworth_lowpass(4, 20.0, 200.0).description.find("20 Hz") != std::string::npos);
}
