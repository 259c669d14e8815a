// Dominant frequency of a signal; see spectrum.hpp.
#include "results/spectrum.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>

#include "core/errors.hpp"
#include "core/fftw_planner_lock.hpp"

namespace railsim::results {

namespace {
struct FftwFree {
  void operator()(void* p) const { fftw_free(p); }
};
}  // namespace

SpectralPeak dominant_frequency(const std::vector<double>& x, double fs, double f_min, double f_max) {
  const std::size_t n = x.size();
  if (n < 8) throw std::invalid_argument("dominant_frequency: need at least 8 samples");
  if (!(fs > 0.0)) throw std::invalid_argument("dominant_frequency: sample rate must be > 0");
  f_max = std::min(f_max, 0.5 * fs);
  if (!(f_min >= 0.0) || !(f_max > f_min))
    throw std::invalid_argument("dominant_frequency: empty frequency range [" + std::to_string(f_min) + ", " +
                                std::to_string(f_max) + "] Hz");
  std::size_t m = 1;
  while (m < 2 * n) m <<= 1;
  std::unique_ptr<double, FftwFree> in(static_cast<double*>(fftw_malloc(sizeof(double) * m)));
  std::unique_ptr<fftw_complex, FftwFree> out(
      static_cast<fftw_complex*>(fftw_malloc(sizeof(fftw_complex) * (m / 2 + 1))));
  if (!in || !out)
    throw NumericalError("dominant_frequency: out of memory for an FFT of " + std::to_string(m) + " samples");
  double mean = 0.0;
  for (double v : x) mean += v;
  mean /= static_cast<double>(n);
  const double pi = 3.14159265358979323846;
  for (std::size_t i = 0; i < m; ++i) {
    if (i < n) {
      const double w = 0.5 * (1.0 - std::cos(2.0 * pi * static_cast<double>(i) / static_cast<double>(n - 1)));
      in.get()[i] = (x[i] - mean) * w;
    } else {
      in.get()[i] = 0.0;
    }
  }
  fftw_plan plan = nullptr;
  {
    std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    plan = fftw_plan_dft_r2c_1d(static_cast<int>(m), in.get(), out.get(), FFTW_ESTIMATE);
  }
  if (!plan)
    throw NumericalError("dominant_frequency: FFTW returned no plan (NULL) for a real transform of " +
                         std::to_string(m) + " samples (out of memory?)");
  fftw_execute(plan);
  {
    std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    fftw_destroy_plan(plan);
  }
  const double df = fs / static_cast<double>(m);
  auto power = [&](std::size_t k) { return out.get()[k][0] * out.get()[k][0] + out.get()[k][1] * out.get()[k][1]; };
  const auto k0 = static_cast<std::size_t>(std::ceil(f_min / df));
  const auto k1 = std::min(m / 2, static_cast<std::size_t>(std::floor(f_max / df)));
  SpectralPeak p;
  p.resolution = df;
  if (k1 < k0) return p;
  std::size_t best = k0;
  double sum = 0.0;
  for (std::size_t k = k0; k <= k1; ++k) {
    sum += power(k);
    if (power(k) > power(best)) best = k;
  }
  p.mean_power = sum / static_cast<double>(k1 - k0 + 1);
  p.power = power(best);
  double shift = 0.0;
  if (best > 0 && best < m / 2) {
    const double a = power(best - 1), b = power(best), c = power(best + 1);
    const double den = a - 2.0 * b + c;
    if (den < 0.0) shift = std::clamp(0.5 * (a - c) / den, -0.5, 0.5);
  }
  p.frequency = (static_cast<double>(best) + shift) * df;
  return p;
}

}  // namespace railsim::results
