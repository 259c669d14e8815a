// `railsim run`: channels.csv and summary.json are written; bad input exits 2,
// numerical failure exits 3 with the diagnostic (and a summary saying so).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "contact/geometry/profile.hpp"
#include "contact/geometry/wheel_rail_geometry.hpp"
#include "core/errors.hpp"
#include "results/csv_writer.hpp"
#include "json_support.hpp"
#include "test_support.hpp"

using namespace railsim;

TEST_CASE("railsim run writes channels and summary", "[engine][cli]") {
  const std::string out = test::temp_dir("run_single");
  const auto r = test::run_railsim("run " + test::source_path("scenarios/single_wheelset.yaml") + " --out " + out);
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const auto csv = results::read_csv(out + "/channels.csv");
  CHECK(csv.rows.size() == 801);  // 4 s every 5 ms, plus t = 0
  // The 10 mm defect displaces the wheelset by several mm (it follows the rails): the max shift
  // in the summary is relative to the rails (ws1.y_rel), the absolute one is labelled (ws1.y).
  double maxy = 0, maxrel = 0;
  for (std::size_t i = 0; i < csv.rows.size(); ++i) {
    maxy = std::max(maxy, std::abs(csv.number(i, "ws1.y")));
    maxrel = std::max(maxrel, std::abs(csv.number(i, "ws1.y_rel")));
  }
  CHECK(maxy > 0.005);
  CHECK(maxrel < 0.5 * maxy);
  const auto js = test::read_json(out + "/summary.json");
  CHECK(js["status"] == "ok");
  CHECK(js["integrator_statistics"]["rhs_calls"].get<long>() > 0);
  CHECK(js["real_time_factor"].get<double>() > 0.0);
  CHECK(js["max_lateral_shift"].get<double>() == Approx(maxrel).epsilon(1e-9));
  CHECK(js["max_lateral_shift_absolute"].get<double>() == Approx(maxy).epsilon(1e-9));
  // Y/Q and wear-number channels.
  CHECK(csv.number(400, "ws1.L.YQ") == Approx(csv.number(400, "ws1.L.Y") / csv.number(400, "ws1.L.Q")));
  CHECK(csv.number(400, "ws1.R.Tgamma") >= 0.0);
}

TEST_CASE("railsim run: running safety and curving of the coach in the R 300 m curve", "[engine][cli]") {
  const std::string out = test::temp_dir("run_coach_R300");
  const auto r =
      test::run_railsim("run " + test::source_path("scenarios/manchester_coach_curve_R300.yaml") + " --out " + out);
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const auto js = test::read_json(out + "/summary.json");
  const auto& rs = js["running_safety"];
  for (const char* key : {"nadal_limit", "flange_angle_deg", "wheelsets", "limits", "en14363_evaluated"})
    CHECK(rs.contains(key));
  const auto& w0 = rs["wheelsets"][0];
  for (const char* key : {"sum_y_2m", "wheel_unloading", "en14363_pass"}) CHECK(w0.contains(key));
  CHECK(w0["wheels"]["left"].contains("yq_instantaneous"));
  CHECK(w0["wheels"]["left"].contains("yq_2m"));
  const auto& c0 = js["curving"]["curves"][0];
  CHECK(c0.contains("sum_Y_expected_M_a_nc"));
  CHECK(c0["wheelsets"][0].contains("angle_of_attack_mrad"));
  CHECK(c0["wheelsets"][0]["wheels"]["left"].contains("Tgamma"));
  // Flange angle from the run's own S1002/UIC60 1:40 geometry (no fallback),
  // held against the exact rigid contact search on the same profiles: its
  // largest contact angle over the geometry's +-15 mm (the flank of S1002 is
  // 70 deg, EN 13715; contact reaches just below its steepest part). Nadal's
  // (tan g - mu) / (1 + mu tan g) with mu = 0.3.
  CHECK(rs["flange_angle_fallback"] == false);
  const double g = rs["flange_angle_deg"].get<double>() * std::acos(-1.0) / 180.0;
  CHECK(rs["nadal_limit"].get<double>() == Approx((std::tan(g) - 0.3) / (1 + 0.3 * std::tan(g))).epsilon(1e-9));
  {
    contact::TrackSetup track;
    track.inclination = std::atan(1.0 / 40.0);
    const contact::WheelRailGeometry exact(contact::read_profile("S1002", contact::ProfileKind::wheel),
                                           contact::read_profile("UIC60", contact::ProfileKind::rail), track);
    double g_exact = 0.0;
    for (double y = 0.0; y <= 15e-3 + 1e-12; y += 0.05e-3) {
      try {
        const auto c = exact.solve(y);
        for (int p = 0; p < c.wheel[0].n; ++p) g_exact = std::max(g_exact, c.wheel[0].p[std::size_t(p)].angle);
      } catch (const InputError&) {
        break;  // past the flange: out of the profiles' range
      }
    }
    INFO("exact search: largest contact angle " << g_exact * 180.0 / std::acos(-1.0) << " deg");
    CHECK(g_exact > 60.0 * std::acos(-1.0) / 180.0);
    // The run's figure is the largest angle of a loaded patch (the load-weighted
    // mean over its strips: 69.4 deg), the exact search's the steepest single
    // point (70.1 deg): within 1 deg (Nadal 1.315 against 1.347).
    CHECK(g <= g_exact + 1e-9);
    CHECK(g == Approx(g_exact).margin(1.0 * std::acos(-1.0) / 180.0));
  }
  CHECK(c0["radius_m"].get<double>() == Approx(300.0).epsilon(1e-9));
  // 102 mm cant deficiency at 80 km/h: safe (EN 14363 and Nadal).
  CHECK(rs["pass"] == true);
  CHECK(std::ifstream(out + "/yq.png").good());
  const auto csv = results::read_csv(out + "/channels.csv");
  // Leading wheel, outer (left) side in the body of the right-hand curve (reference 300 m):
  // flange contact, |Y/Q| between 0.2 and 0.8, wear number well above the inner wheel's.
  std::size_t i = 0;
  while (i + 1 < csv.rows.size() && csv.number(i, "distance") < 300.0) ++i;
  CHECK(csv.number(i, "ws1.L.YQ") < -0.2);
  CHECK(csv.number(i, "ws1.L.YQ") > -0.8);
  CHECK(csv.number(i, "ws1.L.Tgamma") > 1.5 * csv.number(i, "ws1.R.Tgamma"));
}

TEST_CASE("railsim run: bad scenario exits 2, numerical failure exits 3", "[engine][cli]") {
  const std::string out = test::temp_dir("run_bad");
  auto r = test::run_railsim("run " + test::data_path("engine/bad_scenario.yaml") + " --out " + out);
  CHECK(r.exit_code == 2);
  CHECK(r.output.find("bad_scenario.yaml:") != std::string::npos);
  r = test::run_railsim("run " + test::data_path("engine/unstable_scenario.yaml") + " --out " + out);
  INFO(r.output);
  CHECK(r.exit_code == 3);
  CHECK(r.output.find("exceeds the admissible") != std::string::npos);
  const auto failed = test::read_json(out + "/summary.json");
  CHECK(failed["status"] == "failed");
  CHECK(failed["error"].get<std::string>().find("exceeds the admissible") != std::string::npos);
}

TEST_CASE("railsim run --contact-audit: bad counts and tolerances exit 2 naming the option", "[engine][cli][audit]") {
  const std::string out = test::temp_dir("run_audit_bad");
  const std::string base = "run " + test::source_path("scenarios/single_wheelset.yaml") + " --out " + out + " ";
  // Past the int type too (CLI11 said only "Could not convert"), and not whole.
  for (const char* n : {"0", "-5", "10001", "99999999999", "1e20"}) {
    const auto r = test::run_railsim(base + "--contact-audit " + n);
    INFO(r.output);
    CHECK(r.exit_code == 2);
    CHECK(r.output.find("--contact-audit") != std::string::npos);
    CHECK(r.output.find("[1, 10000]") != std::string::npos);
  }
  for (const char* tol : {"0", "-1", "nan", "inf", "101"}) {
    const auto r = test::run_railsim(base + "--contact-audit 5 --audit-tolerance " + tol);
    INFO(r.output);
    CHECK(r.exit_code == 2);
    CHECK(r.output.find("--audit-tolerance") != std::string::npos);
  }
  {
    const auto r = test::run_railsim(base + "--contact-audit 2.5");
    INFO(r.output);
    CHECK(r.exit_code == 2);
    CHECK(r.output.find("--contact-audit: expected a whole number (got '2.5')") != std::string::npos);
  }
  // The audit's settings without the audit were ignored silently.
  for (const char* opt : {"--audit-tolerance 5", "--audit-threads 2"}) {
    const auto r = test::run_railsim(base + opt + " --set duration=0.05");
    INFO(r.output);
    CHECK(r.exit_code == 2);
    CHECK(r.output.find(std::string(opt).substr(0, std::string(opt).find(' ')) +
                        ": applies to the contact audit; give --contact-audit N") != std::string::npos);
  }
  // Another whole-number option past int: named, not "Could not convert".
  for (const char* t : {"99999999999", "65", "1.5"}) {
    const auto r = test::run_railsim(base + "--contact-audit 5 --audit-threads " + t);
    INFO(r.output);
    CHECK(r.exit_code == 2);
    CHECK(r.output.find("--audit-threads") != std::string::npos);
    CHECK(r.output.find("Could not convert") == std::string::npos);
  }
  // A run whose contact has no patch shape (prescribed creep coefficients): bad input, said so.
  const auto r = test::run_railsim(base + "--contact-audit 5 --set duration=0.05");
  INFO(r.output);
  CHECK(r.exit_code == 2);
  CHECK(r.output.find("patch") != std::string::npos);
}
