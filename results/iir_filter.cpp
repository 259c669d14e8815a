// Butterworth IIR filters and zero-phase filtering; see iir_filter.hpp.
#include "results/iir_filter.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <stdexcept>

namespace railsim::results {

namespace {

using cd = std::complex<double>;
constexpr double kPi = 3.14159265358979323846;

void check_design(int order, double f1, double f2, double fs) {
  if (order < 1 || order > 12) throw std::invalid_argument("Butterworth filter: order must be 1..12");
  if (!(fs > 0.0)) throw std::invalid_argument("Butterworth filter: sample rate must be > 0");
  if (!(f1 >= 0.0) || !(f2 > f1) || !(f2 < 0.5 * fs))
    throw std::invalid_argument("Butterworth filter: need 0 <= f1 < f2 < fs/2 (got " + std::to_string(f1) + ", " +
                                std::to_string(f2) + " Hz at fs = " + std::to_string(fs) + " Hz)");
}

// Pre-warped analog frequency [rad/s] of a digital frequency f [Hz].
double prewarp(double f, double fs) { return 2.0 * fs * std::tan(kPi * f / fs); }

// Bilinear map of an analog pole.
cd bilinear(cd s, double fs) { return (2.0 * fs + s) / (2.0 * fs - s); }

// Prototype low-pass poles (unit cut-off, left half-plane).
std::vector<cd> prototype_poles(int n) {
  std::vector<cd> p;
  for (int k = 0; k < n; ++k) p.push_back(std::polar(1.0, kPi * (2.0 * k + n + 1) / (2.0 * n)));
  return p;
}

cd section_response(const Biquad& s, cd zinv) {
  return (s.b0 + zinv * (s.b1 + zinv * s.b2)) / (1.0 + zinv * (s.a1 + zinv * s.a2));
}

// Group digital poles into second-order sections (conjugate pairs, then real
// poles two by two) with the given numerator.
std::vector<Biquad> sections_from_poles(std::vector<cd> poles, double b0, double b1, double b2, double b1_single) {
  const double eps = 1e-10;
  std::vector<Biquad> out;
  std::vector<double> real;
  for (const cd& z : poles) {
    if (z.imag() > eps) {
      Biquad s;
      s.a1 = -2.0 * z.real();
      s.a2 = std::norm(z);
      s.b0 = b0, s.b1 = b1, s.b2 = b2;
      out.push_back(s);
    } else if (std::fabs(z.imag()) <= eps) {
      real.push_back(z.real());
    }
  }
  std::sort(real.begin(), real.end());
  for (std::size_t i = 0; i + 1 < real.size(); i += 2) {
    Biquad s;
    s.a1 = -(real[i] + real[i + 1]);
    s.a2 = real[i] * real[i + 1];
    s.b0 = b0, s.b1 = b1, s.b2 = b2;
    out.push_back(s);
  }
  if (real.size() % 2 == 1) {  // one first-order section (odd low-pass)
    Biquad s;
    s.a1 = -real.back();
    s.a2 = 0.0;
    s.b0 = 1.0, s.b1 = b1_single, s.b2 = 0.0;
    out.push_back(s);
  }
  return out;
}

// Scale every section to unit magnitude at digital frequency f.
void normalise(std::vector<Biquad>& sections, double f, double fs) {
  const cd zinv = std::polar(1.0, -2.0 * kPi * f / fs);
  for (auto& s : sections) {
    const double g = std::abs(section_response(s, zinv));
    s.b0 /= g, s.b1 /= g, s.b2 /= g;
  }
}

// Steady-state states (s1, s2) of every section for a constant input of 1.
std::vector<std::pair<double, double>> steady_states(const IirFilter& f) {
  std::vector<std::pair<double, double>> zi;
  double u = 1.0;
  for (const auto& s : f.sections) {
    const double g = (s.b0 + s.b1 + s.b2) / (1.0 + s.a1 + s.a2) * u;
    zi.emplace_back((s.b1 + s.b2) * u - (s.a1 + s.a2) * g, s.b2 * u - s.a2 * g);
    u = g;
  }
  return zi;
}

// In-place pass with initial states zi scaled by `level`. Every sample goes
// through all sections before the next one (the sections' recursions overlap
// in the processor instead of one pass over the record per section).
void run(const IirFilter& f, std::vector<double>& x, const std::vector<std::pair<double, double>>* zi, double level) {
  constexpr std::size_t kMax = 16;
  const std::size_t ns = std::min(f.sections.size(), kMax);
  double s1[kMax], s2[kMax];
  for (std::size_t k = 0; k < ns; ++k) {
    s1[k] = zi ? (*zi)[k].first * level : 0.0;
    s2[k] = zi ? (*zi)[k].second * level : 0.0;
  }
  const Biquad* sec = f.sections.data();
  for (double& v : x) {
    double in = v;
    for (std::size_t k = 0; k < ns; ++k) {
      const Biquad& s = sec[k];
      const double y = s.b0 * in + s1[k];
      s1[k] = s.b1 * in - s.a1 * y + s2[k];
      s2[k] = s.b2 * in - s.a2 * y;
      in = y;
    }
    v = in;
  }
}

}  // namespace

double IirFilter::magnitude(double f) const {
  const cd zinv = std::polar(1.0, -2.0 * kPi * f / sample_rate);
  cd h = 1.0;
  for (const auto& s : sections) h *= section_response(s, zinv);
  return std::abs(h);
}

std::size_t IirFilter::settling_samples() const {
  double rmax = 0.0;
  for (const auto& s : sections) {
    // Roots of z^2 + a1 z + a2.
    const cd d = std::sqrt(cd(s.a1 * s.a1 - 4.0 * s.a2, 0.0));
    rmax = std::max({rmax, std::abs((-s.a1 + d) / 2.0), std::abs((-s.a1 - d) / 2.0)});
  }
  if (rmax <= 0.0) return 1;
  if (rmax >= 1.0) return 100000;
  return static_cast<std::size_t>(std::ceil(std::log(1e-6) / std::log(rmax)));
}

IirFilter butterworth_lowpass(int order, double fc, double fs) {
  check_design(order, 0.0, fc, fs);
  const double wc = prewarp(fc, fs);
  std::vector<cd> z;
  for (const cd& p : prototype_poles(order)) z.push_back(bilinear(wc * p, fs));
  IirFilter f;
  f.sections = sections_from_poles(z, 1.0, 2.0, 1.0, 1.0);  // zeros at z = -1
  normalise(f.sections, 0.0, fs);
  f.sample_rate = fs;
  f.f_high = fc;
  f.order = order;
  char buf[160];
  std::snprintf(buf, sizeof buf, "Butterworth low-pass, order %d, -3 dB at %.4g Hz (bilinear, pre-warped), fs %.4g Hz",
                order, fc, fs);
  f.description = buf;
  return f;
}

IirFilter butterworth_bandpass(int order, double f1, double f2, double fs) {
  check_design(order, f1, f2, fs);
  if (!(f1 > 0.0)) throw std::invalid_argument("Butterworth band-pass: lower edge must be > 0");
  const double w1 = prewarp(f1, fs), w2 = prewarp(f2, fs);
  const double w0sq = w1 * w2, bw = w2 - w1;
  std::vector<cd> z;
  for (const cd& p : prototype_poles(order)) {
    const cd h = 0.5 * bw * p;
    const cd r = std::sqrt(h * h - w0sq);
    z.push_back(bilinear(h + r, fs));
    z.push_back(bilinear(h - r, fs));
  }
  IirFilter f;
  f.sections = sections_from_poles(z, 1.0, 0.0, -1.0, 0.0);  // one zero at +1 and one at -1 per section
  const double fcentre = fs / kPi * std::atan(std::sqrt(w0sq) / (2.0 * fs));
  normalise(f.sections, fcentre, fs);
  f.sample_rate = fs;
  f.f_low = f1;
  f.f_high = f2;
  f.order = order;
  char buf[180];
  std::snprintf(buf, sizeof buf,
                "Butterworth band-pass, order %d (%d poles), -3 dB at %.4g and %.4g Hz (bilinear, pre-warped), fs %.4g Hz",
                order, 2 * order, f1, f2, fs);
  f.description = buf;
  return f;
}

void filter_forward(const IirFilter& f, const std::vector<double>& x, std::vector<double>& y) {
  y = x;
  run(f, y, nullptr, 0.0);
}

std::vector<double> filtfilt(const IirFilter& f, const std::vector<double>& x, std::size_t padding) {
  const std::size_t n = x.size();
  if (n < 2) return x;
  std::size_t pad = padding > 0 ? padding : f.settling_samples();
  pad = std::min(pad, n - 1);
  std::vector<double> e;
  e.reserve(n + 2 * pad);
  for (std::size_t k = pad; k >= 1; --k) e.push_back(2.0 * x.front() - x[k]);
  e.insert(e.end(), x.begin(), x.end());
  for (std::size_t k = 1; k <= pad; ++k) e.push_back(2.0 * x.back() - x[n - 1 - k]);
  const auto zi = steady_states(f);
  run(f, e, &zi, e.front());
  std::reverse(e.begin(), e.end());
  run(f, e, &zi, e.front());
  std::reverse(e.begin(), e.end());
  return std::vector<double>(e.begin() + static_cast<std::ptrdiff_t>(pad),
                             e.begin() + static_cast<std::ptrdiff_t>(pad + n));
}

double uniform_sample_rate(const std::vector<double>& t, double tolerance) {
  if (t.size() < 3) throw std::invalid_argument("uniform_sample_rate: need at least 3 samples");
  std::vector<double> dt;
  dt.reserve(t.size() - 1);
  for (std::size_t i = 1; i < t.size(); ++i) dt.push_back(t[i] - t[i - 1]);
  std::vector<double> sorted = dt;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2), sorted.end());
  const double med = sorted[sorted.size() / 2];
  if (!(med > 0.0)) throw std::invalid_argument("uniform_sample_rate: time does not increase");
  for (std::size_t i = 0; i + 1 < dt.size(); ++i)
    if (std::fabs(dt[i] - med) > tolerance * med)
      throw std::invalid_argument("uniform_sample_rate: non-uniform sampling at t = " + std::to_string(t[i + 1]) +
                                  " s (spacing " + std::to_string(dt[i]) + " s, median " + std::to_string(med) + " s)");
  if (!(dt.back() > 0.0)) throw std::invalid_argument("uniform_sample_rate: time does not increase at the end");
  return 1.0 / med;
}

}  // namespace railsim::results
