// Dominant frequency of a uniformly sampled signal: the peak of its
// periodogram (FFTW real-to-complex transform) inside a frequency range.
//
// Method (Press et al., Numerical Recipes 3rd ed. 2007, §13.4 "Power spectrum
// estimation using the FFT"): the mean is removed, a Hann window applied,
// the record zero-padded to at least twice its length (a power of two) so the
// bins are fine, |X_k|^2 computed with FFTW, the largest bin in [f_min,
// f_max] located and refined by a parabola through it and its neighbours.
// Frequencies in Hz. FFTW's planner is serialised by the program-wide lock
// (core/fftw_planner_lock.hpp).
#pragma once

#include <vector>

namespace railsim::results {

struct SpectralPeak {
  double frequency = 0.0;     // [Hz]
  double power = 0.0;         // periodogram value at the peak (arbitrary units)
  double resolution = 0.0;    // bin spacing of the padded transform [Hz]
  double mean_power = 0.0;    // mean periodogram value over [f_min, f_max]
};

// Throws std::invalid_argument for fewer than 8 samples, fs <= 0 or an empty
// frequency range (f_min >= f_max, f_min >= fs/2).
SpectralPeak dominant_frequency(const std::vector<double>& x, double fs, double f_min, double f_max);

}  // namespace railsim::results
