// The integrator families agree on one scene, and an explicit method on a
// stiff scene stops with a clear diagnostic.
#include <catch2/catch.hpp>

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "config/yaml_input.hpp"
#include "engine/data.hpp"
#include "engine/io/scenario.hpp"
#include "engine/system.hpp"
#include "engine/simulation.hpp"
#include "engine/engine_test_support.hpp"
#include "test_support.hpp"

using namespace railsim;

namespace {
std::vector<double> lateral_history(const engine::Scenario& sc, const engine::IntegratorOptions& o,
                                    engine::RunSummary* sum = nullptr) {
  std::vector<double> y;
  const int qi = sc.model.bodies[sc.model.wheelsets[0].body].q_index[engine::kLat];
  auto s = engine::simulate(sc.model, o, sc.x0, sc.duration, sc.output_interval,
                            [&](double, const Eigen::VectorXd& x, const engine::Data&) { y.push_back(x[qi]); });
  if (sum) *sum = s;
  return y;
}
// The Cooperrider car (DYTSI's set-up) with the given wheelset model, 2 s.
engine::Scenario cooperrider_car(const char* wheelset_model) {
  const std::string path = test::source_path("scenarios/cooperrider_car_dytsi.yaml");
  YAML::Node node = YAML::LoadFile(path);
  node["wheelset_model"] = wheelset_model;
  node["duration"] = 2.0;
  return engine::load_scenario(config::InputNode(node, path, ""), test::source_path("scenarios"));
}
}  // namespace

TEST_CASE("CVODE, ARKODE and Odeint agree on the single wheelset over a lateral defect", "[engine][integrator]") {
  const auto sc = engine::load_scenario(test::source_path("scenarios/single_wheelset.yaml"));
  engine::IntegratorOptions ref = sc.integrator;
  ref.method = "cvode_bdf";
  ref.rtol = 1e-9;
  ref.atol = 1e-12;
  const auto yref = lateral_history(sc, ref);
  double peak = 0;
  for (double v : yref) peak = std::max(peak, std::abs(v));
  REQUIRE(peak > 1e-3);  // the 10 mm defect moves the wheelset by millimetres
  struct Case {
    const char* method;
    const char* jac;
    const char* ls;
  };
  for (const Case c : {Case{"cvode_bdf", "fd", "dense"}, Case{"cvode_bdf", "assembled", "band"},
                       Case{"arkode_erk", "fd", "dense"}, Case{"arkode_dirk", "assembled", "dense"},
                       Case{"odeint_dopri5", "fd", "dense"}}) {
    engine::IntegratorOptions o = sc.integrator;
    o.method = c.method;
    o.jacobian = c.jac;
    o.linear_solver = c.ls;
    o.rtol = 1e-6;
    o.atol = 1e-9;
    engine::RunSummary sum;
    const auto y = lateral_history(sc, o, &sum);
    REQUIRE(y.size() == yref.size());
    double err = 0;
    for (std::size_t i = 0; i < y.size(); ++i) err = std::max(err, std::abs(y[i] - yref[i]));
    INFO(sum.integrator << ": max deviation " << err / peak * 100 << " % of peak; steps " << sum.stats.steps
                        << ", rhs calls " << sum.stats.rhs_calls << ", failed " << sum.stats.failed_steps);
    CHECK(err < 0.01 * peak);
    CHECK(sum.stats.steps > 0);
    CHECK(sum.stats.rhs_calls >= sum.stats.steps);
  }
}

TEST_CASE("explicit integrator on stiff elastic contact stops with a clear diagnostic", "[engine][integrator]") {
  // Full wheelset model (elastic Hertz contact) at 0.5 m/s: creep damping
  // 2 f / (m V) ~ 2e4 1/s makes the system stiff.
  const std::string extra =
      "wheelset_model: full\n"
      "integrator: {method: odeint_dopri5, rtol: 1.0e-6, atol: 1.0e-9, max_steps: 3000}\n"
      "initial: {ws1.lateral: 0.001}\n";
  auto sc = test::single_wheelset(0.5, 1e7, "vehicles/single_wheelset.yaml", extra);
  for (const char* method : {"odeint_dopri5", "arkode_erk"}) {
    engine::IntegratorOptions o = sc.integrator;
    o.method = method;
    std::string msg;
    try {
      engine::simulate(sc.model, o, sc.x0, 2.0, 0.5);
    } catch (const NumericalError& e) {
      msg = e.what();
    }
    INFO(msg);
    CHECK(msg.find("stiff") != std::string::npos);
    CHECK(msg.find("t = ") != std::string::npos);
  }
  // The implicit BDF method runs the same scene.
  engine::IntegratorOptions o = sc.integrator;
  o.method = "cvode_bdf";
  o.max_steps = 100000;
  const auto sum = engine::simulate(sc.model, o, sc.x0, 2.0, 0.5);
  CHECK(sum.max_abs_lateral[0] <= 0.001 + 1e-9);
}

TEST_CASE("a run that leaves the contact geometry stops with time, place and model", "[engine][integrator]") {
  // Above the critical speed the oscillation grows until the wheelset leaves the 5 mm geometry range.
  auto sc = test::single_wheelset(60.0, 1e7, "vehicles/single_wheelset.yaml",
                                  "max_lateral_shift: 0.005\ninitial: {ws1.lateral: 0.001}\n");
  std::string msg;
  try {
    engine::simulate(sc.model, sc.integrator, sc.x0, 20.0, 0.01);
  } catch (const NumericalError& e) {
    msg = e.what();
  }
  INFO(msg);
  CHECK(msg.find("ws1") != std::string::npos);
  CHECK(msg.find("exceeds the admissible 5 mm") != std::string::npos);
  CHECK(msg.find("t = ") != std::string::npos);
  CHECK(msg.find("lateral wheelset") != std::string::npos);
}

TEST_CASE("Manchester coach on ERRI track: benchmark tolerances against a tight reference", "[engine][integrator][.slow]") {
  // The benchmark scene (bench/bench_engine.cpp) runs Odeint at the scenario's
  // tolerances; its lateral-shift history must stay within 1 % of the peak of
  // a tight CVODE reference.
  auto sc = engine::load_scenario(test::source_path("scenarios/manchester_coach_200_erri.yaml"));
  sc.duration = 4.0;
  engine::IntegratorOptions ref = sc.integrator;
  ref.method = "cvode_bdf";
  ref.rtol = 1e-9;
  ref.atol = 1e-12;
  const auto yref = lateral_history(sc, ref);
  double peak = 0;
  for (double v : yref) peak = std::max(peak, std::abs(v));
  engine::RunSummary sum;
  const auto y = lateral_history(sc, sc.integrator, &sum);
  double err = 0;
  for (std::size_t i = 0; i < y.size(); ++i) err = std::max(err, std::abs(y[i] - yref[i]));
  INFO(sum.integrator << " rtol " << sc.integrator.rtol << ": max deviation " << err / peak * 100 << " % of peak "
                      << peak * 1e3 << " mm; steps " << sum.stats.steps << ", rhs calls " << sum.stats.rhs_calls);
  CHECK(err < 0.01 * peak);
}

// integrator.atol_contact_modes: the absolute tolerance of the wheelsets' spin
// perturbations (both wheelset models) and of their vertical and roll
// velocities (full model); every other state keeps atol. A run with the loose
// contact-mode tolerance stays within 1 % of a tight reference.
TEST_CASE("contact-mode tolerance reaches spin in both wheelset models, bounce in the full one", "[engine][integrator]") {
  for (const char* model : {"lateral", "full"}) {
    INFO("wheelset model " << model);
    const engine::Scenario sc = cooperrider_car(model);
    engine::Data data(sc.model);
    engine::ModelOde ode(sc.model, data);
    engine::IntegratorOptions o = sc.integrator;
    o.atol_contact_modes = 1e-4;
    std::vector<double> atol(std::size_t(ode.size()));
    ode.tolerances(o, atol.data());
    std::vector<bool> contact_mode(atol.size(), false);
    for (const auto& w : sc.model.wheelsets) {
      REQUIRE(w.beta_state >= 0);  // the axle rolls freely in both models
      contact_mode[std::size_t(w.beta_state)] = true;
      const auto& b = sc.model.bodies[w.body];
      for (int k : {engine::kVert, engine::kRoll})
        if (b.v_index[k] >= 0) {
          CHECK(std::string(model) == "full");
          contact_mode[std::size_t(b.v_index[k])] = true;
        }
    }
    int loosened = 0;
    for (std::size_t i = 0; i < atol.size(); ++i) {
      INFO("state " << sc.model.state_names[i]);
      CHECK(atol[i] == Approx(contact_mode[i] ? 1e-4 : o.atol));
      loosened += contact_mode[i];
    }
    CHECK(loosened == (std::string(model) == "full" ? 12 : 4));  // 4 wheelsets x (spin [+ vertical, roll])

    // Accuracy: leading wheelset's lateral motion over 2 s from the 5 mm start.
    engine::IntegratorOptions tight = sc.integrator;
    tight.rtol = 1e-9;
    tight.atol = 1e-11;
    const auto yref = lateral_history(sc, tight);
    const auto y = lateral_history(sc, o);
    REQUIRE(y.size() == yref.size());
    double err = 0, peak = 0;
    for (std::size_t i = 0; i < y.size(); ++i) {
      err = std::max(err, std::abs(y[i] - yref[i]));
      peak = std::max(peak, std::abs(yref[i]));
    }
    INFO("max deviation " << err / peak * 100 << " % of the peak " << peak * 1e3 << " mm");
    CHECK(peak > 4e-3);
    CHECK(err < 0.01 * peak);
  }
}

// integrator.jacobian_max_age reaches CVODE: a long age evaluates the coloured
// Jacobian far less often (CVODE still re-evaluates it whenever Newton fails to
// converge), and the run keeps the accuracy of CVODE's own default of 51 steps
// against a tight reference (measured: 11 / 21 Jacobians against 70 / 139,
// lateral / full).
TEST_CASE("Jacobian age: fewer Jacobians, the same accuracy against a tight reference", "[engine][integrator]") {
  for (const char* model : {"lateral", "full"}) {
    INFO("wheelset model " << model);
    const engine::Scenario sc = cooperrider_car(model);
    engine::IntegratorOptions tight = sc.integrator;
    tight.rtol = 1e-9;
    tight.atol = 1e-11;
    const auto yref = lateral_history(sc, tight);
    double peak = 0;
    for (double v : yref) peak = std::max(peak, std::abs(v));
    REQUIRE(peak > 4e-3);
    long jacobians[2] = {0, 0};
    int k = 0;
    for (long age : {51L, 400L}) {
      engine::IntegratorOptions o = sc.integrator;
      o.jacobian_max_age = age;
      engine::RunSummary sum;
      const auto y = lateral_history(sc, o, &sum);
      REQUIRE(y.size() == yref.size());
      double err = 0;
      for (std::size_t i = 0; i < y.size(); ++i) err = std::max(err, std::abs(y[i] - yref[i]));
      INFO("age " << age << ": " << sum.stats.steps << " steps, " << sum.stats.jacobian_evals << " Jacobians, "
                  << "max deviation " << err / peak * 100 << " % of the peak");
      // Measured at the scenario's rtol: 0.0012 / 0.0007 % (lateral), 5e-5 / 8e-5 % (full).
      CHECK(err < 1e-4 * peak);
      jacobians[k++] = sum.stats.jacobian_evals;
    }
    CHECK(jacobians[1] > 0);
    CHECK(2 * jacobians[1] < jacobians[0]);
  }
}
