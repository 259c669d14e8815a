// Critical speed: bifurcation sweep and ramping against the linear critical
// speed (eigenvalues) where the model is linear, the subcritical branch of a
// nonlinear profile, and the Manchester coach of the main job (ramping vs
// bifurcation within 5 %, reduced creep coefficients lower the critical speed).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "contact/reduction.hpp"
#include "engine/analysis/critical_speed.hpp"
#include "config/yaml_input.hpp"
#include "engine/linearisation.hpp"
#include "engine/io/scenario.hpp"
#include "flange_sweep.hpp"
#include "test_support.hpp"

using namespace railsim::engine;

namespace {

const BifurcationPoint* find_point(const BifurcationResult& r, Branch branch, double speed) {
  for (const auto& p : r.points)
    if (p.branch == branch && std::abs(p.speed - speed) < 1e-6) return &p;
  return nullptr;
}

}  // namespace

// Conical wheels (lambda = 0.2), linear creep forces, flange as a stiff spring
// beyond a 9 mm dead band: linear up to the flange, so the hunting onset is the
// Hopf point of the eigenvalue analysis, and above it the limit cycle grows from
// zero (supercritical).
TEST_CASE("single wheelset, linear model: bifurcation and ramping find the linear critical speed",
          "[critical_speed]") {
  const Scenario sc = load_scenario(railsim::test::data_path("scenarios/single_wheelset_flange.yaml"));
  const double v_lin = linear_critical_speed(sc, 20.0, 80.0);
  // physics-reference.md 8.1 (Wickens): 45.59 m/s for this wheelset; the
  // bisection is checked against it in test_linearisation.cpp, here only sanity.
  REQUIRE(v_lin == Approx(45.6).margin(0.2));

  const std::string dir = railsim::test::temp_dir("cs_linear");
  BifurcationOptions o;
  o.v_min = 43.0;
  o.v_max = 49.0;
  o.v_step = 0.5;
  o.duration = 10.0;
  o.threads = 2;
  const BifurcationResult r = bifurcation_sweep(sc, o, dir + "/points.csv");
  // Tolerance: one speed step (0.5 m/s, 1.1 %). Within about 1 % of V_L the
  // motion grows or decays so slowly (rate ~ V - V_L) that 10 s cannot settle
  // it: a point there may still count as hunting (decaying by less than
  // decay_tolerance over the tail).
  CHECK(std::abs(r.nonlinear_critical_speed - v_lin) <= o.v_step);
  for (const auto& p : r.points) {
    // Clearly below V_L: no limit cycle on either branch.
    if (p.speed < v_lin - o.v_step) CHECK_FALSE(is_hunting(p, o));
    // Clearly above: hunting on both branches, and where both have settled
    // (|growth| < 1 % over the tail) on the same limit cycle (one attractor).
    if (p.speed > v_lin + o.v_step) CHECK(is_hunting(p, o));
    const auto* up = find_point(r, Branch::up, p.speed);
    REQUIRE(up != nullptr);
    if (p.branch == Branch::down && std::abs(p.growth) < 0.01 && std::abs(up->growth) < 0.01 && p.amplitude > o.threshold)
      CHECK(up->amplitude == Approx(p.amplitude).epsilon(0.02));
  }

  RampingOptions ro;
  ro.v_start = 52.0;
  ro.v_end = 38.0;
  ro.deceleration = 0.25;
  const RampingResult rr = ramping(sc, ro);
  REQUIRE(rr.hunting_at_start);
  REQUIRE_FALSE(rr.hunting_at_end);
  // Ramping lags the quasi-static answer by the decay time of the transient;
  // at 0.25 m/s^2 within 2 % below V_L (measured: 1.4 %).
  CHECK(rr.critical_speed <= v_lin * 1.002);
  CHECK(rr.critical_speed >= v_lin * 0.98);
}

// S1002/UIC60 1:40: the equivalent conicity rises towards the flange, the
// onset is subcritical: from a large disturbance the wheelset hunts far below
// V_L, from a small one it stays centred up to V_L (two coexisting attractors).
TEST_CASE("single wheelset, S1002/UIC60: subcritical branch below the linear critical speed",
          "[critical_speed]") {
  const Scenario sc = load_scenario(railsim::test::data_path("scenarios/single_wheelset_s1002.yaml"));
  const double v_lin = linear_critical_speed(sc, 40.0, 200.0);
  REQUIRE(std::isfinite(v_lin));
  const std::string dir = railsim::test::temp_dir("cs_s1002");
  BifurcationOptions o;
  o.v_min = 0.60 * v_lin;
  o.v_max = 0.95 * v_lin;
  o.v_step = 0.05 * v_lin;
  o.duration = 6.0;
  o.large_disturbance = 8e-3;
  o.small_disturbance = 0.5e-3;
  o.threads = 2;
  const BifurcationResult r = bifurcation_sweep(sc, o, dir + "/points.csv");
  REQUIRE(std::isfinite(r.nonlinear_critical_speed));
  // Measured: V_NL = 310 km/h against V_L = 433 km/h (ratio 0.72).
  CHECK(r.nonlinear_critical_speed < 0.85 * v_lin);
  int coexisting = 0;
  for (const auto& p : r.points) {
    if (p.branch != Branch::down || !is_hunting(p, o)) continue;
    const auto* up = find_point(r, Branch::up, p.speed);
    REQUIRE(up != nullptr);
    CHECK(p.amplitude > 3e-3);  // flange-contact limit cycle (S1002 flange at ~6-7 mm)
    if (!is_hunting(*up, o)) ++coexisting;
  }
  CHECK(coexisting >= 3);
}

// The main job's scenario (Kalker + CHOPAYA) on the RSGEO S1002/UIC60 table
// where these figures were measured: a test of the analyses (ramping against
// the bifurcation sweep, continuation to the fold, the reduction's effect),
// which hold on any geometry; the table keeps it to a minute (on the coach's
// own profiles geometry the hunting runs cost 5-10 times more: the main
// job's figures on profiles are in the README).
TEST_CASE("Manchester coach: ramping and bifurcation agree, reduced creep coefficients lower the critical speed",
          "[critical_speed]") {
  std::string text =
      railsim::test::read_text(railsim::test::source_path("scenarios/manchester_coach_critical_speed.yaml"));
  const std::string profiles = "geometry: {type: profiles, wheel: S1002, rail: UIC60, inclination: 1/40, r0: 0.46}";
  const auto at = text.find(profiles);
  REQUIRE(at != std::string::npos);
  text.replace(at, profiles.size(), "geometry: {type: table, file: ../vehicles/contact_tables/RSGEO_S1002_UIC60_1in40.dat}");
  const Scenario sc = load_scenario(railsim::config::InputNode::load_string(text, "manchester_coach_table.yaml"),
                                    railsim::test::source_path("scenarios"));
  const auto& cs = sc.critical_speed;
  const std::string dir = railsim::test::temp_dir("cs_coach");
  BifurcationOptions o;
  o.v_min = 250 / 3.6;
  o.v_max = 320 / 3.6;
  o.v_step = cs.v_step;
  o.duration = cs.duration;
  o.large_disturbance = cs.disturbance;
  o.continuation = false;  // every speed from the fixed disturbance first
  o.up_branch = false;
  o.threads = 2;
  const BifurcationResult b = bifurcation_sweep(sc, o, dir + "/full.csv");
  REQUIRE(std::isfinite(b.nonlinear_critical_speed));

  // The sweep resolves the onset only to its step: hunting at the speed it
  // reports, none one step below, so the fold lies in (hi - v_step, hi].
  // Ramping down reads at or below the fold, lagging by the decay time of the
  // collapsing cycle; the lag shrinks as the deceleration falls.
  const double hi = b.nonlinear_critical_speed, lo = hi - o.v_step;
  auto below_bracket = [&](double v) { return std::max(0.0, lo - v) / lo; };
  RampingOptions ro;
  ro.v_start = cs.ramp_start;
  ro.v_end = 220 / 3.6;
  ro.deceleration = cs.deceleration;
  const RampingResult rr = ramping(sc, ro);
  REQUIRE(rr.hunting_at_start);
  REQUIRE_FALSE(rr.hunting_at_end);
  // Issue 8: within 5 % of what the sweep resolves, and never above it
  // (measured: sweep 290 km/h at 10 km/h steps from 7 mm, no hunting at 280;
  // ramping at 0.5 m/s^2 274.5 km/h, 2.0 % below 280).
  CHECK(rr.critical_speed <= hi + 1e-9);
  CHECK(below_bracket(rr.critical_speed) < 0.05);
  // Halving the deceleration halves the time the collapse lags behind the
  // speed: the reading rises towards the fold and stays below the sweep's
  // hunting speed (measured 276.6 km/h at 0.25 m/s^2, 1.2 % below 280).
  RampingOptions slow = ro;
  slow.deceleration = 0.5 * ro.deceleration;
  slow.v_end = 250 / 3.6;
  const RampingResult rs = ramping(sc, slow);
  REQUIRE(rs.hunting_at_start);
  REQUIRE_FALSE(rs.hunting_at_end);
  CHECK(rs.critical_speed > rr.critical_speed);
  CHECK(rs.critical_speed <= hi + 1e-9);
  CHECK(below_bracket(rs.critical_speed) < below_bracket(rr.critical_speed));
  // Path following below the lowest hunting speed: down to the fold (measured
  // 280 km/h, as the serial chain from the top of the branch found); the main
  // job's setting.
  REQUIRE(cs.continuation);
  BifurcationOptions oc = o;
  oc.continuation = true;
  oc.v_min = 260 / 3.6;
  const BifurcationResult bc = bifurcation_sweep(sc, oc, dir + "/continuation.csv");
  // Following the branch never ends above the fixed-disturbance sweep. On the
  // smoothed table (issue 13) both read 290 km/h at 10 km/h steps (on the raw
  // table continuation found 280 km/h); ramping is within the issue-8
  // tolerance of the bracket continuation resolves too.
  CHECK(bc.nonlinear_critical_speed <= b.nonlinear_critical_speed + 1e-9);
  CHECK(rr.critical_speed <= bc.nonlinear_critical_speed + 1e-9);
  CHECK(std::max(0.0, bc.nonlinear_critical_speed - o.v_step - rr.critical_speed) /
            (bc.nonlinear_critical_speed - o.v_step) <
        0.05);

  // Toumi's elastic finite-element factors (k11 0.72, k22 = k23 0.56).
  const auto k = railsim::contact::parse_reduction("elastic_fe", "test");
  const Scenario reduced = with_contact(sc, "", &k);
  o.v_min = 200 / 3.6;
  o.v_max = 260 / 3.6;
  o.continuation = true;
  const BifurcationResult br = bifurcation_sweep(reduced, o, dir + "/reduced.csv");
  REQUIRE(std::isfinite(br.nonlinear_critical_speed));
  // Measured: 240 km/h against 280 km/h (-14.3 %, both with continuation; the
  // main job's figures); the mission's range is up to 40 %.
  const double change = (br.nonlinear_critical_speed - bc.nonlinear_critical_speed) / bc.nonlinear_critical_speed;
  CHECK(change < -0.10);
  CHECK(change > -0.40);
  const double lin = linear_critical_speed(sc, 50.0, 150.0);
  const double lin_reduced = linear_critical_speed(reduced, 50.0, 150.0);
  CHECK(lin_reduced < 0.9 * lin);
}

// Path following on the down branch: started from the limit cycle of the speed
// above, each speed finds the branch down to its fold, whatever the initial
// disturbance; an interrupted chain resumes from the stored state.
TEST_CASE("bifurcation sweep with continuation follows the branch to its fold and resumes", "[critical_speed]") {
  const Scenario sc = load_scenario(railsim::test::data_path("scenarios/single_wheelset_s1002.yaml"));
  const std::string dir = railsim::test::temp_dir("cs_continuation");
  BifurcationOptions o;
  o.v_min = 250 / 3.6;
  o.v_max = 360 / 3.6;
  o.v_step = 10 / 3.6;
  o.duration = 6.0;
  o.large_disturbance = 8e-3;
  o.up_branch = false;
  o.threads = 2;
  const BifurcationResult fixed = bifurcation_sweep(sc, o, dir + "/fixed.csv");
  o.continuation = true;
  const BifurcationResult cont = bifurcation_sweep(sc, o, dir + "/cont.csv");
  REQUIRE(std::isfinite(fixed.nonlinear_critical_speed));
  REQUIRE(std::isfinite(cont.nonlinear_critical_speed));
  // The fold lies below what a fixed disturbance finds: measured 300 km/h with
  // continuation (limit cycle 4.2 mm) against 310 km/h from 8 mm (at 300 km/h
  // the 8 mm start decays: outside the basin of the limit cycle).
  CHECK(cont.nonlinear_critical_speed < fixed.nonlinear_critical_speed - 1e-9);
  // On the branch both settle on the same limit cycle.
  for (const auto& p : cont.points) {
    if (!is_hunting(p, o)) continue;
    const auto* q = find_point(fixed, Branch::down, p.speed);
    REQUIRE(q != nullptr);
    if (is_hunting(*q, o)) CHECK(p.amplitude == Approx(q->amplitude).epsilon(0.02));
  }

  // The chain ran below the lowest speed the 8 mm start keeps hunting.
  int continued = 0;
  for (const auto& p : cont.points) continued += p.continued ? 1 : 0;
  CHECK(continued >= 1);

  // Interrupt it: phase 1 after 4 points (its part files lost), the chain
  // before its last point; the final file is gone. Resuming gives the same file.
  // Then once more with the chain gone and the states file torn inside its
  // last line (the last number cut, no newline): the torn state is ignored,
  // the run it belongs to is repeated, and the result is again the same.
  const std::string full = railsim::test::read_text(dir + "/cont.csv");
  auto keep_lines = [](const std::string& path, std::size_t n) {
    std::ifstream in(path);
    std::string out, line;
    for (std::size_t i = 0; i < n && std::getline(in, line); ++i) out += line + "\n";
    in.close();
    std::ofstream(path, std::ios::trunc) << out;
  };
  const std::string chain = railsim::test::read_text(dir + "/cont.csv.chain.csv");
  const auto chain_rows = static_cast<std::size_t>(std::count(chain.begin(), chain.end(), '\n')) - 1;
  REQUIRE(chain_rows == static_cast<std::size_t>(continued));
  keep_lines(dir + "/cont.csv.chain.csv", chain_rows);  // header + all but the last
  keep_lines(dir + "/cont.csv.sweep.csv", 1 + 4);
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().filename().string().rfind("cont.csv.sweep.csv.part", 0) == 0) std::filesystem::remove(e.path());
  std::filesystem::remove(dir + "/cont.csv");
  const BifurcationResult again = bifurcation_sweep(sc, o, dir + "/cont.csv");
  CHECK(railsim::test::read_text(dir + "/cont.csv") == full);

  std::filesystem::remove(dir + "/cont.csv.chain.csv");
  std::filesystem::remove(dir + "/cont.csv");
  {
    // Keep the states of the phase-1 runs only; the one of the lowest hunting
    // speed (where the chain starts) goes last, torn.
    char vh_key[64];
    std::snprintf(vh_key, sizeof vh_key, "down:%.6g,", fixed.nonlinear_critical_speed);
    std::ifstream in(dir + "/cont.csv.down.states");
    std::string kept, vh_line, line;
    while (std::getline(in, line)) {
      if (line.rfind(vh_key, 0) == 0) vh_line = line;
      else if (line.rfind("down:", 0) == 0) kept += line + "\n";
    }
    in.close();
    REQUIRE(vh_line.size() > 20);
    kept += vh_line.substr(0, vh_line.size() - 5);  // its last number cut, no newline
    std::ofstream(dir + "/cont.csv.down.states", std::ios::trunc) << kept;
  }
  const BifurcationResult torn = bifurcation_sweep(sc, o, dir + "/cont.csv");
  CHECK(railsim::test::read_text(dir + "/cont.csv") == full);
  CHECK(torn.nonlinear_critical_speed == cont.nonlinear_critical_speed);
  CHECK(again.nonlinear_critical_speed == cont.nonlinear_critical_speed);
}

// The Cooperrider car (lateral wheelset model, RSGEO table) has an undamped
// bogie-pitch mode (no pitch damper; real part at rounding level, ~1e-13
// 1/s). At 100 m/s, below the hunting onset, it is the least damped mode:
// the start test of linear_critical_speed must not read it as a loss of
// stability (it returned the range's lower end, 360 km/h). DYTSI's linear
// critical speed of the same car: 109.0 m/s (issue 14; railsim measured
// 109.9 m/s before the geometry was smoothed).
TEST_CASE("linear critical speed: an undamped mode at the range start is not a loss of stability",
          "[critical_speed]") {
  std::string text = railsim::test::read_text(railsim::test::source_path("scenarios/cooperrider_car.yaml"));
  const auto at = text.find("wheelset_model: full");
  REQUIRE(at != std::string::npos);
  text.replace(at, 20, "wheelset_model: lateral");
  const Scenario sc = load_scenario(railsim::config::InputNode::load_string(text, "cooperrider_car_lateral.yaml"),
                                    railsim::test::source_path("scenarios"));
  const double lo = max_real_part(sc.model, 100.0);
  INFO("largest real part at 100 m/s: " << lo << " 1/s");
  CHECK(std::abs(lo) < kUnstableGrowth);  // the undamped mode is there and leads
  const double v = linear_critical_speed(sc, 100.0, 130.0);
  CHECK(v > 100.5);
  CHECK(v == Approx(109.0).epsilon(0.03));
  CHECK(max_real_part(sc.model, 0.99 * v) < kUnstableGrowth);
  CHECK(max_real_part(sc.model, 1.01 * v) > kUnstableGrowth);
}

TEST_CASE("bifurcation sweep: numerical failures and runs too short give no critical speed, not hunting",
          "[critical_speed][robustness]") {
  const Scenario base = load_scenario(railsim::test::data_path("scenarios/single_wheelset_flange.yaml"));
  BifurcationOptions o = railsim::test::flange_sweep_options();
  SECTION("an integrator that cannot take a step: every point fails numerically") {
    Scenario sc = base;
    sc.integrator.max_steps = 3;  // a forced blow-up: legal, but no run gets far
    const auto r = bifurcation_sweep(sc, o, railsim::test::temp_dir("numerical_failure") + "/points.csv");
    REQUIRE(r.points.size() == 3);
    for (const auto& p : r.points) {
      CHECK(p.numerical_failure);
      CHECK_FALSE(p.failed);
      CHECK(point_state(p, o) == PointState::failed);
      CHECK_FALSE(is_hunting(p, o));
    }
    CHECK(std::isnan(r.nonlinear_critical_speed));
    CHECK(r.undetermined_kind == BifurcationResult::Undetermined::numerical_failure);
    CHECK(r.undetermined.find("48.0 km/h") == std::string::npos);  // speeds in km/h: 48 m/s is 172.8 km/h
    CHECK(r.undetermined.find("172.8 km/h") != std::string::npos);
    CHECK(r.undetermined.find("numerical failure") != std::string::npos);
  }
  SECTION("a resumed sweep refuses a damaged points file instead of reading a verdict from it") {
    const std::string out = railsim::test::temp_dir("damaged_points") + "/points.csv";
    bifurcation_sweep(base, o, out);  // the folder's settings file (points.csv.settings), then its points damaged
    std::ofstream(out) << "index,key,speed_m_s,down,amplitude_m,frequency_hz,growth,stop\n"
                          "0,down:48,48,1,0.004,2.1,0,0\n1,down:46,46,1,nan,2.0,0,0\n2,down:44,44,1,0.0001,0,0,0\n";
    CHECK_THROWS_WITH(bifurcation_sweep(base, o, out),
                      Catch::Contains("points.csv: point 'down:46'") && Catch::Contains("damaged file"));
    // A file of an earlier version, whose "failed" column said 1 for any stop (numerical ones too): refused,
    // not read as derailments (which count as hunting).
    std::ofstream(out) << "index,key,speed_m_s,down,amplitude_m,frequency_hz,growth,failed\n"
                          "0,down:48,48,1,0.004,2.1,0,1\n1,down:46,46,1,0.004,2.0,0,1\n2,down:44,44,1,0.0001,0,0,0\n";
    CHECK_THROWS_WITH(bifurcation_sweep(base, o, out),
                      Catch::Contains("points.csv: its columns") && Catch::Contains("another version"));
  }
  SECTION("runs too short to show a cycle in their tail") {
    o.duration = 0.5;  // tail 0.15 s: less than one hunting half-cycle (about 2-3 Hz here)
    const auto r = bifurcation_sweep(base, o, railsim::test::temp_dir("too_short") + "/points.csv");
    REQUIRE(r.points.size() == 3);
    const BifurcationPoint* top = find_point(r, Branch::down, 48.0);
    REQUIRE(top != nullptr);
    CHECK(top->amplitude > o.threshold);
    CHECK(top->frequency == 0.0);
    CHECK(point_state(*top, o) == PointState::too_short);
    CHECK(std::isnan(r.nonlinear_critical_speed));
    CHECK(r.undetermined_kind == BifurcationResult::Undetermined::too_short);
    CHECK(r.undetermined.find("--duration") != std::string::npos);
  }
}
