// Lateral wheelset model: Klingel's kinematic wavelength (physics-reference
// §8.2), quasi-static wheel loads and the loss-of-contact diagnostic.
#include <catch2/catch.hpp>

#include <cmath>

#include "core/errors.hpp"
#include "engine/linearisation.hpp"
#include "engine/simulation.hpp"
#include "engine/system.hpp"
#include "engine/engine_test_support.hpp"
#include "test_support.hpp"

using namespace railsim;

TEST_CASE("free conical wheelset oscillates with Klingel's wavelength", "[engine][wheelset]") {
  const double r0 = 0.46, l0 = 0.75, lambda = 0.2;
  const double LK = 2 * M_PI * std::sqrt(r0 * l0 / lambda);  // 8.25 m
  CHECK(LK == Approx(8.25).epsilon(1e-3));
  const double V = 5.0;  // low speed: creep forces dominate inertia
  auto sc = test::single_wheelset(V, 1e7, "tests/data/engine/free_wheelset.yaml",
                                  "integrator: {method: cvode_bdf, rtol: 1.0e-9, atol: 1.0e-12, max_step: 0.005}\n"
                                  "initial: {ws1.lateral: 0.001}\n");
  // From the eigenvalues: the kinematic mode's wavelength V / f.
  const auto md = engine::modes(sc.model, Eigen::VectorXd::Zero(sc.model.n_states));
  REQUIRE(!md.empty());
  double best = 1e9;
  for (const auto& m : md) best = std::min(best, std::abs(V / m.frequency - LK));
  CHECK(best / LK < 0.02);
  // From a time run: distance between upward zero crossings of y.
  const int qi = sc.model.bodies[0].q_index[engine::kLat];
  std::vector<double> crossings;
  double prev_t = 0, prev_y = 0.001;
  engine::simulate(sc.model, sc.integrator, sc.x0, 8.0, 0.001, [&](double t, const Eigen::VectorXd& x, const engine::Data&) {
    const double y = x[qi];
    if (prev_y < 0 && y >= 0) crossings.push_back(prev_t + (t - prev_t) * (-prev_y) / (y - prev_y));
    prev_t = t;
    prev_y = y;
  });
  REQUIRE(crossings.size() >= 3);
  const double period = (crossings.back() - crossings.front()) / double(crossings.size() - 1);
  INFO("time-run wavelength " << V * period << " m, Klingel " << LK << " m");
  CHECK(V * period == Approx(LK).epsilon(0.02));
}

TEST_CASE("lateral model: wheel loads at rest are half the wheelset weight", "[engine][wheelset]") {
  auto sc = test::single_wheelset(20.0);
  engine::Data d(sc.model);
  Eigen::VectorXd xd(sc.model.n_states);
  engine::rhs_or_throw(sc.model, d, 0.0, sc.x0.data(), xd.data());
  const double W = 1813 * engine::kGravity;
  CHECK(d.wheel[0].Q == Approx(W / 2).epsilon(1e-12));
  CHECK(d.wheel[1].Q == Approx(W / 2).epsilon(1e-12));
  CHECK(xd.norm() == Approx(0.0).margin(1e-12));
}

TEST_CASE("lateral and full wheelset models agree over the lateral defect", "[engine][wheelset]") {
  // Same single wheelset and defect; the full model adds vertical, roll and
  // spin dynamics with elastic contact, which barely change the lateral motion
  // of conical wheels (gravitational stiffness 2 N lambda / l0 ~ 5 kN/m << 1 MN/m).
  auto lat = engine::load_scenario(test::source_path("scenarios/single_wheelset.yaml"));
  auto full = test::scenario_from_text(
      "vehicle: vehicles/single_wheelset.yaml\n"
      "track: {segments: [{type: straight, length: 400}], irregularities: [{type: defect, channel: lateral, start: 20, "
      "wavelength: 20, amplitude_mm: 10}]}\n"
      "speed: 40\nduration: 4\noutput_interval: 0.005\nwheelset_model: full\n"
      "contact:\n  geometry: {type: conical, r0: 0.46, conicity: 0.2, l0: 0.75, contact_angle: 0}\n"
      "  tangential: coefficients\n  creep_coefficients: {f11: 1.0e7, f22: 1.0e7}\n  spin: false\n"
      "integrator: {method: cvode_bdf, rtol: 1.0e-7, atol: 1.0e-9, max_step: 0.002}\n");
  std::vector<double> yl, yf;
  const int ql = lat.model.bodies[0].q_index[engine::kLat];
  const int qf = full.model.bodies[0].q_index[engine::kLat];
  engine::simulate(lat.model, lat.integrator, lat.x0, lat.duration, lat.output_interval,
                   [&](double, const Eigen::VectorXd& x, const engine::Data&) { yl.push_back(x[ql]); });
  engine::simulate(full.model, full.integrator, full.x0, full.duration, full.output_interval,
                   [&](double, const Eigen::VectorXd& x, const engine::Data&) { yf.push_back(x[qf]); });
  REQUIRE(yl.size() == yf.size());
  double peak = 0, err = 0;
  for (std::size_t i = 0; i < yl.size(); ++i) {
    peak = std::max(peak, std::abs(yl[i]));
    err = std::max(err, std::abs(yl[i] - yf[i]));
  }
  INFO("peak " << peak * 1e3 << " mm, max difference " << err / peak * 100 << " % of peak");
  CHECK(err < 0.03 * peak);
}
