// System assembly: static equilibrium of the Manchester coach (wheel loads =
// static weight share) and no drift in steady running on straight, level,
// perfect track; the bogie alone likewise; the coloured Jacobian's contact
// replay.
#include <algorithm>
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include <yaml-cpp/yaml.h>

#include <vector>

#include "config/yaml_input.hpp"
#include "engine/integrators/jacobian_pattern.hpp"
#include "engine/io/scenario.hpp"
#include "engine/simulation.hpp"
#include "engine/system.hpp"
#include "engine_test_support.hpp"
#include "test_support.hpp"

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

// Coloured Jacobian differences replay the contact of every wheelset whose
// states a colour does not perturb (ModelOde, Data::reuse_contact). The
// Jacobian must be the one of plain coloured differences to the bit: in both
// wheelset models (the lateral model's wheel loads read the suspension, the
// full model's only the wheelset), on profiles with yaw and a flexible track
// (curve_twist) and on the Cooperrider car's geometry table; also when the
// integrator's last evaluation was at another state (the records are then
// made again at the Jacobian's state). The lateral model's load-to-approach
// solves start warm (Data::approach_warm_start, here from an evaluation at
// another state): the plain differences start every evaluation, the base
// included, where the Jacobian's base evaluation started.
TEST_CASE("coloured Jacobian with contact replay equals plain coloured differences", "[engine][system][jacobian]") {
  int warm_cases = 0;
  for (const char* file : {"scenarios/manchester_coach_curve_twist.yaml", "scenarios/cooperrider_car_dytsi.yaml"})
    for (const char* model : {"lateral", "full"}) {
      INFO(file << ", " << model << " wheelset model");
      const std::string path = test::source_path(file);
      YAML::Node node = YAML::LoadFile(path);
      node["wheelset_model"] = model;
      const engine::Scenario sc =
          engine::load_scenario(config::InputNode(node, path, ""), test::source_path("scenarios"));
      const int n = sc.model.n_states;
      // A state off the centre: every wheelset shifted and yawed, the car rolled.
      Eigen::VectorXd x = sc.x0;
      for (const auto& w : sc.model.wheelsets) {
        const auto& b = sc.model.bodies[std::size_t(w.body)];
        x[b.q_index[engine::kLat]] += 2e-3;
        x[b.q_index[engine::kYaw]] += 1e-3;
        x[b.v_index[engine::kLat]] += 0.01;
      }
      const double t = 0.7;
      engine::Data d(sc.model);
      engine::ModelOde ode(sc.model, d);
      const engine::JacobianPattern& p = ode.sparsity();
      Eigen::VectorXd fx(n), fother(n), xother = x;
      xother[0] += 1e-4;
      REQUIRE(ode.rhs(t, xother.data(), fother.data()));  // warm starts from another state
      const std::vector<double> start_x = d.approach_warm_start;
      warm_cases += std::any_of(start_x.begin(), start_x.end(), [](double v) { return v > 0.0; });
      REQUIRE(ode.rhs(t, x.data(), fx.data()));
      std::vector<double> replayed(std::size_t(p.nonzeros())), again(replayed.size());
      REQUIRE(ode.sparse_jacobian(t, x.data(), fx.data(), replayed.data()));
      REQUIRE(ode.rhs(t, xother.data(), fother.data()));  // the last evaluation elsewhere
      const std::vector<double> start_again = d.approach_warm_start;
      REQUIRE(ode.sparse_jacobian(t, x.data(), fx.data(), again.data()));
      // Plain coloured differences, every contact solved, on a Data of its own,
      // each evaluation started from the warm starts `start`.
      auto plain_jacobian = [&](const std::vector<double>& start, std::vector<double>& plain) {
        plain.assign(replayed.size(), 0.0);
        engine::Data d2(sc.model);
        Eigen::VectorXd xp(n), fp(n), f0(n);
        d2.approach_warm_start = start;
        REQUIRE(engine::rhs(sc.model, d2, t, x.data(), f0.data()));
        for (int c = 0; c < p.colors; ++c) {
          xp = x;
          for (int j = 0; j < n; ++j)
            if (p.color[std::size_t(j)] == c) xp[j] += 1e-7 * std::max(1.0, std::abs(x[j])) + 1e-9;
          d2.approach_warm_start = start;
          REQUIRE(engine::rhs(sc.model, d2, t, xp.data(), fp.data()));
          for (int j = 0; j < n; ++j) {
            if (p.color[std::size_t(j)] != c) continue;
            for (int k = p.colptr[std::size_t(j)]; k < p.colptr[std::size_t(j) + 1]; ++k) {
              const int i = p.rowind[std::size_t(k)];
              plain[std::size_t(k)] = p.kinematic_row[std::size_t(i)]
                                          ? (p.kinematic_col[std::size_t(i)] == j ? 1.0 : 0.0)
                                          : (fp[i] - f0[i]) / (1e-7 * std::max(1.0, std::abs(x[j])) + 1e-9);
            }
          }
        }
      };
      std::vector<double> plain, plain_again;
      plain_jacobian(start_x, plain);
      plain_jacobian(start_again, plain_again);
      int differ = 0, contact_rows = 0;
      for (std::size_t k = 0; k < plain.size(); ++k) {
        differ += replayed[k] != plain[k] || again[k] != plain_again[k];
        contact_rows += plain[k] != 0.0;
      }
      CHECK(differ == 0);
      CHECK(contact_rows > n);
    }
  CHECK(warm_cases > 0);  // the lateral model on profiles
}
