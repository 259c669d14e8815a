// Vehicle files: the Cooperrider car (cooperrider-car.md) assembled from its
// YAML carries the weight as DYTSI's layout says (§5.1, §7.3).
#include <catch2/catch.hpp>

#include <cmath>

#include "engine/system.hpp"
#include "engine/engine_test_support.hpp"
#include "test_support.hpp"

using namespace railsim;

TEST_CASE("Cooperrider car: spring preloads and wheel loads of cooperrider-car.md", "[engine][vehicle]") {
  auto sc = engine::load_scenario(test::source_path("scenarios/cooperrider_car.yaml"));
  const auto& m = sc.model;
  REQUIRE(m.n_states == 66);  // cooperrider-car.md §2: 66 first-order states
  // §5.1: each secondary vertical spring carries M_cb g / 4, each primary vertical spring (M_cb + 2 M_bf) g / 8.
  const double g = engine::kGravity;
  for (const auto& e : m.springs) {
    if (e.name.rfind("sec_vert", 0) == 0) CHECK(std::abs(e.preload.z()) == Approx(44388 * g / 4).epsilon(1e-6));
    if (e.name.rfind("prim_vert", 0) == 0)
      CHECK(std::abs(e.preload.z()) == Approx((44388 + 2 * 2918.9) * g / 8).epsilon(1e-6));
  }
  // §7.3: static normal load per wheel (M_cb/4 + M_bf/2 + M_w) g / 2 / cos(delta0) and the table's N0 agree within 0.1 %.
  const double share = (44388.0 / 4 + 2918.9 / 2 + 1022) * g / 2;
  for (const auto& w : m.wheelsets)
    for (int i = 0; i < 2; ++i) {
      CHECK(w.static_load[i] * std::cos(0.01422) == Approx(share).epsilon(1e-4));
      CHECK(w.static_load[i] == Approx(66661).epsilon(1e-3));
    }
}
