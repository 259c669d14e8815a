// PSD synthesis: the Welch PSD estimate (FFTW, Hann window, 50 % overlap) of a
// long synthesised sample lies within 20 % of the target PSD across the
// wavelength band, for ERRI B176 and FRA spectra and all four channels; same
// seed gives the same sample bit for bit, a different seed a different one;
// slopes are the derivative of the values; the interpolated component
// reproduces the grid and is tapered to zero at its ends.
#include <catch2/catch.hpp>

#include <fftw3.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include "core/errors.hpp"
#include "track/psd_synthesis.hpp"

using namespace railsim::track;

namespace {

constexpr double kPi = 3.14159265358979323846;

struct Welch {
  std::vector<double> omega, psd;  // rad/m, one-sided m^2/(rad/m)
  int segments = 0;
};

// Welch estimate of the one-sided PSD over Omega of samples x with step h,
// segments of m points, Hann window, 50 % overlap.
Welch welch(const std::vector<double>& x, double h, int m) {
  std::vector<double> w(static_cast<std::size_t>(m)), buf(static_cast<std::size_t>(m));
  double wsum2 = 0;
  for (int j = 0; j < m; ++j) {
    w[static_cast<std::size_t>(j)] = 0.5 * (1 - std::cos(2 * kPi * j / m));
    wsum2 += w[static_cast<std::size_t>(j)] * w[static_cast<std::size_t>(j)];
  }
  std::vector<fftw_complex> X(static_cast<std::size_t>(m / 2 + 1));
  fftw_plan plan = fftw_plan_dft_r2c_1d(m, buf.data(), X.data(), FFTW_ESTIMATE);
  Welch out;
  out.psd.assign(static_cast<std::size_t>(m / 2 + 1), 0.0);
  for (std::size_t start = 0; start + static_cast<std::size_t>(m) <= x.size(); start += static_cast<std::size_t>(m / 2)) {
    for (int j = 0; j < m; ++j) buf[static_cast<std::size_t>(j)] = w[static_cast<std::size_t>(j)] * x[start + static_cast<std::size_t>(j)];
    fftw_execute(plan);
    for (int k = 1; k < m / 2; ++k)
      out.psd[static_cast<std::size_t>(k)] += X[static_cast<std::size_t>(k)][0] * X[static_cast<std::size_t>(k)][0] +
                                              X[static_cast<std::size_t>(k)][1] * X[static_cast<std::size_t>(k)][1];
    ++out.segments;
  }
  fftw_destroy_plan(plan);
  // S_f = 2 h |X|^2 / sum w^2 (one-sided, cyclic frequency); S_Omega = S_f / (2 pi).
  out.omega.resize(out.psd.size());
  for (std::size_t k = 0; k < out.psd.size(); ++k) {
    out.psd[k] *= 2.0 * h / (wsum2 * out.segments) / (2 * kPi);
    out.omega[k] = 2 * kPi * static_cast<double>(k) / (m * h);
  }
  return out;
}

// Largest relative deviation of the Welch estimate from the target over the
// band, leaving out 3 Welch bins at each edge (the Hann main lobe straddles
// the hard band limits there).
double worst_deviation(const TrackSpectrum& sp, Channel c, const SynthesisOptions& o, int m, int* bins) {
  const SampledChannel x = synthesise_channel(sp, c, o);
  const Welch w = welch(x.value, x.step, m);
  const double dO = w.omega[1];
  const double lo = 2 * kPi / o.wavelength_max + 3 * dO, hi = 2 * kPi / o.wavelength_min - 3 * dO;
  double worst = 0;
  *bins = 0;
  for (std::size_t k = 1; k < w.omega.size(); ++k) {
    if (w.omega[k] < lo || w.omega[k] > hi) continue;
    worst = std::max(worst, std::abs(w.psd[k] / sp.psd(c, w.omega[k]) - 1.0));
    ++*bins;
  }
  return worst;
}

}  // namespace

TEST_CASE("Welch PSD of synthesised ERRI and FRA irregularities is within 20 % of the target", "[tracks][psd_synthesis]") {
  struct Case {
    const char* spectrum;
    double lmin, lmax;
  };
  for (const Case cs : {Case{"erri_low", 3.0, 150.0}, Case{"erri_high", 2.0, 100.0}, Case{"fra_4", 3.0, 70.0},
                        Case{"fra_6", 2.0, 100.0}}) {
    const TrackSpectrum sp = TrackSpectrum::named(cs.spectrum);
    SynthesisOptions o;
    o.wavelength_min = cs.lmin;
    o.wavelength_max = cs.lmax;
    o.s_begin = 0;
    o.s_end = 200000;  // 200 km: ~500 Welch segments
    o.taper = 0;
    o.step = cs.lmin / 8;
    o.seed = 2024 + static_cast<std::uint64_t>(cs.lmax);  // a different realisation per case
    // Welch segments of at least 4 lambda_max (power of two points): the band
    // edge lies >= 4 Welch bins above zero; ~500 segments keep the statistical
    // scatter of each bin near 1/sqrt(500) = 4.5 %.
    int m = 1;
    while (m * o.step < 4 * cs.lmax) m *= 2;
    for (Channel c : kAllChannels) {
      int bins = 0;
      const double worst = worst_deviation(sp, c, o, m, &bins);
      INFO(cs.spectrum << " " << channel_name(c));
      CHECK(bins > 50);
      CHECK(worst < 0.20);
      std::printf("[psd synthesis] %-9s %-11s band %g-%g m: Welch (%d-pt segments) vs target over %d bins: max "
                  "deviation %.1f %%\n",
                  cs.spectrum, channel_name(c), cs.lmin, cs.lmax, m, bins, 100 * worst);
    }
  }
}

TEST_CASE("synthesised variance matches the band variance of the PSD", "[tracks][psd_synthesis]") {
  const TrackSpectrum sp = TrackSpectrum::named("erri_low");
  SynthesisOptions o;
  o.s_end = 100000;
  o.taper = 0;
  for (Channel c : {Channel::vertical, Channel::lateral}) {
    const SampledChannel x = synthesise_channel(sp, c, o);
    double sum2 = 0;
    for (double v : x.value) sum2 += v * v;
    const double var = sum2 / static_cast<double>(x.value.size());
    // Random phases, deterministic amplitudes: the sample variance is close to the expected one.
    CHECK(var == Approx(sp.variance(c, 3.0, 150.0)).epsilon(0.03));
  }
}

TEST_CASE("same seed gives the same irregularity bit for bit and another seed another one", "[tracks][psd_synthesis]") {
  const TrackSpectrum sp = TrackSpectrum::named("fra_5");
  SynthesisOptions o;
  o.s_end = 3000;
  o.seed = 7;
  const SampledChannel a = synthesise_channel(sp, Channel::vertical, o);
  const SampledChannel b = synthesise_channel(sp, Channel::vertical, o);
  REQUIRE(a.value.size() == b.value.size());
  CHECK(std::memcmp(a.value.data(), b.value.data(), a.value.size() * sizeof(double)) == 0);
  CHECK(std::memcmp(a.slope.data(), b.slope.data(), a.slope.size() * sizeof(double)) == 0);
  o.seed = 8;
  const SampledChannel c = synthesise_channel(sp, Channel::vertical, o);
  double diff = 0, ref = 0;
  for (std::size_t j = 0; j < a.value.size(); ++j) {
    diff += (a.value[j] - c.value[j]) * (a.value[j] - c.value[j]);
    ref += a.value[j] * a.value[j];
  }
  CHECK(diff > 0.5 * ref);  // independent samples: E[diff] = 2 ref
  // Channels draw independent streams: vertical and lateral of one seed differ.
  o.seed = 7;
  const SampledChannel l = synthesise_channel(sp, Channel::lateral, o);
  double corr = 0, nl = 0;
  for (std::size_t j = 0; j < a.value.size(); ++j) {
    corr += a.value[j] * l.value[j];
    nl += l.value[j] * l.value[j];
  }
  CHECK(std::abs(corr) / std::sqrt(ref * nl) < 0.3);
  // The component built twice evaluates identically between grid points too.
  const PsdIrregularity p1(sp, {Channel::lateral, Channel::gauge}, o), p2(sp, {Channel::lateral, Channel::gauge}, o);
  for (double s = 0.0; s < 3000; s += 17.123) {
    IrregularityState x, y;
    p1.add_to(s, x);
    p2.add_to(s, y);
    CHECK(std::memcmp(&x, &y, sizeof x) == 0);
  }
}

TEST_CASE("slopes are the derivative of the values and interpolation and tapers hold", "[tracks][psd_synthesis]") {
  const TrackSpectrum sp = TrackSpectrum::named("erri_high");
  SynthesisOptions o;
  o.s_begin = 100;
  o.s_end = 1100;
  o.taper = 25;
  o.seed = 3;
  const PsdIrregularity p(sp, {Channel::vertical}, o);
  const SampledChannel g = synthesise_channel(sp, Channel::vertical, o);
  double worst_fd = 0, scale = 0;
  for (double s = 101.0; s < 1099.0; s += 3.3) {
    const double h = 1e-3;
    IrregularityState a, b, c;
    p.add_to(s - h, a);
    p.add_to(s, b);
    p.add_to(s + h, c);
    const double fd = (c[Channel::vertical] - a[Channel::vertical]) / (2 * h);
    worst_fd = std::max(worst_fd, std::abs(b.slope_of(Channel::vertical) - fd));
    scale = std::max(scale, std::abs(fd));
  }
  CHECK(worst_fd < 1e-4 * scale);
  // Grid points are reproduced exactly by the Hermite interpolant.
  for (std::size_t j = 0; j < g.value.size(); j += 97) {
    IrregularityState st;
    p.add_to(g.s0 + static_cast<double>(j) * g.step, st);
    CHECK(st[Channel::vertical] == Approx(g.value[j]).margin(1e-15));
  }
  // Zero value and slope at both ends, full amplitude inside.
  IrregularityState e0, e1, out;
  p.add_to(100.0, e0);
  p.add_to(1100.0, e1);
  p.add_to(1100.5, out);
  CHECK(std::abs(e0[Channel::vertical]) < 1e-15);
  CHECK(std::abs(e0.slope_of(Channel::vertical)) < 1e-15);
  CHECK(std::abs(e1[Channel::vertical]) < 1e-8);  // the last grid point lies past s_end (step 0.1875 m)
  CHECK(out[Channel::vertical] == 0.0);
}

TEST_CASE("inconsistent synthesis options are refused", "[tracks][psd_synthesis]") {
  const TrackSpectrum sp = TrackSpectrum::named("erri_low");
  SynthesisOptions o;
  o.wavelength_min = 10;
  o.wavelength_max = 5;
  CHECK_THROWS_AS(synthesise_channel(sp, Channel::lateral, o), railsim::InputError);
  o = SynthesisOptions{};
  o.step = 1.0;  // > lambda_min / 4
  CHECK_THROWS_WITH(synthesise_channel(sp, Channel::lateral, o), Catch::Contains("wavelength_min / 4"));
  o = SynthesisOptions{};
  o.s_end = 30;
  o.taper = 20;
  CHECK_THROWS_WITH(synthesise_channel(sp, Channel::lateral, o), Catch::Contains("taper"));
}
