// Track irregularity PSDs (ERRI B176, FRA classes); see track_psd.hpp.
#include "track/track_psd.hpp"

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <array>
#include <cmath>

#include "core/errors.hpp"

namespace railsim::track {

namespace {

constexpr double kPi = 3.14159265358979323846;

// ERRI B176 constants (physics-reference §10.2).
constexpr double kErriOc = 0.8246, kErriOr = 0.0206, kErriOs = 0.4380, kErriB = 0.75;

struct FraClass {
  double A_v, A_a, omega_s, omega_c;  // cm^2 rad/m, rad/m
};
// FRA classes 1-6 (physics-reference §10.3).
constexpr std::array<FraClass, 6> kFra = {{
    {1.2107, 3.3634, 0.6046, 0.8245},
    {1.0181, 1.2107, 0.9308, 0.8245},
    {0.6816, 0.4128, 0.8520, 0.8245},
    {0.5376, 0.3027, 1.1312, 0.8245},
    {0.2095, 0.0762, 0.8209, 0.8245},
    {0.0339, 0.0339, 0.4380, 0.8245},
}};
constexpr double kFraK = 0.25;
constexpr double kCm2ToM2 = 1e-4;

}  // namespace

std::string track_spectrum_names() { return "erri_low, erri_high, fra_1, fra_2, fra_3, fra_4, fra_5, fra_6"; }

TrackSpectrum TrackSpectrum::named(std::string_view name) {
  TrackSpectrum t;
  t.name_ = std::string(name);
  if (name == "erri_low" || name == "erri_high") {
    const bool low = name == "erri_low";
    t.family_ = SpectrumFamily::erri;
    t.A_a_ = low ? 2.119e-7 : 6.125e-7;
    t.A_v_ = low ? 4.032e-7 : 1.080e-6;
    t.A_g_ = low ? 0.532e-7 : 1.032e-7;
    t.omega_c_ = kErriOc;
    t.omega_r_ = kErriOr;
    t.omega_s_ = kErriOs;
    return t;
  }
  if (name.size() == 5 && name.substr(0, 4) == "fra_" && name[4] >= '1' && name[4] <= '6') {
    const FraClass& c = kFra[static_cast<std::size_t>(name[4] - '1')];
    t.family_ = SpectrumFamily::fra;
    t.A_v_ = c.A_v;
    t.A_a_ = c.A_a;
    t.omega_s_ = c.omega_s;
    t.omega_c_ = c.omega_c;
    return t;
  }
  throw InputError("unknown track spectrum '" + std::string(name) + "' (known: " + track_spectrum_names() + ")");
}

double TrackSpectrum::psd(Channel channel, double omega) const {
  const double o2 = omega * omega;
  const double c2 = omega_c_ * omega_c_, s2 = omega_s_ * omega_s_, r2 = omega_r_ * omega_r_;
  if (family_ == SpectrumFamily::erri) {
    const double base = c2 / ((o2 + r2) * (o2 + c2));
    switch (channel) {
      case Channel::vertical: return A_v_ * base;
      case Channel::lateral: return A_a_ * base;
      case Channel::cross_level:
        return (2.0 * kErriB) * (2.0 * kErriB) * (A_v_ / (kErriB * kErriB)) * base * o2 / (o2 + s2);
      case Channel::gauge: return A_g_ * base * o2 / (o2 + s2);
    }
    return 0.0;
  }
  switch (channel) {
    case Channel::vertical: return kCm2ToM2 * kFraK * A_v_ * c2 / (o2 * (o2 + c2));
    case Channel::lateral: return kCm2ToM2 * kFraK * A_a_ * c2 / (o2 * (o2 + c2));
    case Channel::cross_level:
    case Channel::gauge: return kCm2ToM2 * 4.0 * kFraK * A_v_ * c2 / ((o2 + c2) * (o2 + s2));
  }
  return 0.0;
}

double TrackSpectrum::variance(Channel channel, double lambda_min, double lambda_max) const {
  const double a = 2.0 * kPi / lambda_max, b = 2.0 * kPi / lambda_min;
  // Integrate in log(Omega): the spectra span decades.
  auto f = [&](double x) {
    const double o = std::exp(x);
    return psd(channel, o) * o;
  };
  return boost::math::quadrature::gauss_kronrod<double, 61>::integrate(f, std::log(a), std::log(b), 15, 1e-12);
}

}  // namespace railsim::track
