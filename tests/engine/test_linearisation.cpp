// Linear stability of the single wheelset (physics-reference §8.1): the
// critical speed from the eigenvalues against the closed-form Routh-Hurwitz
// result, and time runs just below / above it.
#include <catch2/catch.hpp>

#include <cmath>

#include "engine/linearisation.hpp"
#include "engine/simulation.hpp"
#include "engine_test_support.hpp"

using namespace railsim;

namespace {
// Closed form of physics-reference §8.1 (Routh-Hurwitz boundary).
double routh_hurwitz_vc(double m, double I, double l0, double r0, double lambda, double f, double ky, double kpsi) {
  const double J = I + m * l0 * l0;
  const double num = 4 * f * f * l0 * r0 * J * (kpsi + ky * l0 * l0);
  const double den = 4 * f * f * lambda * J * J - l0 * r0 * std::pow(I * ky - m * kpsi, 2);
  return std::sqrt(num / den);
}
// Envelope growth: max |y| over the last second divided by that of the first.
double growth(const engine::Scenario& sc, double duration) {
  std::vector<double> t, y;
  const int qi = sc.model.bodies[0].q_index[engine::kLat];
  engine::simulate(sc.model, sc.integrator, sc.x0, duration, 0.002,
                   [&](double tt, const Eigen::VectorXd& x, const engine::Data&) {
                     t.push_back(tt);
                     y.push_back(x[qi]);
                   });
  double first = 0, last = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (t[i] <= 1.0) first = std::max(first, std::abs(y[i]));
    if (t[i] >= duration - 1.0) last = std::max(last, std::abs(y[i]));
  }
  return last / first;
}
}  // namespace

TEST_CASE("single wheelset critical speed matches the Routh-Hurwitz closed form", "[engine][linearisation]") {
  const auto sc = test::single_wheelset(30.0);
  // Parameters of vehicles/single_wheelset.yaml and the scenario (physics-reference §8.1 check values).
  const double vc_closed = routh_hurwitz_vc(1813, 1120, 0.75, 0.46, 0.2, 1e7, 2 * 0.5e6, 2 * 1e6 * 1.0 * 1.0);
  CHECK(vc_closed == Approx(45.59).epsilon(5e-4));  // value printed in physics-reference §8.1
  const double vc = engine::critical_speed(sc.model, 20.0, 80.0, 1e-6);
  CHECK(vc == Approx(vc_closed).epsilon(0.01));
  // The reference note: the largest real part changes sign between 0.999 and 1.001 V_c.
  CHECK(engine::max_real_part(sc.model, 0.999 * vc_closed) < 0);
  CHECK(engine::max_real_part(sc.model, 1.001 * vc_closed) > 0);
}

TEST_CASE("time runs decay just below and grow just above the critical speed", "[engine][linearisation]") {
  const double vc = 45.59;
  for (double ratio : {0.97, 1.03}) {
    auto sc = test::single_wheelset(ratio * vc, 1e7, "vehicles/single_wheelset.yaml",
                                    "integrator: {method: cvode_bdf, rtol: 1.0e-8, atol: 1.0e-11, max_step: 0.002}\n"
                                    "initial: {ws1.lateral: 0.001}\n");
    const double g = growth(sc, 8.0);
    INFO("V/Vc = " << ratio << ", envelope ratio last/first second = " << g);
    if (ratio < 1) CHECK(g < 0.8);
    else CHECK(g > 1.25);
  }
}

TEST_CASE("stiff primary yaw: no hunting (negative Routh-Hurwitz denominator)", "[engine][linearisation]") {
  // Manchester-like primary stiffness on the single wheelset (physics-reference §8.1 last remark).
  const auto sc = test::single_wheelset(30.0, 1e7, "tests/data/engine/single_wheelset_stiff.yaml");
  for (double V : {10.0, 50.0, 100.0}) CHECK(engine::max_real_part(sc.model, V) < 0);
}

TEST_CASE("Manchester coach: the lateral and full wheelset models give close critical speeds", "[engine][linearisation]") {
  // Perfect straight track; the two wheelset models differ only by roll and
  // vertical dynamics, elastic contact, spin perturbation and gyroscopic terms.
  auto text = [](const char* model) {
    return std::string("vehicle: vehicles/manchester_coach.yaml\n"
                       "track: {segments: [{type: straight, length: 3000}]}\n"
                       "speed: 50\nduration: 1\nwheelset_model: ") + model + "\n"
                       "contact:\n  geometry: {type: conical, r0: 0.46, conicity: 0.15, l0: 0.75}\n"
                       "  tangential: coefficients\n  creep_coefficients: {f11: 1.0e7, f22: 1.0e7}\n";
  };
  const double v_lat = engine::critical_speed(test::scenario_from_text(text("lateral")).model, 40, 150, 1e-4);
  const double v_full = engine::critical_speed(test::scenario_from_text(text("full")).model, 40, 150, 1e-4);
  INFO("lateral " << v_lat << " m/s, full " << v_full << " m/s");
  CHECK(v_full == Approx(v_lat).epsilon(0.05));
}
