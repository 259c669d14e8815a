// Full wheelset model with several contact points per wheel: two half-load
// points with the same geometry carry exactly the normal load of one point
// (N_k = N0/2 (1 + dq/q0)^{3/2} each) and, with linear creep, twice its creep
// force (each patch keeps the single point's size, a, b ~ (N_k/N0_k)^{1/3}).
// (Tolerance 1e-9: the halved N0 are stored with 10 significant digits.)
#include <catch2/catch.hpp>

#include "engine/system.hpp"
#include "engine_test_support.hpp"

using namespace railsim;

namespace {
engine::Scenario cooperrider_with(const std::string& table) {
  return test::scenario_from_text(
      "vehicle: vehicles/cooperrider_car.yaml\n"
      "track: {segments: [{type: straight, length: 1000}]}\n"
      "speed: 40\nduration: 1\nwheelset_model: full\n"
      "contact:\n  geometry: {type: table, file: " + table + "}\n"
      "  tangential: coefficients\n"
      "  material: {E: 2.1e11, nu: 0.27, mu: 0.15, shear_modulus: 1.43836e11}\n");
}
}  // namespace

TEST_CASE("full model: two half-load contact points superpose", "[engine][wheelset]") {
  const auto one = cooperrider_with("tests/data/engine/rsgeo_1in10.dat");
  const auto two = cooperrider_with("tests/data/engine/rsgeo_1in10_two_half_points.dat");
  REQUIRE(one.model.n_states == two.model.n_states);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(one.model.n_states), xd1(x.size()), xd2(x.size());
  for (int i = 0; i < one.model.n_states; ++i) {
    const auto& n = one.model.state_names[i];
    if (n == "ws1.lateral") x[i] = 0.002;
    if (n == "ws1.vertical") x[i] = -5e-6;
    if (n == "ws1.lateral_rate") x[i] = 0.05;
    if (n == "ws1.yaw") x[i] = 1e-4;
  }
  engine::Data d1(one.model), d2(two.model);
  engine::rhs_or_throw(one.model, d1, 0.0, x.data(), xd1.data());
  engine::rhs_or_throw(two.model, d2, 0.0, x.data(), xd2.data());
  for (int i = 0; i < 2; ++i) {
    INFO("wheel " << i);
    CHECK(d2.wheel[i].N == Approx(d1.wheel[i].N).epsilon(1e-9));
    CHECK(d1.wheel[i].N > 66661);  // pressed 5 um into the rails
    CHECK(d2.wheel[i].Fy == Approx(2 * d1.wheel[i].Fy).epsilon(1e-9));
    CHECK(d2.wheel[i].Fx == Approx(2 * d1.wheel[i].Fx).epsilon(1e-9));
  }
}
