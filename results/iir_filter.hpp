// Butterworth IIR filters (low-pass, band-pass) designed by the bilinear
// transform, as cascades of second-order sections, and zero-phase filtering
// by forward-backward passes (filtfilt).
//
// Design (Oppenheim & Schafer, Discrete-Time Signal Processing, 3rd ed. 2010,
// §7.1.2 bilinear transformation and §7.2 Butterworth design; Parks & Burrus,
// Digital Filter Design, 1987, ch. 7 for the low-pass to band-pass transform):
//   analog low-pass prototype of order N, unit cut-off: poles
//     p_k = exp(i pi (2k + N + 1) / (2N)), k = 0..N-1, no finite zeros;
//   band edges pre-warped, W = 2 fs tan(pi f / fs), so that the digital filter
//   has its -3 dB points exactly at the requested frequencies;
//   low-pass: s -> s / Wc;  band-pass: s -> (s^2 + W0^2) / (s B), W0^2 = W1 W2,
//   B = W2 - W1 (each prototype pole gives two poles, N zeros at s = 0);
//   bilinear map z = (2 fs + s) / (2 fs - s); zeros at infinity go to z = -1,
//   zeros at s = 0 to z = +1; gain normalised to 1 at DC (low-pass) or at the
//   centre frequency (band-pass).
// The resulting single-pass magnitude is exactly
//   low-pass   |H(f)|^2 = 1 / (1 + (tan(pi f/fs) / tan(pi fc/fs))^(2N))
//   band-pass  |H(f)|^2 = 1 / (1 + ((W^2 - W0^2) / (W B))^(2N)),  W = 2 fs tan(pi f/fs)
// and filtfilt() applies the filter forward then backward: zero phase,
// magnitude |H(f)|^2 (-6 dB at the band edges, twice the attenuation in dB).
// Edges: the record is extended at both ends by an odd reflection (2 x0 - x)
// of `padding` samples and each section starts from its steady state for the
// first padded value, which suppresses the start-up transients
// (Gustafsson 1996, IEEE Trans. Signal Processing 44(4), 988-992, on
// forward-backward initial conditions).
// Sections use the transposed direct form II. Frequencies in Hz.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace railsim::results {

// y[n] = b0 x[n] + b1 x[n-1] + b2 x[n-2] - a1 y[n-1] - a2 y[n-2]
struct Biquad {
  double b0 = 1.0, b1 = 0.0, b2 = 0.0, a1 = 0.0, a2 = 0.0;
};

struct IirFilter {
  std::vector<Biquad> sections;
  double sample_rate = 0.0;  // [Hz]
  double f_low = 0.0;        // lower -3 dB edge of a band-pass (0 for a low-pass) [Hz]
  double f_high = 0.0;       // upper -3 dB edge (cut-off of a low-pass) [Hz]
  int order = 0;             // prototype order N
  std::string description;   // e.g. "Butterworth low-pass, order 4, 20 Hz (bilinear, pre-warped)"

  // Single-pass magnitude |H| at frequency f [Hz] (evaluated from the sections).
  double magnitude(double f) const;
  // Samples after which the impulse response has decayed below ~1e-6 of its
  // peak (the default padding of filtfilt; from the slowest pole).
  std::size_t settling_samples() const;
};

// Order-N Butterworth low-pass with cut-off fc. Throws std::invalid_argument
// unless 1 <= order <= 12 and 0 < fc < fs/2.
IirFilter butterworth_lowpass(int order, double fc, double fs);

// Order-N Butterworth band-pass with edges f1 < f2 (2N poles). Throws
// std::invalid_argument unless 1 <= order <= 12 and 0 < f1 < f2 < fs/2.
IirFilter butterworth_bandpass(int order, double f1, double f2, double fs);

// One forward pass (zero initial state), in place into `y` (resized).
void filter_forward(const IirFilter& f, const std::vector<double>& x, std::vector<double>& y);

// Zero-phase forward-backward filtering with odd-reflection padding of
// `padding` samples (0: settling_samples(), capped at x.size() - 1) and
// steady-state initial conditions. Fewer than 2 samples are returned unchanged.
std::vector<double> filtfilt(const IirFilter& f, const std::vector<double>& x, std::size_t padding = 0);

// Sample rate of a time series [Hz], from its median spacing. Throws
// std::invalid_argument when any spacing (the last one excepted, which may be
// shorter at the end of a run) differs from the median by more than
// `tolerance` (relative), or for fewer than 3 samples.
double uniform_sample_rate(const std::vector<double>& t, double tolerance = 1e-3);

}  // namespace railsim::results
