// Cant deficiency and excess against physics-reference §10.1:
// E_eq = 2b V^2 / (g R), D = E_eq - E; practical form E_eq[mm] = 11.8 V^2[km/h]/R[m]
// for 2b = 1500 mm; a_nc = g D / 2b (0.654 m/s^2 per 100 mm).
#include <catch2/catch.hpp>

#include <cmath>

#include "test_support.hpp"
#include "track/cant.hpp"
#include "track/track_file.hpp"

using namespace railsim::track;

TEST_CASE("cant deficiency matches 2b V^2/(gR) - E and the 11.8 V^2/R rule", "[tracks][cant]") {
  struct Case {
    double V_kmh, R, E_mm;
  };
  for (const Case c : {Case{160, 1000, 100}, Case{80, 300, 150}, Case{40, 300, 150}, Case{200, 2500, 160}}) {
    const double V = c.V_kmh / 3.6;
    for (double dir : {1.0, -1.0}) {  // left and right curves: E has the sign of kappa
      const double D = cant_deficiency(V, dir / c.R, dir * c.E_mm * 1e-3, 1.5);
      CHECK(D == Approx(1.5 * V * V / (9.81 * c.R) - c.E_mm * 1e-3).epsilon(1e-14));
      // The rounded practical rule agrees to its own rounding (11.8 vs 11.798).
      CHECK(D * 1e3 == Approx(11.8 * c.V_kmh * c.V_kmh / c.R - c.E_mm).margin(0.02e-2 * 11.8 * c.V_kmh * c.V_kmh / c.R));
      CHECK(cant_excess(V, dir / c.R, dir * c.E_mm * 1e-3, 1.5) == Approx(-D).epsilon(1e-14));
      CHECK(uncompensated_acceleration(V, dir / c.R, dir * c.E_mm * 1e-3, 1.5) == Approx(9.81 * D / 1.5).epsilon(1e-14));
    }
  }
  // 100 mm of deficiency = 0.654 m/s^2.
  const double V = std::sqrt(0.1 * 9.81 * 500 / 1.5);
  CHECK(uncompensated_acceleration(V, 1.0 / 500, 0.0, 1.5) == Approx(0.654).epsilon(1e-3));
  // Cant on the wrong side counts against the vehicle; on a straight all cant is excess.
  CHECK(cant_deficiency(20.0, 1.0 / 500, -0.05, 1.5) == Approx(1.5 * 400 / (9.81 * 500) + 0.05).epsilon(1e-14));
  CHECK(cant_deficiency(20.0, 0.0, -0.05, 1.5) == Approx(-0.05).epsilon(1e-14));
  CHECK(cant_angle(0.15, 1.5) == Approx(std::asin(0.1)).epsilon(1e-15));
}

TEST_CASE("Track::cant_deficiency on the shipped R = 1000 m curve", "[tracks][cant]") {
  const Track t = load_track(railsim::test::source_path("tracks/curve_R1000.yaml"));
  // Full curve: 11.8 * 160^2 / 1000 - 100 = 202 mm; 92 km/h is the balancing speed.
  CHECK(t.cant_deficiency(600.0, 160 / 3.6) * 1e3 == Approx(1.5 * std::pow(160 / 3.6, 2) / (9.81 * 1000) * 1e3 - 100).epsilon(1e-12));
  CHECK(std::abs(t.cant_deficiency(600.0, std::sqrt(0.1 * 9.81 * 1000 / 1.5))) < 1e-12);
  // Mid-clothoid: half the curvature, half the cant.
  CHECK(t.cant_deficiency(150.0, 160 / 3.6) == Approx(0.5 * t.cant_deficiency(600.0, 160 / 3.6)).epsilon(1e-12));
}
