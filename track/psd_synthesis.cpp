// Random track irregularities synthesised from a PSD by IFFT; see psd_synthesis.hpp.
#include "track/psd_synthesis.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <random>

#include "core/errors.hpp"
#include "core/fftw_planner_lock.hpp"

namespace railsim::track {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr std::size_t kMaxFftSize = std::size_t{1} << 25;  // 32 Mi samples (~0.5 GB of work arrays)

// FFTW's planner is not thread-safe; execution is. Plan creation and
// destruction take the program-wide planner lock (core/fftw_planner_lock.hpp);
// FFTW_ESTIMATE: deterministic plans.

struct FftwFree {
  void operator()(void* p) const { fftw_free(p); }
};
template <class T>
using FftwBuffer = std::unique_ptr<T, FftwFree>;

// Complex-to-real inverse transform (unnormalised): out_j = sum_k X_k e^{2 pi i jk/N} with Hermitian extension.
void inverse_fft(fftw_complex* in, double* out, int n) {
  fftw_plan plan = nullptr;
  {
    std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    plan = fftw_plan_dft_c2r_1d(n, in, out, FFTW_ESTIMATE);
  }
  if (!plan)
    throw NumericalError("psd synthesis: FFTW returned no plan (NULL) for an inverse real transform of " +
                         std::to_string(n) + " samples (out of memory?)");
  fftw_execute(plan);
  std::lock_guard<std::mutex> lock(fftw_planner_mutex());
  fftw_destroy_plan(plan);
}

// Quintic smooth-step taper w(s) and dw/ds for the range [a, b] with taper length T.
void taper_at(double s, double a, double b, double T, double& w, double& dw) {
  w = 1.0;
  dw = 0.0;
  if (T <= 0.0) return;
  auto step = [](double t, double& f, double& df) {
    t = std::clamp(t, 0.0, 1.0);
    f = t * t * t * (10.0 + t * (-15.0 + 6.0 * t));
    df = 30.0 * t * t * (1.0 - t) * (1.0 - t);
  };
  double f = 1.0, df = 0.0;
  if (s - a < T) {
    step((s - a) / T, f, df);
    w = f;
    dw = df / T;
  } else if (b - s < T) {
    step((b - s) / T, f, df);
    w = f;
    dw = -df / T;
  }
}

void check_options(const SynthesisOptions& o) {
  using config::format_number;
  if (!(o.wavelength_min > 0.0) || !(o.wavelength_max > o.wavelength_min))
    throw InputError("psd synthesis: need 0 < wavelength_min < wavelength_max (got " +
                     format_number(o.wavelength_min) + ", " + format_number(o.wavelength_max) + ")");
  if (!(o.s_end > o.s_begin))
    throw InputError("psd synthesis: empty range s = " + format_number(o.s_begin) + " .. " + format_number(o.s_end));
  if (o.taper < 0.0 || 2.0 * o.taper > o.s_end - o.s_begin)
    throw InputError("psd synthesis: taper " + format_number(o.taper) +
                     " m must be >= 0 and at most half the range (" + format_number(0.5 * (o.s_end - o.s_begin)) +
                     " m)");
  if (o.step < 0.0 || o.step > 0.25 * o.wavelength_min)
    throw InputError("psd synthesis: step " + format_number(o.step) + " m must be <= wavelength_min / 4 (" +
                     format_number(0.25 * o.wavelength_min) + " m)");
}

}  // namespace

SampledChannel synthesise_channel(const TrackSpectrum& spectrum, Channel channel, const SynthesisOptions& o) {
  check_options(o);
  const double h = o.step > 0.0 ? o.step : o.wavelength_min / 16.0;
  const double range = o.s_end - o.s_begin;
  const double record = std::max(range, 8.0 * o.wavelength_max);
  std::size_t n = 2;
  while (static_cast<double>(n) * h < record + h) {
    n *= 2;
    if (n > kMaxFftSize)
      throw InputError("psd synthesis: " + config::format_number(record) + " m at a step of " +
                       config::format_number(h) + " m needs more than 2^25 samples; shorten the range or "
                       "raise wavelength_min");
  }
  const int N = static_cast<int>(n);
  const double dOmega = 2.0 * kPi / (static_cast<double>(n) * h);
  const double omega_min = 2.0 * kPi / o.wavelength_max * (1.0 - 1e-12);
  const double omega_max = 2.0 * kPi / o.wavelength_min * (1.0 + 1e-12);

  const std::size_t nc = n / 2 + 1;
  FftwBuffer<fftw_complex> X(fftw_alloc_complex(nc)), Y(fftw_alloc_complex(nc));
  FftwBuffer<double> x(fftw_alloc_real(n)), y(fftw_alloc_real(n));
  if (!X || !Y || !x || !y) throw NumericalError("psd synthesis: out of memory for " + std::to_string(n) + " samples");
  std::fill_n(&X.get()[0][0], 2 * nc, 0.0);
  std::fill_n(&Y.get()[0][0], 2 * nc, 0.0);

  // Independent, reproducible stream per (seed, channel).
  std::seed_seq seq{static_cast<std::uint32_t>(o.seed & 0xffffffffu), static_cast<std::uint32_t>(o.seed >> 32),
                    static_cast<std::uint32_t>(index(channel))};
  std::mt19937_64 rng(seq);
  for (std::size_t k = 1; k + 1 < nc; ++k) {
    const double omega = static_cast<double>(k) * dOmega;
    if (omega < omega_min || omega > omega_max) continue;
    const double phase = 2.0 * kPi * static_cast<double>(rng() >> 11) * 0x1.0p-53;
    const double a = o.scale * std::sqrt(2.0 * spectrum.psd(channel, omega) * dOmega);
    const double re = 0.5 * a * std::cos(phase), im = 0.5 * a * std::sin(phase);
    X.get()[k][0] = re;
    X.get()[k][1] = im;
    Y.get()[k][0] = -omega * im;  // i Omega X_k
    Y.get()[k][1] = omega * re;
  }
  inverse_fft(X.get(), x.get(), N);
  inverse_fft(Y.get(), y.get(), N);

  SampledChannel out;
  out.s0 = o.s_begin;
  out.step = h;
  const std::size_t m = static_cast<std::size_t>(std::ceil(range / h)) + 1;
  out.value.resize(m);
  out.slope.resize(m);
  for (std::size_t j = 0; j < m; ++j) {
    const double s = o.s_begin + static_cast<double>(j) * h;
    double w = 0.0, dw = 0.0;
    if (s <= o.s_end) taper_at(s, o.s_begin, o.s_end, o.taper, w, dw);
    const double v = x.get()[j], dv = y.get()[j];
    out.value[j] = w * v;
    out.slope[j] = w * dv + dw * v;
  }
  return out;
}

PsdIrregularity::PsdIrregularity(const TrackSpectrum& spectrum, const std::vector<Channel>& channels,
                                 const SynthesisOptions& options)
    : spectrum_name_(spectrum.name()), options_(options) {
  for (Channel c : channels) {
    SampledChannel sc = synthesise_channel(spectrum, c, options);
    s_last_ = sc.s0 + static_cast<double>(sc.value.size() - 1) * sc.step;
    splines_[static_cast<std::size_t>(index(c))].emplace(std::move(sc.value), std::move(sc.slope), sc.s0, sc.step);
  }
}

void PsdIrregularity::add_to(double s, IrregularityState& out) const {
  if (s < options_.s_begin || s > options_.s_end) return;
  const double t = std::min(s, s_last_);
  for (Channel c : kAllChannels) {
    const auto& sp = splines_[static_cast<std::size_t>(index(c))];
    if (sp) out.add(c, (*sp)(t), sp->prime(t));
  }
}

std::string PsdIrregularity::describe() const {
  std::string ch;
  for (Channel c : kAllChannels)
    if (splines_[static_cast<std::size_t>(index(c))]) ch += (ch.empty() ? "" : "+") + std::string(channel_name(c));
  char buf[200];
  std::snprintf(buf, sizeof buf, " wavelengths %.4g-%.4g m, s = %.6g-%.6g m, seed %llu", options_.wavelength_min,
                options_.wavelength_max, options_.s_begin, options_.s_end,
                static_cast<unsigned long long>(options_.seed));
  return "psd " + spectrum_name_ + " (" + ch + ")" + buf;
}

std::unique_ptr<IrregularityComponent> parse_psd_irregularity(const config::InputNode& node,
                                                              const IrregularityContext& context) {
  node.allow_only({"type", "spectrum", "channels", "seed", "wavelength_min", "wavelength_max", "from", "to", "taper",
                   "step", "scale"});
  const config::InputNode sp = node.at("spectrum");
  TrackSpectrum spectrum;
  try {
    spectrum = TrackSpectrum::named(sp.as_string());
  } catch (const InputError&) {
    sp.fail("unknown spectrum '" + sp.as_string() + "' (known: " + track_spectrum_names() + ")");
  }
  std::vector<Channel> channels;
  if (auto chs = node.find("channels")) {
    for (const auto& e : chs->elements()) {
      const auto c = channel_from_name(e.as_string());
      if (!c) e.fail("unknown channel '" + e.as_string() + "' (allowed: lateral, vertical, cross_level, gauge)");
      if (std::find(channels.begin(), channels.end(), *c) != channels.end()) e.fail("channel listed twice");
      channels.push_back(*c);
    }
    if (channels.empty()) chs->fail("expected at least one channel");
  } else {
    channels.assign(kAllChannels.begin(), kAllChannels.end());
  }
  SynthesisOptions o;
  const config::InputNode seed = node.at("seed");
  const long sv = seed.as_integer();
  if (sv < 0) seed.fail("expected a non-negative integer (got " + seed.text() + ")");
  o.seed = static_cast<std::uint64_t>(sv);
  o.wavelength_min = node.has("wavelength_min") ? node.at("wavelength_min").as_in_range(0.1, 1000.0) : 3.0;
  o.wavelength_max = node.has("wavelength_max") ? node.at("wavelength_max").as_in_range(0.1, 10000.0) : 150.0;
  if (o.wavelength_max <= o.wavelength_min)
    node.at("wavelength_max").fail("must be greater than wavelength_min (" + config::format_number(o.wavelength_min) +
                                   " m)");
  o.s_begin = node.has("from") ? node.at("from").as_in_range(0.0, context.track_length) : 0.0;
  o.s_end = node.has("to") ? node.at("to").as_in_range(0.0, context.track_length) : context.track_length;
  if (o.s_end <= o.s_begin) node.at("to").fail("must be greater than 'from' (" + config::format_number(o.s_begin) + ")");
  const double half = 0.5 * (o.s_end - o.s_begin);
  o.taper = node.has("taper") ? node.at("taper").as_in_range(0.0, half) : std::min(20.0, half);
  if (auto st = node.find("step")) o.step = st->as_in_range(0.0, 0.25 * o.wavelength_min, true);
  o.scale = node.has("scale") ? node.at("scale").as_in_range(0.0, 100.0) : 1.0;
  return std::make_unique<PsdIrregularity>(spectrum, channels, o);
}

}  // namespace railsim::track
