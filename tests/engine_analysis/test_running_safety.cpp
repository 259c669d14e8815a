// Running-safety criteria against the Nadal table and hand-computed force histories.
#include <catch2/catch.hpp>

#include <cmath>

#include "engine/analysis/running_safety.hpp"
#include "results/csv_writer.hpp"
#include "test_support.hpp"

using namespace railsim::engine;

TEST_CASE("Nadal limit matches the printed table to its precision", "[safety]") {
  const auto t = railsim::results::read_csv(railsim::test::data_path("nadal_table.csv"));
  REQUIRE(t.rows.size() == 20);
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    const double g = t.number(i, "flange_angle_deg") * M_PI / 180.0;
    const double mu = t.number(i, "mu");
    CHECK(nadal_limit(g, mu) == Approx(t.number(i, "yq_limit")).margin(0.0006));
  }
  CHECK(weinstock_limit(70.0 * M_PI / 180.0, 0.36) == Approx(1.200 + 0.36).margin(0.0006));
}

TEST_CASE("Prud'homme limit: P0 = 160 kN gives 63.3 kN", "[safety]") {
  CHECK(prudhomme_limit(160e3) == Approx(63333.3).epsilon(1e-5));
  CHECK(prudhomme_limit(160e3, 0.85) == Approx(0.85 * 63333.3).epsilon(1e-5));
}

TEST_CASE("EN 14363 evaluation of a synthetic force history with a known 2 m mean", "[safety]") {
  // 100 m sampled every 0.01 m; between samples the signal is linear, so a plateau
  // spanning samples 40.00..41.00 m counts as 1.00 m plus two half-ramps of 0.01 m:
  // effective width 1.01 m. Left wheel: Q = 50 kN; Y = 45 kN on a 1 m long plateau at 40.0..41.0 m,
  // zero elsewhere. The best 2 m window covers the plateau fully: (Y/Q)_2m = (45/50) * 1/2 = 0.45.
  // A spike of Y/Q = 2 over 0.1 m at 70 m averages to 0.1 over 2 m and must not fail the check.
  // Right wheel: Q drops to 15 kN over 60..61 m: unloading (50-15)/50 = 0.7 > 0.6.
  AxleForces f;
  f.name = "axle 1";
  f.static_wheel_load = 50e3;
  for (int i = 0; i <= 10000; ++i) {
    const double x = i * 0.01;
    f.distance.push_back(x);
    double yl = (x >= 40.0 && x <= 41.0) ? 45e3 : 0.0;
    if (x >= 70.0 && x <= 70.1) yl = 100e3;
    f.Y_left.push_back(yl);
    f.Q_left.push_back(50e3);
    f.Y_right.push_back(-5e3);
    f.Q_right.push_back((x >= 60.0 && x <= 61.0) ? 15e3 : 50e3);
  }
  const auto s = evaluate_axle(f);
  CHECK(s.yq_left.max_abs == Approx(0.9 * 1.01 / 2.0).epsilon(1e-6));
  CHECK(s.yq_left.at_distance == Approx(40.5).margin(0.5));
  CHECK(s.yq_left.pass);
  // Right: Y/Q = -0.1 outside the dip and -1/3 over the dip: best window 0.1 + (1/3 - 0.1) * 1.01 / 2.
  CHECK(s.yq_right.max_abs == Approx(0.1 + (1.0 / 3.0 - 0.1) * 1.01 / 2.0).epsilon(1e-6));
  CHECK(s.max_unloading == Approx(0.7).epsilon(1e-9));
  CHECK(s.unloading_at == Approx(60.0).margin(0.02));
  CHECK_FALSE(s.unloading_pass);
  CHECK_FALSE(s.pass);
  // Sum Y: 45 - 5 = 40 kN over the plateau, -5 kN elsewhere -> (40 * 1.01 - 5 * 0.99) / 2 kN;
  // limit 10 + P0/3 kN with P0 = 100 kN.
  CHECK(s.sum_y.max_abs == Approx((40e3 * 1.01 - 5e3 * 0.99) / 2.0).epsilon(1e-6));
  CHECK(s.sum_y.limit == Approx((10.0 + 100.0 / 3.0) * 1e3).epsilon(1e-9));
  CHECK(s.sum_y.pass);
}

TEST_CASE("inconsistent force series are refused", "[safety]") {
  AxleForces f;
  f.static_wheel_load = 50e3;
  f.distance = {0.0, 1.0};
  f.Y_left = {0.0};
  CHECK_THROWS_AS(evaluate_axle(f), std::invalid_argument);
}
