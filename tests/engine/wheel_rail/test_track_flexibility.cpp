// The flexible track under the wheelsets (engine/wheel_rail/track_flexibility.hpp):
// the rail's bending as the Winkler beam's transfer function, the
// quasi-static deflections in a curve as force / stiffness (both wheelset
// models, both curve directions), the lateral model untouched by the
// vertical part, the twist kink of curve_twist as a hump instead of a
// one-sample spike in the full model, and bad input naming the key.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "core/errors.hpp"
#include "engine/analysis/critical_speed.hpp"
#include "engine/analysis/run_history.hpp"
#include "engine/analysis/run_safety.hpp"
#include "engine/data.hpp"
#include "engine/engine_test_support.hpp"
#include "engine/io/scenario.hpp"
#include "engine/simulation.hpp"
#include "engine/system.hpp"
#include "engine/wheel_rail/track_flexibility.hpp"
#include "test_support.hpp"

using namespace railsim;
using namespace railsim::engine;

namespace {

// Straight track whose left rail's height is a cosine of wavenumber Omega and
// whose right rail's is a linear ramp with kinks (0 until 40 m, -6 mm/m to
// 43 m, then level): the two shapes of the tests below.
class ProfileTrack final : public TrackReference {
 public:
  ProfileTrack(double amplitude, double omega) : a_(amplitude), w_(omega) {}
  void sample(double s, TrackSample& out) const override {
    out = TrackSample{};
    out.vert_left = a_ * std::cos(w_ * s);
    out.dvert_left = -a_ * w_ * std::sin(w_ * s);
    if (s > 40.0 && s < 43.0) {
      out.vert_right = -6e-3 * (s - 40.0);
      out.dvert_right = -6e-3;
    } else if (s >= 43.0) {
      out.vert_right = -18e-3;
    }
  }
  std::string describe() const override { return "test profile"; }

 private:
  double a_, w_;
};

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace

// A rail over a support of height z_s lies along z_s convolved with the
// beam's influence line: a cosine of wavenumber Omega keeps 1 / (1 + (Omega /
// beta)^4 / 4) of its amplitude (Hetenyi 1946); a linear ramp keeps its
// heights away from the kinks and its slope becomes continuous.
TEST_CASE("track flexibility: the rails' bending is the Winkler beam's transfer function", "[engine][track]") {
  const double EI = 6.38e6, k = 7.15e7;
  const double beta = rail_foundation_beta(k, EI);
  CHECK(beta == Approx(std::cbrt(k / (8.0 * EI))));
  // The beam's own beta from the foundation modulus: k = 2 k_f / beta, beta^4 = k_f / (4 EI).
  const double kf = 0.5 * k * beta;
  CHECK(std::pow(kf / (4.0 * EI), 0.25) == Approx(beta).epsilon(1e-12));
  for (double lambda : {2.0, 3.0, 5.0, 10.0, 30.0}) {
    const double omega = 2.0 * M_PI / lambda;
    const ProfileTrack track(1e-3, omega);
    const SmoothedRailGeometry g(track, 200.0, beta);
    const double H = 1.0 / (1.0 + std::pow(omega / beta, 4) / 4.0);
    double zmax = 0.0;
    for (double s = 60.0; s < 60.0 + lambda; s += lambda / 400.0) {
      double z[2], dz[2];
      g.at(s, z, dz);
      zmax = std::max(zmax, std::abs(z[0]));
      // The slope is the derivative of the height (numerically).
      double zp[2], zm[2], d[2];
      g.at(s + 1e-4, zp, d);
      g.at(s - 1e-4, zm, d);
      CHECK(dz[0] == Approx((zp[0] - zm[0]) / 2e-4).margin(1e-3 * 1e-3 * omega));
    }
    INFO("wavelength " << lambda << " m: amplitude " << zmax << " against " << 1e-3 * H);
    CHECK(zmax == Approx(1e-3 * H).epsilon(0.01));
  }
  // The ramp: level heights kept, the kink's slope step spread over metres.
  const ProfileTrack track(0.0, 1.0);
  const SmoothedRailGeometry g(track, 200.0, beta);
  double z[2], dz[2];
  g.at(30.0, z, dz);
  CHECK(z[1] == Approx(0.0).margin(1e-6));
  g.at(55.0, z, dz);
  CHECK(z[1] == Approx(-18e-3).margin(1e-5));
  g.at(41.5, z, dz);
  CHECK(z[1] == Approx(-9e-3).margin(1e-4));  // the ramp's middle, by symmetry
  double largest_jump = 0.0, prev = 0.0;
  for (double s = 38.0; s < 45.0; s += 0.01) {
    g.at(s, z, dz);
    if (s > 38.0) largest_jump = std::max(largest_jump, std::abs(dz[1] - prev));
    prev = dz[1];
  }
  INFO("largest change of the rail's slope over 1 cm: " << largest_jump);
  CHECK(largest_jump < 0.02 * 6e-3);  // unsmoothed: the whole 6e-3 at each kink
}

// In a steady curve the track's lateral mass is deflected by the wheelset's
// lateral force and each rail by its wheel's load above the static one:
// y_t = -(Y_L + Y_R) / k_y, z_i = -(Q_i - Q0_i) / k_z, at the quasi-static
// start; opposite lateral deflections in the mirrored curve. The lateral model
// has the lateral mass only.
TEST_CASE("track flexibility: quasi-static deflections in a curve are force over stiffness", "[engine][track]") {
  const std::string base = read_text(test::data_path("engine/coach_curve_R300_profiles.yaml"));
  const double ky = 5.5e7, kz = 7.15e7;
  const std::string flex = "track_flexibility:\n  lateral: {mass: 370, stiffness: 5.5e7, damping: 7.0e4}\n"
                           "  vertical: {mass: 180, stiffness: 7.15e7, damping: 6.0e4}\n";
  for (const char* model : {"lateral", "full"}) {
    double deflection[2] = {0.0, 0.0};
    for (int dir = 0; dir < 2; ++dir) {
      std::string t = base;
      t.replace(t.find("wheelset_model: lateral\n"), 24, std::string("wheelset_model: ") + model + "\n" + flex);
      t.replace(t.find("start_distance: 15"), 18, "start_distance: 120");
      if (dir == 1) t.replace(t.find("direction: right"), 16, "direction: left");
      t.replace(t.find("vehicle: ../../../"), 18, "vehicle: ");
      const Scenario sc = test::scenario_from_text(t);
      const Model& m = sc.model;
      Data d(m);
      Eigen::VectorXd xd(m.n_states);
      REQUIRE(rhs(m, d, 0.0, sc.x0.data(), xd.data()));
      // The channels carry the rails' positions (here the deflections: the track is perfect).
      const std::vector<std::string> names = channel_names(m);
      std::vector<double> row;
      channel_row(m, 0.0, sc.x0, d, row);
      REQUIRE(row.size() == names.size());
      auto column = [&](const std::string& name) {
        const auto it = std::find(names.begin(), names.end(), name);
        return it == names.end() ? -1 : int(it - names.begin());
      };
      REQUIRE(column("ws1.track_y") >= 0);
      CHECK(row[std::size_t(column("ws1.track_y"))] == sc.x0[m.wheelsets[0].track_lateral_state]);
      CHECK((column("ws1.R.rail_z") >= 0) == (std::string(model) == "full"));
      if (column("ws1.R.rail_z") >= 0)
        CHECK(row[std::size_t(column("ws1.R.rail_z"))] == sc.x0[m.wheelsets[0].rail_vertical_state[1]]);
      for (std::size_t w = 0; w < m.wheelsets.size(); ++w) {
        const Wheelset& ws = m.wheelsets[w];
        INFO(model << " model, curve " << (dir == 0 ? "right" : "left") << ", " << ws.name);
        REQUIRE(ws.track_lateral_state >= 0);
        const double Y = d.wheel[2 * w].Y + d.wheel[2 * w + 1].Y;
        const double yt = sc.x0[ws.track_lateral_state];
        if (w == 0) CHECK(std::abs(Y) > 1e4);  // the curve loads the track under the leading wheelset
        CHECK(yt == Approx(-Y / ky).epsilon(2e-3).margin(1e-8));
        if (w == 0) deflection[dir] = yt;
        if (std::string(model) == "lateral") {
          CHECK(ws.rail_vertical_state[0] < 0);
          continue;
        }
        for (int i = 0; i < 2; ++i) {
          REQUIRE(ws.rail_vertical_state[i] >= 0);
          const double dQ = d.wheel[2 * w + std::size_t(i)].Q - ws.static_vertical_load[i];
          CHECK(sc.x0[ws.rail_vertical_state[i]] == Approx(-dQ / kz).epsilon(2e-3).margin(1e-8));
        }
      }
    }
    INFO(model << ": leading wheelset's track deflection right / left curve " << deflection[0] << " / " << deflection[1]);
    CHECK(deflection[0] > 0.0);  // right-hand curve: the leading wheelset pushes the outer (left) rail outward
    CHECK(deflection[1] == Approx(-deflection[0]).epsilon(0.01));
  }
}

// The lateral wheelset model's loads are quasi-static: the vertical track
// adds no states and changes nothing.
TEST_CASE("track flexibility: the lateral model ignores the vertical part", "[engine][track]") {
  std::string t = read_text(test::data_path("engine/coach_curve_R300_profiles.yaml"));
  t.replace(t.find("vehicle: ../../../"), 18, "vehicle: ");
  const Scenario rigid = test::scenario_from_text(t);
  t.replace(t.find("wheelset_model: lateral\n"), 24,
            "wheelset_model: lateral\ntrack_flexibility:\n  vertical: {mass: 180, stiffness: 7.15e7, damping: 6.0e4, "
            "bending_stiffness: 6.38e6}\n");
  const Scenario flexible = test::scenario_from_text(t);
  REQUIRE(flexible.model.n_states == rigid.model.n_states);
  Data d1(rigid.model), d2(flexible.model);
  Eigen::VectorXd x = rigid.x0, f1(rigid.model.n_states), f2(rigid.model.n_states);
  x[rigid.model.bodies[std::size_t(rigid.model.wheelsets[0].body)].q_index[kLat]] = 3e-3;
  for (double t0 : {0.0, 1.3, 2.7}) {
    REQUIRE(rhs(rigid.model, d1, t0, x.data(), f1.data()));
    REQUIRE(rhs(flexible.model, d2, t0, x.data(), f2.data()));
    CHECK((f1 - f2).cwiseAbs().maxCoeff() == 0.0);
  }
}

// The coach's full model through curve_twist at 60 km/h: on rigid rails the
// twist ramp's kink is an impact, and |Y/Q| of the leading outer wheel peaks
// in one sample far above its 2 m mean; on the scenario's flexible track the
// peak is a hump whose 2 m mean is within 5 % of it, for every wheel.
TEST_CASE("track flexibility: the twist kink is no spike in the full model", "[engine][track][safety]") {
  std::string t = read_text(test::source_path("scenarios/manchester_coach_curve_twist.yaml"));
  t.replace(t.find("wheelset_model: lateral\n"), 24, "wheelset_model: full\n");
  t.replace(t.find("vehicle: ../"), 12, "vehicle: ");
  t.replace(t.find("track: ../"), 10, "track: ");
  REQUIRE(t.find("track_flexibility:") != std::string::npos);
  auto worst_ratio = [](const Scenario& sc, std::string& where) {
    RunHistory h(sc.model);
    simulate(sc.model, sc.integrator, sc.x0, sc.duration, sc.output_interval,
             [&](double tt, const Eigen::VectorXd& x, const Data& d) { h.record(sc.model, tt, x, d); });
    const RunSafety r = evaluate_run_safety(h, 70.0 * M_PI / 180.0, 0.3, SafetySettings{});
    // The wheels that matter: the run's largest |Y/Q| and every peak above half of it.
    double largest = 0.0;
    for (const auto& ws : r.wheelsets)
      for (int i = 0; i < 2; ++i) largest = std::max(largest, ws.wheel[i].max_abs_yq.value);
    double worst = 0.0;
    for (const auto& ws : r.wheelsets)
      for (int i = 0; i < 2; ++i) {
        const WheelSafety& w = ws.wheel[i];
        if (w.max_abs_yq.value < 0.5 * largest) continue;
        const double ratio = w.max_abs_yq.value / w.max_yq_2m.value;
        if (ratio > worst) {
          worst = ratio;
          where = ws.name + (i == 0 ? " left" : " right") + ": instantaneous " + std::to_string(w.max_abs_yq.value) +
                  ", 2 m mean " + std::to_string(w.max_yq_2m.value);
        }
      }
    return worst;
  };
  std::string where;
  const double flexible = worst_ratio(test::scenario_from_text(t), where);
  INFO("flexible track, worst wheel " << where);
  CHECK(flexible < 1.05);
  std::string rigid_text = t;
  const std::size_t a = rigid_text.find("track_flexibility:");
  rigid_text.erase(a, rigid_text.find("\n", rigid_text.find("vertical:", a)) + 1 - a);
  const double rigid = worst_ratio(test::scenario_from_text(rigid_text), where);
  INFO("rigid rails, worst wheel " << where);
  CHECK(rigid > 1.5);
}

TEST_CASE("track flexibility: bad input names the key and the range", "[engine][track][bad_input]") {
  const std::string base = read_text(test::data_path("engine/coach_curve_R300_profiles.yaml"));
  auto load = [&](const std::string& flex) {
    std::string t = base;
    t.replace(t.find("vehicle: ../../../"), 18, "vehicle: ");
    t.replace(t.find("wheelset_model: lateral\n"), 24, "wheelset_model: full\n" + flex);
    return test::scenario_from_text(t);
  };
  auto message = [&](const std::string& flex) {
    try {
      load(flex);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string neg = message("track_flexibility:\n  vertical: {mass: 180, stiffness: -1, damping: 6e4}\n");
  CHECK(neg.find("stiffness") != std::string::npos);
  INFO(neg);
  CHECK(neg.find("100000") != std::string::npos);
  const std::string bend = message("track_flexibility:\n  lateral: {mass: 300, stiffness: 5e7, damping: 7e4, "
                                   "bending_stiffness: 1e6}\n");
  CHECK(bend.find("bending_stiffness") != std::string::npos);
  const std::string empty = message("track_flexibility: {}\n");
  CHECK(empty.find("track_flexibility") != std::string::npos);
  const std::string mass = message("track_flexibility:\n  vertical: {stiffness: 7e7, damping: 6e4}\n");
  CHECK(mass.find("mass") != std::string::npos);
  const std::string nan = message("track_flexibility:\n  vertical: {mass: .nan, stiffness: 7e7, damping: 6e4}\n");
  CHECK(nan.find("mass") != std::string::npos);
}

// The rails' bending table covers the whole track with at most 1e6 rows and a
// row every 0.1 / beta: a track too long for both is refused before any table
// is built, naming the key and the longest track allowed (beta = 1.12 1/m:
// 89 km); a 20 km track is tabulated.
TEST_CASE("track flexibility: the rails' bending table is bounded by the track length", "[engine][track][bad_input]") {
  const std::string base = read_text(test::source_path("scenarios/manchester_coach.yaml"));
  auto on_track = [&](int length) {
    std::string t = base;
    t.replace(t.find("wheelset_model: lateral"), 23, "wheelset_model: full");
    t.replace(t.find("vehicle: ../"), 12, "vehicle: ");
    t.replace(t.find("{type: straight, length: 600}"), 29, "{type: straight, length: " + std::to_string(length) + "}");
    return test::scenario_from_text(t + "track_flexibility:\n  vertical: {mass: 180, stiffness: 7.15e7, damping: 6.0e4, "
                                        "bending_stiffness: 6.38e6}\n");
  };
  std::string what = "no error";
  try {
    on_track(200000);
  } catch (const InputError& e) {
    what = e.what();
  }
  INFO(what);
  CHECK(what.find("track_flexibility.vertical.bending_stiffness") != std::string::npos);
  CHECK(what.find("200000 m") != std::string::npos);
  CHECK(what.find("at most 89") != std::string::npos);
  const Scenario sc = on_track(20000);
  REQUIRE(sc.model.track_flexibility.vertical_geometry);
  double z[2], dz[2];
  sc.model.track_flexibility.vertical_geometry->at(19990.0, z, dz);
  CHECK(z[0] == 0.0);  // the track has a lateral defect only: the rails lie level
  CHECK(dz[1] == 0.0);
}

// Stability: a lateral track of ballasted-track stiffness lowers the coach's
// linear critical speed, and a track a hundred times stiffer gives the rigid
// rails' within 0.5 % (the flexible model contains the rigid one as its
// limit), in both wheelset models; likewise a very stiff vertical track in the
// full model.
TEST_CASE("track flexibility: linear critical speed below the rigid track's, the rigid one in the stiff limit",
          "[engine][track][critical_speed]") {
  const std::string base = read_text(test::source_path("scenarios/manchester_coach.yaml"));
  auto with = [&](const std::string& model, const std::string& flex) {
    std::string t = base;
    t.replace(t.find("wheelset_model: lateral"), 23, "wheelset_model: " + model);
    t.replace(t.find("vehicle: ../"), 12, "vehicle: ");
    if (t.find("track: ../") != std::string::npos) t.replace(t.find("track: ../"), 10, "track: ");
    return test::scenario_from_text(t + flex);
  };
  for (const std::string model : {"lateral", "full"}) {
    const double rigid = linear_critical_speed(with(model, ""), 40.0, 150.0);
    const double soft = linear_critical_speed(
        with(model, "track_flexibility:\n  lateral: {mass: 370, stiffness: 5.5e7, damping: 7.0e4}\n"), 40.0, 150.0);
    const double stiff = linear_critical_speed(
        with(model, "track_flexibility:\n  lateral: {mass: 370, stiffness: 5.5e9, damping: 7.0e4}\n"), 40.0, 150.0);
    INFO(model << " model: linear critical speed rigid " << rigid * 3.6 << ", lateral track 55 MN/m " << soft * 3.6
                << ", 5.5 GN/m " << stiff * 3.6 << " km/h");
    REQUIRE(std::isfinite(rigid));
    CHECK(soft < 0.98 * rigid);
    CHECK(stiff == Approx(rigid).epsilon(0.005));
    if (model == "full") {
      const double vstiff = linear_critical_speed(
          with(model, "track_flexibility:\n  vertical: {mass: 180, stiffness: 7.15e9, damping: 6.0e4}\n"), 40.0, 150.0);
      INFO("full model, vertical track 7.15 GN/m: " << vstiff * 3.6 << " km/h");
      CHECK(vstiff == Approx(rigid).epsilon(0.005));
    }
  }
}
