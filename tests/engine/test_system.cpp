// System assembly: static equilibrium of the Manchester coach (wheel loads =
// static weight share) and no drift in steady running on straight, level,
// perfect track; the bogie alone likewise.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "engine/simulation.hpp"
#include "engine/system.hpp"
#include "engine_test_support.hpp"

using namespace railsim;

namespace {
engine::Scenario on_perfect_track(const std::string& vehicle, const std::string& model, double V) {
  return test::scenario_from_text(
      "vehicle: " + vehicle + "\n"
      "track: {segments: [{type: straight, length: 2000}]}\n"
      "speed: " + std::to_string(V) + "\n"
      "duration: 1\n"
      "wheelset_model: " + model + "\n"
      "contact:\n"
      "  geometry: {type: conical, r0: 0.46, conicity: 0.15, l0: 0.75, contact_angle: 0}\n"
      "  tangential: coefficients\n"
      "  creep_coefficients: {f11: 1.0e7, f22: 1.0e7, f23: 1.0e4}\n"
      "integrator: {method: cvode_bdf, rtol: 1.0e-8, atol: 1.0e-11, max_step: 0.002}\n");
}
}  // namespace

TEST_CASE("Manchester coach: wheel loads at rest equal the static weight share", "[engine][system]") {
  for (const char* model : {"lateral", "full"}) {
    const auto sc = on_perfect_track("vehicles/manchester_coach.yaml", model, 0.5);
    // Masses of physics-reference §7.1: car 32000, bogies 2 x 2615, wheelsets 4 x 1813 kg, 8 wheels.
    const double share = (32000 + 2 * 2615 + 4 * 1813) * engine::kGravity / 8;
    engine::Data d(sc.model);
    Eigen::VectorXd xd(sc.model.n_states);
    engine::rhs_or_throw(sc.model, d, 0.0, sc.x0.data(), xd.data());
    REQUIRE(d.wheel.size() == 8);
    for (const auto& w : d.wheel) CHECK(w.Q == Approx(share).epsilon(1e-3));
    CHECK(xd.cwiseAbs().maxCoeff() < 1e-6);  // equilibrium: no acceleration at x = 0
  }
}

TEST_CASE("Manchester coach: no drift in steady running at 200 km/h", "[engine][system]") {
  for (const char* model : {"lateral", "full"}) {
    const auto sc = on_perfect_track("vehicles/manchester_coach.yaml", model, 200 / 3.6);
    const double share = (32000 + 2 * 2615 + 4 * 1813) * engine::kGravity / 8;
    double max_state = 0, max_dQ = 0;
    engine::simulate(sc.model, sc.integrator, sc.x0, 3.0, 0.01, [&](double, const Eigen::VectorXd& x, const engine::Data& d) {
      max_state = std::max(max_state, x.cwiseAbs().maxCoeff());
      for (const auto& w : d.wheel) max_dQ = std::max(max_dQ, std::abs(w.Q - share) / share);
    });
    INFO(model << " wheelset model: max |state| " << max_state << ", max wheel-load deviation " << max_dQ);
    // Full model: the statics residual (~1e-6 N) rings the undamped elastic-contact
    // modes at the 1e-8 level (m, rad, m/s); no growth, no drift.
    CHECK(max_state < (std::string(model) == "full" ? 1e-7 : 1e-9));
    CHECK(max_dQ < 1e-3);
  }
}

TEST_CASE("bogie under a fixed car body: frame weight shared by primary and secondary springs", "[engine][system]") {
  const auto sc = on_perfect_track("vehicles/bogie.yaml", "lateral", 1.0);
  // The frame sits between the fixed car body (secondary, 2 x 430 kN/m) and the
  // wheelsets (primary, 4 x 1220 kN/m): parallel springs, so the primaries carry
  // the fraction kp / (kp + ks) of the frame weight.
  const double kp = 4 * 1.220e6, ks = 2 * 430e3;
  const double share = (1813 + 2615 * kp / (kp + ks) / 2) * engine::kGravity / 2;
  engine::Data d(sc.model);
  Eigen::VectorXd xd(sc.model.n_states);
  engine::rhs_or_throw(sc.model, d, 0.0, sc.x0.data(), xd.data());
  for (const auto& w : d.wheel) CHECK(w.Q == Approx(share).epsilon(1e-3));
}
