// Dominant frequency of a signal (results/spectrum.hpp) for sums of sines
// with known frequencies.
#include <catch2/catch.hpp>

#include <cmath>

#include "results/spectrum.hpp"

using namespace railsim::results;

TEST_CASE("dominant frequency finds the strongest sine inside the range", "[results][spectrum]") {
  const double fs = 200.0;
  std::vector<double> x(1600);  // 8 s
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double t = static_cast<double>(i) / fs;
    x[i] = 5.0 + 3.0 * std::sin(2 * M_PI * 4.52 * t) + 1.0 * std::sin(2 * M_PI * 9.0 * t + 0.4) +
           6.0 * std::sin(2 * M_PI * 0.3 * t);  // a large slow component outside the range
  }
  const auto p = dominant_frequency(x, fs, 1.0, 15.0);
  // Padded bins are fs / 4096 = 0.049 Hz; the parabola refines well below that.
  CHECK(p.resolution == Approx(fs / 4096.0));
  CHECK(p.frequency == Approx(4.52).margin(0.01));
  // Restricting the range to 7..15 Hz finds the weaker 9 Hz sine.
  CHECK(dominant_frequency(x, fs, 7.0, 15.0).frequency == Approx(9.0).margin(0.01));
  CHECK(p.power > p.mean_power);
}

TEST_CASE("dominant frequency refuses bad input", "[results][spectrum]") {
  CHECK_THROWS_AS(dominant_frequency(std::vector<double>(4, 0.0), 100.0, 1.0, 10.0), std::invalid_argument);
  CHECK_THROWS_AS(dominant_frequency(std::vector<double>(100, 0.0), 100.0, 60.0, 70.0), std::invalid_argument);
  CHECK_THROWS_AS(dominant_frequency(std::vector<double>(100, 0.0), 0.0, 1.0, 10.0), std::invalid_argument);
}
