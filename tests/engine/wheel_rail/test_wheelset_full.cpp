// Full wheelset model with several contact points per wheel: two half-load
// points with the same geometry carry exactly the normal load of one point
// (N_k = N0/2 (1 + dq/q0)^{3/2} each) and, with linear creep, twice its creep
// force (each patch keeps the single point's size, a, b ~ (N_k/N0_k)^{1/3}).
// (Tolerance 1e-9: the halved N0 are stored with 10 significant digits.)
#include <catch2/catch.hpp>

#include "engine/system.hpp"
#include "engine/wheel_rail/wear_number.hpp"
#include "engine/engine_test_support.hpp"

using namespace railsim;

namespace {
engine::Scenario cooperrider_with(const std::string& table, const char* model = "full") {
  return test::scenario_from_text(
      "vehicle: vehicles/cooperrider_car.yaml\n"
      "track: {segments: [{type: straight, length: 1000}]}\n"
      "speed: 40\nduration: 1\nwheelset_model: " + std::string(model) + "\n"
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

TEST_CASE("wear number with several points: the sum of every point's own frictional work", "[engine][wheelset]") {
  // T gamma of a wheel = sum over its loaded points of -(Fx xi + Fy eta + Mz phi) with each
  // point's own forces and creepages (wear_number.hpp), checked against the recorded patches;
  // the two half-load points carry twice the single point's linear-creep forces at the same
  // creepages, hence twice its T gamma. Both wheelset models, both wheels, the mirror pose.
  for (const char* model : {"full", "lateral"}) {
    const auto one = cooperrider_with("tests/data/engine/rsgeo_1in10.dat", model);
    const auto two = cooperrider_with("tests/data/engine/rsgeo_1in10_two_half_points.dat", model);
    for (const double side : {1.0, -1.0}) {
      INFO(model << " model, shift " << side * 2 << " mm");
      Eigen::VectorXd x = Eigen::VectorXd::Zero(one.model.n_states), xd(x.size());
      for (int i = 0; i < one.model.n_states; ++i) {
        const auto& n = one.model.state_names[i];
        if (n == "ws1.lateral") x[i] = side * 0.002;
        if (n == "ws1.vertical") x[i] = -5e-6;
        if (n == "ws1.lateral_rate") x[i] = side * 0.05;
        if (n == "ws1.yaw") x[i] = side * 1e-4;
      }
      engine::Data d1(one.model), d2(two.model);
      d1.record_patches = d2.record_patches = true;
      engine::rhs_or_throw(one.model, d1, 0.0, x.data(), xd.data());
      engine::rhs_or_throw(two.model, d2, 0.0, x.data(), xd.data());
      for (int i = 0; i < 2; ++i) {
        const engine::WheelOutput& w = d2.wheel[i];
        REQUIRE(w.patches == 2);
        double sum = 0.0;
        for (int p = 0; p < w.patches; ++p) {
          const engine::PatchState& ps = d2.patch[i * engine::WheelGeometry::kMaxPoints + p];
          sum += -(ps.forces.Fx * ps.input.creep.xi + ps.forces.Fy * ps.input.creep.eta +
                   ps.forces.Mz * ps.input.creep.phi);
        }
        CHECK(engine::wear_number(w) == Approx(sum).epsilon(1e-12));
        CHECK(engine::wear_number(d1.wheel[i]) > 0.0);
        CHECK(engine::wear_number(w) == Approx(2.0 * engine::wear_number(d1.wheel[i])).epsilon(1e-6));
      }
    }
  }
}
