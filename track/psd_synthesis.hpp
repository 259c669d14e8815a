// Synthesis of random track irregularities from a one-sided PSD
// (physics-reference §10.4, random-phase harmonic sum evaluated by IFFT):
//
//   r(s) = sum_k a_k cos(Omega_k (s - s_begin) + phi_k),   a_k = sqrt(2 S(Omega_k) dOmega)
//
// on the FFT grid Omega_k = k dOmega, dOmega = 2 pi / L_rec, keeping only the
// band lambda_min <= 2 pi / Omega_k <= lambda_max. Expected variance
// sum_k S(Omega_k) dOmega (= the band variance of the PSD). The phases phi_k are
// i.i.d. uniform in [0, 2 pi), drawn from std::mt19937_64 seeded by
// std::seed_seq{seed, channel}: the same seed gives the same track bit for bit
// (the phase is built from the raw 53 high bits, no library distribution), and
// each channel has its own independent stream. Values and exact slopes
// r'(s) = -sum a_k Omega_k sin(...) come from two complex-to-real FFTW
// transforms on a grid of step h (default lambda_min / 16) over a record
// L_rec >= max(s_end - s_begin, 8 lambda_max) (a power of two of samples, so
// the sample is not periodic over the track). Between grid points the sample
// is interpolated by cubic Hermite splines on (value, slope) (Boost.Math),
// relative error ~ (2 pi h / lambda)^4 / 384 < 1e-4 at lambda_min.
// Both ends are tapered over `taper` metres by the quintic smooth-step
// w = 10t^3 - 15t^4 + 6t^5 (value and slope by the product rule), so the
// irregularity starts and ends at zero without a transient.
#pragma once

#include <boost/math/interpolators/cubic_hermite.hpp>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "config/yaml_input.hpp"
#include "track/irregularity.hpp"
#include "track/irregularity_registry.hpp"
#include "track/track_psd.hpp"

namespace railsim::track {

struct SynthesisOptions {
  double wavelength_min = 3.0;    // [m]
  double wavelength_max = 150.0;  // [m]
  double s_begin = 0.0;           // [m]
  double s_end = 1000.0;          // [m]
  double taper = 20.0;            // [m] at each end (0: none)
  double step = 0.0;              // grid step [m]; 0 -> wavelength_min / 16
  double scale = 1.0;             // multiplies every amplitude
  std::uint64_t seed = 1;
};

// One synthesised channel on its uniform grid (before interpolation).
struct SampledChannel {
  double s0 = 0.0, step = 0.0;
  std::vector<double> value, slope;  // [m], [-]
};

// Synthesise one channel of `spectrum`. Throws InputError on inconsistent options.
SampledChannel synthesise_channel(const TrackSpectrum& spectrum, Channel channel, const SynthesisOptions& options);

// An irregularity component holding synthesised channels.
class PsdIrregularity final : public IrregularityComponent {
 public:
  PsdIrregularity(const TrackSpectrum& spectrum, const std::vector<Channel>& channels, const SynthesisOptions& options);
  void add_to(double s, IrregularityState& out) const override;
  double s_begin() const override { return options_.s_begin; }
  double s_end() const override { return options_.s_end; }
  std::string describe() const override;

 private:
  using Spline = boost::math::interpolators::cardinal_cubic_hermite<std::vector<double>>;
  std::string spectrum_name_;
  SynthesisOptions options_;
  std::array<std::optional<Spline>, kChannelCount> splines_;
  double s_last_ = 0.0;  // last grid point (>= s_end)
};

// Registry parser ("psd").
std::unique_ptr<IrregularityComponent> parse_psd_irregularity(const config::InputNode& node,
                                                              const IrregularityContext& context);

}  // namespace railsim::track
