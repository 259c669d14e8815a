// Running-safety limit values (engine/analysis/safety_limits.hpp) against the
// Nadal table, Prud'homme's worked example and the limit formulas' own numbers.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "engine/analysis/safety_limits.hpp"
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

TEST_CASE("Prud'homme limit: P0 = 160 kN gives 63.3 kN, freight wagons k1 = 0.85", "[safety]") {
  CHECK(prudhomme_limit(160e3) == Approx(63333.3).epsilon(1e-5));
  CHECK(prudhomme_limit(160e3, 0.85) == Approx(0.85 * 63333.3).epsilon(1e-5));
  // k1 (10 + 2 Q0 / 3) kN with Q0 = 80 kN is the same number.
  CHECK(prudhomme_limit(2 * 80e3) == Approx((10.0 + 2.0 * 80.0 / 3.0) * 1e3));
  CHECK(track_shift_factor(VehicleCategory::freight) == 0.85);
  for (auto c : {VehicleCategory::passenger, VehicleCategory::locomotive, VehicleCategory::multiple_unit})
    CHECK(track_shift_factor(c) == 1.0);
  // Instability (normal method): half the track-shift limit.
  CHECK(instability_sum_y_limit(160e3) == Approx(31666.67).epsilon(1e-5));
  CHECK(instability_sum_y_limit(160e3, 0.85) == Approx(0.85 * 31666.67).epsilon(1e-5));
}

TEST_CASE("(Y/Q)_2m limit: 0.8 down to R = 250 m, 1.2 below", "[safety]") {
  CHECK(yq_2m_limit(std::numeric_limits<double>::infinity()) == 0.8);
  CHECK(yq_2m_limit(250.0) == 0.8);
  CHECK(yq_2m_limit(249.9) == 1.2);
  CHECK(yq_2m_limit(150.0) == 1.2);
}

TEST_CASE("Q_max limit: 90 kN + Q0 capped by the speed class", "[safety]") {
  // Q0 = 50 kN: 140 kN at every speed (below all caps).
  for (double v : {100.0, 180.0, 230.0, 280.0, 320.0}) CHECK(qmax_limit(50e3, v / 3.6) == Approx(140e3));
  // Q0 = 100 kN: 190 kN uncapped; caps 200 / 190 / 180 / 170 / 160 kN.
  CHECK(qmax_limit(100e3, 160.0 / 3.6) == Approx(190e3));
  CHECK(qmax_limit(100e3, 200.0 / 3.6) == Approx(190e3));
  CHECK(qmax_limit(100e3, 240.0 / 3.6) == Approx(180e3));
  CHECK(qmax_limit(100e3, 300.0 / 3.6) == Approx(170e3));
  CHECK(qmax_limit(100e3, 301.0 / 3.6) == Approx(160e3));
}

TEST_CASE("bogie-frame acceleration limit of the simplified method", "[safety]") {
  // (12 - m/5)/2: 5 t -> 5.5 m/s^2; the Manchester bogie (2.615 t frame + 2 x 1.813 t) 6.241 t -> 5.376.
  CHECK(bogie_frame_acceleration_limit(5000.0) == Approx(5.5));
  CHECK(bogie_frame_acceleration_limit(6241.0) == Approx(0.5 * (12.0 - 6.241 / 5.0)));
}
