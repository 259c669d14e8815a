// Contact tables: interpolation, jumps, cache (contact/geometry/contact_table.cpp).
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>

#include "contact/geometry/contact_table.hpp"
#include "core/errors.hpp"
#include "test_support.hpp"

using namespace railsim;
using namespace railsim::contact;

namespace {
struct Fixture {
  Profile w = read_profile("S1002", ProfileKind::wheel);
  Profile r = read_profile("UIC60", ProfileKind::rail);
  TrackSetup ts = [] {
    TrackSetup t;
    t.inclination = std::atan(1.0 / 40.0);
    return t;
  }();
  WheelRailGeometry g{w, r, ts};
};
}  // namespace

TEST_CASE("Table interpolation matches direct solves away from jumps", "[geometry][table]") {
  Fixture f;
  TableGrid grid;
  grid.y_min = -0.004;
  grid.y_max = 0.004;
  grid.y_step = 1e-4;
  const ContactTable t = ContactTable::build(f.g, grid);
  REQUIRE(t.rows() == 81);
  TableSample s;
  for (double y : {-0.00345, 0.00155, 0.00305}) {
    t.lookup(y, s);
    const auto d = f.g.solve(y);
    INFO("y = " << y);
    CHECK(s.roll == Approx(d.roll).margin(2e-6));
    for (int side = 0; side < 2; ++side) {
      const auto& a = s.wheel[static_cast<std::size_t>(side)].p[0];
      const auto& b = d.wheel[static_cast<std::size_t>(side)].p[0];
      CHECK(a.radius == Approx(b.radius).margin(2e-6));
      CHECK(a.y_wheel == Approx(b.y_wheel).margin(0.2e-3));
      CHECK(a.angle == Approx(b.angle).margin(2e-3));
    }
  }
  CHECK_THROWS_AS(t.lookup(0.0041, s), InputError);
}

TEST_CASE("Table lookup never averages across the tread-flange jump", "[geometry][table]") {
  Fixture f;
  TableGrid grid;
  grid.y_min = 0.0055;
  grid.y_max = 0.0075;
  grid.y_step = 1e-3;  // coarse on purpose: rows at 5.5, 6.5, 7.5 mm
  const ContactTable t = ContactTable::build(f.g, grid);
  TableSample s;
  // 5.5 mm: flange root (about 19 deg); 6.5 mm: flank (about 67 deg). An
  // average would give about 43 deg.
  t.lookup(0.0059, s);  // nearer the 5.5 mm row
  CHECK(s.wheel[0].p[0].angle < 25.0 * M_PI / 180.0);
  t.lookup(0.0061, s);  // nearer the 6.5 mm row
  CHECK(s.wheel[0].p[0].angle > 60.0 * M_PI / 180.0);
}

TEST_CASE("Tables are cached on disk keyed by their inputs", "[geometry][table]") {
  Fixture f;
  const std::string dir = test::temp_dir("geometry_cache");
  TableGrid grid;
  grid.y_min = -0.002;
  grid.y_max = 0.002;
  grid.y_step = 2e-4;
  bool hit = true;
  const ContactTable a = ContactTable::cached(f.g, f.w, f.r, grid, dir, &hit);
  CHECK_FALSE(hit);
  const ContactTable b = ContactTable::cached(f.g, f.w, f.r, grid, dir, &hit);
  CHECK(hit);
  REQUIRE(a.rows() == b.rows());
  for (std::size_t i = 0; i < a.rows(); ++i)
    for (int c = 0; c < ContactTable::kColumns; ++c) {
      const double x = a.value(i, c), y = b.value(i, c);
      CHECK(((std::isnan(x) && std::isnan(y)) || x == y));
    }
  // Another inclination is another key.
  TrackSetup ts2 = f.ts;
  ts2.inclination = std::atan(1.0 / 20.0);
  const WheelRailGeometry g2(f.w, f.r, ts2);
  CHECK(ContactTable::cache_key(g2, f.w, f.r, grid) != ContactTable::cache_key(f.g, f.w, f.r, grid));
  ContactTable::cached(g2, f.w, f.r, grid, dir, &hit);
  CHECK_FALSE(hit);
  // A corrupt cache file is rebuilt, not trusted.
  for (const auto& e : std::filesystem::directory_iterator(dir)) std::filesystem::resize_file(e.path(), 40);
  ContactTable::cached(f.g, f.w, f.r, grid, dir, &hit);
  CHECK_FALSE(hit);
  TableGrid bad = grid;
  bad.y_step = 0.0;
  CHECK_THROWS_AS(ContactTable::build(f.g, bad), InputError);
}
