// The 13-column contact-geometry table (DYTSI RSGEO): values at zero shift
// and the landmarks listed in cooperrider-car.md §7.2.
#include <catch2/catch.hpp>

#include "core/errors.hpp"
#include "engine/wheel_rail/geometry_table.hpp"
#include "test_support.hpp"

using namespace railsim;

TEST_CASE("RSGEO table: values at zero shift and landmarks", "[engine][geometry]") {
  const engine::GeometryTable t(test::source_path("vehicles/contact_tables/RSGEO_S1002_UIC60_1in40.dat"));
  CHECK(t.rows() == 3402);
  engine::ContactPointGeometry c = t.main_point(0.0);
  CHECK(c.N0 == Approx(66661).epsilon(1e-4));
  CHECK(c.contact_angle == Approx(0.01422).epsilon(1e-3));
  CHECK(c.semi_a == Approx(5.952e-3).epsilon(1e-3));
  CHECK(c.semi_b == Approx(6.653e-3).epsilon(1e-3));
  CHECK(c.lateral == Approx(0.75630).epsilon(1e-5));
  CHECK(c.rolling_radius == Approx(0.4248829).epsilon(1e-6));
  CHECK(c.C11 == Approx(4.125).epsilon(1e-3));
  CHECK(c.q0 == Approx(7.011e-5).epsilon(1e-3));
  CHECK(t.r0() == Approx(0.4248829).epsilon(1e-6));
  c = t.main_point(0.005);
  CHECK(c.rolling_radius == Approx(0.42574).epsilon(2e-5));
  c = t.main_point(0.009);
  CHECK(c.rolling_radius == Approx(0.43961).epsilon(2e-5));
  CHECK(c.contact_angle == Approx(1.221).epsilon(2e-3));
}

TEST_CASE("malformed geometry table names file and line", "[engine][geometry]") {
  std::string msg;
  try {
    engine::GeometryTable t(test::data_path("engine/bad_geometry_table.dat"));
  } catch (const InputError& e) {
    msg = e.what();
  }
  CHECK(msg.find("bad_geometry_table.dat:4:") != std::string::npos);
  CHECK(msg.find("13 numbers") != std::string::npos);
}
