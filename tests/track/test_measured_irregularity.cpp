// Measured irregularities from CSV: values reproduced at the measuring points
// (mm -> m), monotone interpolation between them, zero outside, and clear
// errors naming the file and line for unsorted distances, missing columns,
// non-numbers and ragged rows (files in tests/data/tracks/).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"
#include "test_support.hpp"
#include "track/measured_irregularity.hpp"

using namespace railsim::track;
using railsim::test::data_path;

TEST_CASE("a measured file is read and interpolated", "[tracks][measured]") {
  MeasuredTable t = read_measured_irregularity(data_path("tracks/measured_good.csv"));
  REQUIRE(t.s.size() == 6);
  CHECK(t.channels[index(Channel::lateral)]);
  CHECK(t.channels[index(Channel::vertical)]);
  CHECK_FALSE(t.channels[index(Channel::gauge)]);
  const std::vector<double> lat = {0.0, 1.5e-3, 2.0e-3, 1.0e-3, -0.5e-3, -1.0e-3};
  const MeasuredIrregularity m(std::move(t), 100.0);
  CHECK(m.s_begin() == 100.0);
  CHECK(m.s_end() == 105.0);
  for (std::size_t i = 0; i < lat.size(); ++i) {
    IrregularityState st;
    m.add_to(100.0 + static_cast<double>(i), st);
    CHECK(st[Channel::lateral] == Approx(lat[i]).margin(1e-15));
  }
  // Monotone (PCHIP): between 1.0 and 2.0 mm the value stays within them.
  for (double s = 101.0; s <= 102.0; s += 0.05) {
    IrregularityState st;
    m.add_to(s, st);
    CHECK(st[Channel::lateral] >= 1.5e-3 - 1e-15);
    CHECK(st[Channel::lateral] <= 2.0e-3 + 1e-15);
  }
  // Slope matches finite differences.
  IrregularityState a, b, c;
  m.add_to(103.3 - 1e-5, a);
  m.add_to(103.3, b);
  m.add_to(103.3 + 1e-5, c);
  CHECK(b.slope_of(Channel::vertical) == Approx((c[Channel::vertical] - a[Channel::vertical]) / 2e-5).epsilon(1e-5));
}

TEST_CASE("bad measured files give errors naming file and line", "[tracks][measured]") {
  auto msg = [](const char* f) {
    try {
      read_measured_irregularity(data_path(std::string("tracks/") + f));
    } catch (const railsim::InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string unsorted = msg("measured_unsorted.csv");
  CHECK_THAT(unsorted, Catch::Contains("measured_unsorted.csv:5:") && Catch::Contains("sorted"));
  const std::string nan = msg("measured_not_number.csv");
  CHECK_THAT(nan, Catch::Contains("measured_not_number.csv:4:") && Catch::Contains("'abc'") &&
                      Catch::Contains("column 'lateral'"));
  const std::string missing = msg("measured_missing_s.csv");
  CHECK_THAT(missing, Catch::Contains("measured_missing_s.csv:1:") && Catch::Contains("distance"));
  const std::string ragged = msg("measured_ragged.csv");
  CHECK_THAT(ragged, Catch::Contains("measured_ragged.csv:3:") && Catch::Contains("found 2"));
  CHECK_THAT(msg("does_not_exist.csv"), Catch::Contains("cannot open"));
  // A value beyond any track irregularity (1e300 mm ran, and 'rms = inf mm' was printed).
  CHECK_THAT(msg("measured_huge.csv"), Catch::Contains("measured_huge.csv:4: column 'lateral': 1e+300 mm outside "
                                                       "[-200, 200] mm"));
}
