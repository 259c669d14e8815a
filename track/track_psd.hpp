// Track irregularity power spectral densities (physics-reference §10.2-10.3).
//
// Convention (stated once, used everywhere in railsim): S(Omega) is the
// ONE-SIDED PSD over the angular spatial frequency Omega = 2 pi / lambda
// [rad/m], in m^2/(rad/m), so that the variance is
//   sigma^2 = integral_0^inf S(Omega) dOmega.
// (Reading checked against the reference's sanity numbers: ERRI low level,
// 3-150 m: sigma_v = 2.86 mm, sigma_a = 2.08 mm.) Convert to cyclic frequency
// with S_f(f) = 2 pi S(2 pi f).
//
// Channels (irregularity.hpp): lateral (alignment), vertical (level),
// cross_level as the HEIGHT difference of the rails [m] (the angle PSD times
// (2b)^2), gauge.
//
// ERRI B176 (low / high level), Omega_c = 0.8246, Omega_r = 0.0206,
// Omega_s = 0.4380 rad/m, b = 0.75 m:
//   vertical    A_v Oc^2 / ((O^2 + Or^2)(O^2 + Oc^2))
//   lateral     A_a Oc^2 / ((O^2 + Or^2)(O^2 + Oc^2))
//   cross-level (2b)^2 (A_v / b^2) Oc^2 O^2 / ((O^2 + Or^2)(O^2 + Oc^2)(O^2 + Os^2))
//   gauge       A_g Oc^2 O^2 / ((O^2 + Or^2)(O^2 + Oc^2)(O^2 + Os^2))
//   low:  A_a = 2.119e-7, A_v = 4.032e-7, A_g = 0.532e-7 m rad
//   high: A_a = 6.125e-7, A_v = 1.080e-6, A_g = 1.032e-7 m rad
// FRA classes 1-6 (k = 0.25, A in cm^2 rad/m, result x 1e-4 -> m^2/(rad/m)):
//   vertical    k A_v Oc^2 / (O^2 (O^2 + Oc^2))
//   lateral     k A_a Oc^2 / (O^2 (O^2 + Oc^2))
//   cross-level, gauge  4 k A_v Oc^2 / ((O^2 + Oc^2)(O^2 + Os^2))
// (table of A_v, A_a, Omega_s, Omega_c per class in track_psd.cpp). The FRA
// vertical and lateral forms diverge as 1/Omega^2: always band-limit.
#pragma once

#include <string>
#include <string_view>

#include "track/irregularity.hpp"

namespace railsim::track {

enum class SpectrumFamily { erri, fra };

class TrackSpectrum {
 public:
  // "erri_low", "erri_high", "fra_1" ... "fra_6"; unknown -> InputError listing them.
  static TrackSpectrum named(std::string_view name);
  // One-sided PSD [m^2/(rad/m)] of a channel at Omega [rad/m] (Omega > 0).
  double psd(Channel channel, double omega) const;
  // Variance [m^2] of a channel over wavelengths [lambda_min, lambda_max] [m]
  // (adaptive Gauss-Kronrod quadrature of psd()).
  double variance(Channel channel, double lambda_min, double lambda_max) const;
  const std::string& name() const { return name_; }
  SpectrumFamily family() const { return family_; }

 private:
  std::string name_;
  SpectrumFamily family_ = SpectrumFamily::erri;
  // ERRI: A_a, A_v, A_g [m rad]; FRA: A_a, A_v [cm^2 rad/m].
  double A_a_ = 0.0, A_v_ = 0.0, A_g_ = 0.0;
  double omega_c_ = 0.0, omega_r_ = 0.0, omega_s_ = 0.0;
};

// "erri_low, erri_high, fra_1, ..., fra_6".
std::string track_spectrum_names();

}  // namespace railsim::track
