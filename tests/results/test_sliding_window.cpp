// Sliding-window means and rms against closed-form integrals.
#include <catch2/catch.hpp>

#include <cmath>

#include "results/sliding_window.hpp"

using namespace railsim::results;

namespace {
std::vector<double> linspace(double a, double b, int n) {
  std::vector<double> v(n);
  for (int i = 0; i < n; ++i) v[i] = a + (b - a) * i / (n - 1);
  return v;
}
}  // namespace

TEST_CASE("2 m sliding mean of a sine equals the analytic window average", "[results]") {
  // mean over [c-w/2, c+w/2] of sin(kx) = sin(kc) sin(kw/2)/(kw/2)
  const double k = 2.0 * M_PI / 7.0, w = 2.0;
  const auto x = linspace(0.0, 100.0, 20001);
  std::vector<double> y;
  for (double xi : x) y.push_back(std::sin(k * xi));
  const auto m = sliding_mean(x, y, w, 0.5);
  REQUIRE(m.centre.size() == 197);  // centres 1.0, 1.5, ..., 99.0
  const double factor = std::sin(k * w / 2) / (k * w / 2);
  for (std::size_t i = 0; i < m.centre.size(); ++i)
    CHECK(m.value[i] == Approx(std::sin(k * m.centre[i]) * factor).margin(2e-6));
}

TEST_CASE("sliding mean of a step is the covered fraction (known 2 m mean)", "[results]") {
  // Y/Q = 0 before x = 10 m, 1.0 after: the 2 m mean rises linearly over 9..11 m.
  const std::vector<double> x = {0.0, 9.999999, 10.0, 30.0};
  const std::vector<double> y = {0.0, 0.0, 1.0, 1.0};
  const auto m = sliding_mean(x, y, 2.0, 0.5);
  for (std::size_t i = 0; i < m.centre.size(); ++i) {
    const double c = m.centre[i];
    const double expected = std::clamp((c + 1.0 - 10.0) / 2.0, 0.0, 1.0);
    CHECK(m.value[i] == Approx(expected).margin(1e-6));
  }
}

TEST_CASE("sliding rms of a sine over whole periods is A/sqrt(2)", "[results]") {
  const auto x = linspace(0.0, 40.0, 40001);
  std::vector<double> y;
  for (double xi : x) y.push_back(3.0 * std::sin(2.0 * M_PI * xi / 4.0));
  const auto r = sliding_rms(x, y, 8.0, 1.0);
  for (double v : r.value) CHECK(v == Approx(3.0 / std::sqrt(2.0)).epsilon(1e-5));
}

TEST_CASE("percentile by linear interpolation of order statistics", "[results]") {
  const std::vector<double> v = {5, 1, 4, 2, 3};
  CHECK(percentile(v, 0) == 1.0);
  CHECK(percentile(v, 100) == 5.0);
  CHECK(percentile(v, 50) == 3.0);
  CHECK(percentile(v, 99.85) == Approx(4.994));
  CHECK(std::isnan(percentile({}, 50)));
}

TEST_CASE("sliding window rejects unsorted abscissae", "[results]") {
  CHECK_THROWS_AS(sliding_mean({0.0, 2.0, 1.0}, {0.0, 0.0, 0.0}, 1.0, 0.5), std::invalid_argument);
}

TEST_CASE("several percentiles at once equal the single ones (0.15 %, 50 %, 99.85 %)", "[results]") {
  // 11 values 0..10: position (n - 1) p / 100 = 10 p / 100, linear between order statistics.
  std::vector<double> v;
  for (int i = 10; i >= 0; --i) v.push_back(i);
  const auto p = percentiles(v, {0.15, 50.0, 99.85, 100.0});
  REQUIRE(p.size() == 4);
  CHECK(p[0] == Approx(0.015));
  CHECK(p[1] == Approx(5.0));
  CHECK(p[2] == Approx(9.985));
  CHECK(p[3] == Approx(10.0));
  for (double q : {0.15, 50.0, 99.85}) CHECK(percentiles(v, {q})[0] == Approx(percentile(v, q)));
  CHECK(std::isnan(percentiles({}, {50.0})[0]));
}
