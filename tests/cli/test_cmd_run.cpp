// `railsim run` (cli/cmd_run.cpp): scenario variants by --speed-kmh and --set
// (relative paths from the scenario's folder, bad keys and values exit 2 naming
// the option), the EN 14363 running-safety section of summary.json (every
// quantity with limit, margin, where, when and zone; per zone), the hunting
// coach failing the instability criteria above its critical speed and passing
// below, a bogie failing (Y/Q)_2m on a large alignment defect and passing on a
// small one, lateral shifts relative to the rails, the charts.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "json_support.hpp"
#include "results/csv_writer.hpp"
#include "test_support.hpp"

using namespace railsim;

namespace {

using nlohmann::json;

// The "worst" verdict of quantity `name` in the running_safety section.
json worst_of(const json& js, const std::string& name) {
  for (const auto& q : js["running_safety"]["quantities"])
    if (q["quantity"] == name) return q["worst"];
  FAIL("no quantity " << name);
  return json();
}

double number(const json& j, const std::string& key) { return test::json_number(j, key); }

bool passes(const json& j) { return j.value("pass", false); }

std::string coach(const std::string& speed, const std::string& out) {
  // The main job's coach (S1002/UIC60 1:40 profiles, CHOPAYA), kicked by the 10 mm / 20 m lateral
  // defect of tracks/straight_lateral_defect.yaml (a path relative to scenarios/), 4 s.
  return "run " + test::source_path("scenarios/manchester_coach_critical_speed.yaml") + " --speed-kmh " + speed +
         " --set duration=4 --set track=../tracks/straight_lateral_defect.yaml --out " + out;
}

}  // namespace

TEST_CASE("railsim run: the coach hunting above its critical speed fails the instability criteria, below passes",
          "[cli][run][safety]") {
  // On its own S1002/UIC60 1:40 profiles (equivalent conicity 0.185 at 3 mm) the coach hunts
  // after the defect at 330 km/h (f0 5.3 Hz, above the 4.5 Hz it had on the Cooperrider
  // car's flatter table): (Sum Y)_rms 25.3 kN > 23.2 kN, bogie-frame rms 7.3 m/s^2 > 5.38
  // m/s^2 (measured). At 250 km/h the motion decays (every wheelset's largest shift in the
  // last 0.5 s below 0.35 of its peak after the defect: measured 0.12-0.26 with the free axle,
  // 0.09-0.19 with the imposed axle rotation) and passes both limits ((Sum Y)_rms 14.3 kN
  // against 23.2 kN; below 0.6 of it with the imposed rotation, whose transient decays faster).
  const std::string hot = test::temp_dir("run_hunting_330");
  auto r = test::run_railsim(coach("330", hot));
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  json js = test::read_json(hot + "/summary.json");
  CHECK(js["running_safety"]["pass"] == false);
  CHECK(number(js, "speed_initial") == Approx(330.0 / 3.6));
  const double f0 = number(js["running_safety"]["processing"], "hunting_frequency_hz");
  CHECK(f0 > 4.5);
  CHECK(f0 < 6.0);
  const json rms = worst_of(js, "sum_y_rms");
  INFO(rms);
  CHECK_FALSE(passes(rms));
  CHECK(number(rms, "value") > number(rms, "limit"));
  CHECK(number(rms, "limit") == Approx(23182).margin(50));
  const json bog = worst_of(js, "bogie_ay_rms");
  INFO(bog);
  CHECK_FALSE(passes(bog));
  CHECK(number(bog, "value") > number(bog, "limit"));
  CHECK(std::ifstream(hot + "/sum_y_rms.png").good());
  CHECK(std::ifstream(hot + "/yq.png").good());

  const std::string cold = test::temp_dir("run_hunting_250");
  r = test::run_railsim(coach("250", cold));
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  js = test::read_json(cold + "/summary.json");
  const json rms2 = worst_of(js, "sum_y_rms");
  INFO(rms2);
  CHECK(passes(rms2));
  CHECK(number(rms2, "value") < number(rms2, "limit"));
  const auto ch = railsim::results::read_csv(cold + "/channels.csv");
  for (int w = 1; w <= 4; ++w) {
    const std::string col = "ws" + std::to_string(w) + ".y_rel";
    double early = 0.0, late = 0.0;
    for (std::size_t i = 0; i < ch.rows.size(); ++i) {
      const double t = ch.number(i, "time"), y = std::abs(ch.number(i, col));
      early = std::max(early, y);
      if (t >= 3.5) late = std::max(late, y);
    }
    INFO(col << ": peak |y| " << early << " m, largest in 3.5-4 s " << late << " m");
    CHECK(early > 3e-3);
    CHECK(late < 0.35 * early);
  }
  CHECK(passes(worst_of(js, "bogie_ay_rms")));
  CHECK(js["running_safety"]["pass"] == true);
}

TEST_CASE("railsim run: (Y/Q)_2m fails on a 20 mm alignment defect, passes on 10 mm", "[cli][run][safety]") {
  // The bogie of scenarios/bogie.yaml at 160 km/h over the 20 m cosine defect (amplitude set
  // by --set on a list element): (Y/Q)_2m 0.97 against 0.8, and 0.44 for the 10 mm defect.
  for (int amp : {20, 10}) {
    const std::string out = test::temp_dir("run_bogie_" + std::to_string(amp));
    const auto r = test::run_railsim("run " + test::source_path("scenarios/bogie.yaml") +
                                     " --set 'track.irregularities[0].amplitude_mm=" + std::to_string(amp) +
                                     "' --out " + out);
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    const json js = test::read_json(out + "/summary.json");
    const json yq = worst_of(js, "yq_2m");
    INFO(yq);
    CHECK(number(yq, "limit") == 0.8);
    CHECK(yq["zone"] == "straight");
    if (amp == 20) {
      CHECK_FALSE(passes(yq));
      CHECK(number(yq, "value") > 0.85);
      CHECK(number(yq, "margin") < 0.0);
      CHECK(js["running_safety"]["pass"] == false);
    } else {
      CHECK(passes(yq));
      CHECK(number(yq, "value") < 0.6);
      CHECK(number(yq, "margin") > 0.2);
    }
    // Where and when: on the defect (20..40 m), in its first second.
    CHECK(number(yq, "at_distance") > 20.0);
    CHECK(number(yq, "at_distance") < 60.0);
    CHECK(number(yq, "at_time") < 1.5);
  }
}

TEST_CASE("railsim run: summary lists every quantity with limit, margin, where, when and zone", "[cli][run][safety]") {
  const std::string out = test::temp_dir("run_summary_R300");
  const auto r = test::run_railsim("run " + test::source_path("scenarios/manchester_coach_curve_R300.yaml") +
                                   " --set duration=12 --out " + out);
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const json js = test::read_json(out + "/summary.json");
  const json& rs = js["running_safety"];
  for (const char* q : {"yq_2m", "q_max", "wheel_unloading", "y_qst", "q_qst", "yq_qst", "sum_y_2m", "sum_y_rms",
                        "bogie_ay_rms", "car_ay", "car_az", "car_ay_rms", "car_az_rms", "car_ay_qst"}) {
    INFO(q);
    const json w = worst_of(js, q);
    for (const char* key : {"item", "value", "limit", "margin", "pass", "zone", "at_distance", "at_time"})
      CHECK(w.contains(key));
  }
  for (const auto& q : rs["quantities"]) {
    CHECK(q.contains("limit_source"));
    for (const auto& item : q["items"]) CHECK_FALSE(item["processing"].empty());
  }
  // Processing steps are named, zones come from the alignment, and the summary is per zone.
  const json& pr = rs["processing"];
  CHECK(pr["force_lowpass"].get<std::string>().rfind("Butterworth low-pass, order 4, -3 dB at 20 Hz", 0) == 0);
  CHECK(pr["acceleration_bandpass"].get<std::string>().rfind("Butterworth band-pass", 0) == 0);
  CHECK(pr.contains("hunting_frequency_source"));
  CHECK(rs["zones"][2]["zone"] == "small_radius_curve");
  CHECK(rs["zones"][2]["test_zone"] == "4");
  CHECK(rs["zones"][2]["radius_m"].get<double>() == Approx(300.0));
  REQUIRE(rs["zone_summary"].size() == 3);  // straight, small-radius curve, transition
  for (const auto& z : rs["zone_summary"]) CHECK_FALSE(z["by_quantity"].empty());
  const json yq_item = rs["quantities"][0]["items"][0];
  const auto steps = yq_item["processing"].dump();
  CHECK(steps.find("sliding mean over 2 m, centres every 0.5 m") != std::string::npos);
  CHECK(steps.find("F1 = 0.15 %, F2 = 99.85 % percentile") != std::string::npos);
  CHECK(number(rs, "track_shift_factor_k1") == 1.0);
  // Quasi-static Y of the leading outer wheel in the R 300 m curve: tens of kN, within 60 kN.
  const json yqst = worst_of(js, "y_qst");
  CHECK(number(yqst, "value") > 10e3);
  CHECK(number(yqst, "limit") == 60e3);
  CHECK(yqst["zone"] == "small_radius_curve");
  // Channels: accelerations of the measuring points and the shift relative to the rails.
  const auto csv = results::read_csv(out + "/channels.csv");
  for (const char* c : {"car.ay@bogie1", "car.az@end2", "bogie1.ay@ws1", "ws1.y_rel"}) CHECK_NOTHROW(csv.column(c));
  // A freight-wagon category lowers the track-shift limit by k1 = 0.85 (scenario setting through --set).
  const std::string out2 = test::temp_dir("run_summary_R300_freight");
  const auto r2 = test::run_railsim("run " + test::source_path("scenarios/manchester_coach_curve_R300.yaml") +
                                    " --set duration=3 --set running_safety.vehicle_category=freight --out " + out2);
  INFO(r2.output);
  REQUIRE(r2.exit_code == 0);
  const json js2 = test::read_json(out2 + "/summary.json");
  CHECK(number(js2["running_safety"], "track_shift_factor_k1") == 0.85);
  CHECK(number(worst_of(js2, "sum_y_2m"), "limit") ==
        Approx(0.85 * number(worst_of(js, "sum_y_2m"), "limit")).epsilon(1e-9));
}

TEST_CASE("railsim run: lateral shift relative to the rails on the ERRI track, absolute labelled", "[cli][run]") {
  // Issue 17: on the ERRI track the coach's absolute shift peaks at 7.49 mm, its shift relative
  // to the rails near 3.9 mm; the flange-contact warning (> 6 mm) must use the relative one.
  const std::string out = test::temp_dir("run_erri_shift");
  const auto r = test::run_railsim("run " + test::source_path("scenarios/manchester_coach_200_erri.yaml") +
                                   " --out " + out);
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const json js = test::read_json(out + "/summary.json");
  const double y_rel = number(js, "max_lateral_shift"), y_abs = number(js, "max_lateral_shift_absolute");
  CHECK(y_rel > 0.003);
  CHECK(y_rel < 0.0045);
  CHECK(y_abs > 0.007);
  for (const auto& w : js["warnings"]) CHECK(w.get<std::string>().find("flange contact") == std::string::npos);
  CHECK(js["max_lateral_shift_absolute_definition"].get<std::string>().rfind("relative to the design centre line", 0) ==
        0);
  // The channels hold both: <ws>.y (absolute) and <ws>.y_rel (relative to the rails).
  const auto csv = results::read_csv(out + "/channels.csv");
  double ya = 0.0, yr = 0.0;
  for (std::size_t i = 0; i < csv.rows.size(); ++i) {
    ya = std::max(ya, std::abs(csv.number(i, "ws1.y")));
    yr = std::max(yr, std::abs(csv.number(i, "ws1.y_rel")));
  }
  CHECK(ya == Approx(number(js["max_lateral_shift_absolute_per_wheelset"], "ws1")).epsilon(1e-6));
  CHECK(yr == Approx(number(js["max_lateral_shift_per_wheelset"], "ws1")).epsilon(1e-6));
}

TEST_CASE("railsim run: --set and --speed-kmh errors exit 2 naming the option", "[cli][run]") {
  const std::string s = test::source_path("scenarios/manchester_coach_curve_R300.yaml");
  const std::string out = test::temp_dir("run_set_errors");
  struct Case {
    std::string args, expect;
  };
  const Case cases[] = {
      {"--set contact.material.mu=abc", "--set contact.material.mu=abc: "},
      {"--set contact.material.mu=5", "--set contact.material.mu=5: "},
      {"--set contact.material.muu=0.2", "unknown key"},
      {"--set nokey", "--set nokey: expected key=value"},
      {"--set track.segments[0].length=10", "not a mapping"},
      {"--set 'initial[ws9.lateral]=0.001'", "--set initial[ws9.lateral]=0.001: "},
      {"--set running_safety.vehicle_category=tram", "--set running_safety.vehicle_category=tram: "},
      {"--set 'duration=[1, 2'", "not valid YAML"},
      {"--speed-kmh -5", "--speed-kmh"},
      // Overrides that contradict each other are refused, naming both options.
      {"--set speed=20 --speed-kmh 90", "--speed-kmh 90: the speed is already set by --set speed=20"},
      {"--set speed_kmh=80 --set speed_kmh=90", "--set speed_kmh=90: the speed is already set by --set speed_kmh=80"},
      {"--set contact.material.mu=0.2 --set contact.material.mu=0.3",
       "key 'contact.material.mu' is already set to a different value by --set contact.material.mu=0.2"},
      {"--set 'contact.material={mu: 0.2}' --set contact.material.mu=0.3",
       "key 'contact.material.mu' lies inside key 'contact.material' set by --set contact.material={mu: 0.2}"},
      {"--set contact.material.mu=0.3 --set 'contact.material={mu: 0.2}'",
       "key 'contact.material.mu' lies inside key 'contact.material' set by this option"},
  };
  for (const auto& c : cases) {
    const auto r = test::run_railsim("run " + s + " " + c.args + " --out " + out);
    INFO(c.args << "\n" << r.output);
    CHECK(r.exit_code == 2);
    CHECK(r.output.find(c.expect) != std::string::npos);
  }
  // The unknown key's message names the option and the allowed keys.
  const auto r = test::run_railsim("run " + s + " --set contact.material.muu=0.2 --out " + out);
  CHECK(r.output.find("--set contact.material.muu=0.2: ") != std::string::npos);
  CHECK(r.output.find("allowed here: E, nu, mu, shear_modulus") != std::string::npos);
}

TEST_CASE("railsim run: --set on inline tracks and speed, variants without copied YAML", "[cli][run]") {
  const std::string out = test::temp_dir("run_set_ok");
  // `speed` replaces the scenario's speed_kmh; a list element of the inline track is changed.
  const auto r = test::run_railsim("run " + test::source_path("scenarios/manchester_coach.yaml") +
                                   " --set speed=20 --set 'track.segments[0].length=300' --set duration=1 --out " +
                                   out);
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const json js = test::read_json(out + "/summary.json");
  CHECK(number(js, "speed_initial") == 20.0);
  CHECK(js["overrides"][0] == "--set speed=20");  // the overrides are recorded
  // A key repeated with the same value is no contradiction.
  const auto same = test::run_railsim("run " + test::source_path("scenarios/manchester_coach.yaml") +
                                      " --set speed=20 --set speed=20 --set duration=0.2 --set duration=0.2 --out " +
                                      out + "/same");
  INFO(same.output);
  CHECK(same.exit_code == 0);
  CHECK(number(js["running_safety"]["zones"][0], "end") == 300.0);  // the straight section of the zones
}

TEST_CASE("railsim run: --set through a YAML alias changes that place only, past the track end a warning",
          "[cli][run][robustness]") {
  const std::string s = test::data_path("scenarios/single_wheelset_aliased_segments.yaml");
  const std::string out = test::temp_dir("run_set_alias");
  // segments: [&straight {length: 200}, *straight]; the second set to 300 m: 500 m of track, not 600.
  auto r = test::run_railsim("run " + s + " --set 'track.segments[1].length=300' --out " + out);
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  json js = test::read_json(out + "/summary.json");
  const auto& zones = js["running_safety"]["zones"];
  REQUIRE(!zones.empty());
  CHECK(number(zones[zones.size() - 1], "end") == 500.0);
  CHECK(js["warnings"].empty());  // 40 m in 1 s: well inside the track
  // The whole aliased element replaced: the same 500 m.
  r = test::run_railsim("run " + s + " --set 'track.segments[1]={type: straight, length: 300}' --out " + out);
  REQUIRE(r.exit_code == 0);
  js = test::read_json(out + "/summary.json");
  CHECK(number(js["running_safety"]["zones"][js["running_safety"]["zones"].size() - 1], "end") == 500.0);
  // 40 m/s for 15 s from 0: 600 m on a 400 m track: the run says where it leaves the track.
  r = test::run_railsim("run " + s + " --set duration=15 --set output_interval=0.05 --out " + out);
  REQUIRE(r.exit_code == 0);
  js = test::read_json(out + "/summary.json");
  REQUIRE(js["warnings"].size() == 1);
  const std::string w = js["warnings"][0];
  CHECK(w.find("key 'duration'") != std::string::npos);
  CHECK(w.find("at 144 km/h for 15 s the leading wheelset ends at track distance 600 m, past the track's defined "
               "length 400 m") != std::string::npos);
  CHECK(w.find("t = 10 s") != std::string::npos);
  CHECK(r.output.find("past the track's defined length 400 m") != std::string::npos);  // and said on the terminal
  // The warning is about the scenario's own run: `modes` (its own speeds, no
  // run) loads the same 15 s scenario without it.
  std::string text = test::read_text(s);
  const auto at = text.find("duration: 1\n");
  REQUIRE(at != std::string::npos);
  text.replace(at, 12, "duration: 15\n");
  const auto veh = text.find("../../../vehicles/");
  REQUIRE(veh != std::string::npos);
  text.replace(veh, 18, test::source_path("vehicles/"));
  const std::string longer = out + "/long_run.yaml";
  std::ofstream(longer) << text;
  r = test::run_railsim("modes " + longer + " --v-min 20 --v-max 30 --out " + out + "/modes");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK(r.output.find("past the track") == std::string::npos);
  r = test::run_railsim("run " + longer + " --set output_interval=0.05 --out " + out + "/run15");
  REQUIRE(r.exit_code == 0);
  CHECK(r.output.find("past the track's defined length 400 m") != std::string::npos);
}

TEST_CASE("railsim run: a rerun that fails leaves none of the previous run's files", "[cli][run][robustness]") {
  const std::string s = test::data_path("scenarios/single_wheelset_aliased_segments.yaml");
  const std::string out = test::temp_dir("run_stale");
  auto r = test::run_railsim("run " + s + " --out " + out);
  REQUIRE(r.exit_code == 0);
  REQUIRE(std::filesystem::exists(out + "/yq.png"));
  json js = test::read_json(out + "/summary.json");
  CHECK(js["status"] == "ok");
  // 40 m: less than one 100 m window of (Sum Y)_rms: the chart is not drawn and the summary says why.
  CHECK(js["charts"]["yq.png"] == "written");
  CHECK(std::string(js["charts"]["sum_y_rms.png"]).find("not drawn") == 0);
  CHECK_FALSE(std::filesystem::exists(out + "/sum_y_rms.png"));
  // The same folder, a run that fails numerically: only its own summary is there.
  r = test::run_railsim("run " + s + " --set integrator.max_steps=1 --out " + out);
  INFO(r.output);
  CHECK(r.exit_code == 3);
  js = test::read_json(out + "/summary.json");
  CHECK(js["status"] == "failed");
  for (const char* f : {"yq.png", "yq.png.json", "sum_y_rms.png"})
    CHECK_FALSE(std::filesystem::exists(out + "/" + std::string(f)));
}

TEST_CASE("railsim run: initial deviations that unload a wheel of the lateral model are bad input, not a failure",
          "[cli][run][robustness]") {
  // 30 mm lateral shift is within the key's range (the geometry's 50 mm) but unloads the left wheel of the
  // lateral model at t = 0: before, exit 3 "numerical failure" and summary.json status failed.
  const std::string out = test::temp_dir("run_initial_range");
  const auto r = test::run_railsim("run " + test::source_path("scenarios/single_wheelset.yaml") + " --out " + out +
                                   " --set duration=0.5 --set 'initial[ws1.lateral]=0.03'");
  INFO(r.output);
  CHECK(r.exit_code == 2);
  CHECK(r.output.find("key 'initial': these deviations put the start state outside the model's range") !=
        std::string::npos);
  CHECK(r.output.find("loss of contact") != std::string::npos);
  // 10 mm starts and runs.
  const auto ok = test::run_railsim("run " + test::source_path("scenarios/single_wheelset.yaml") + " --out " + out +
                                    " --set duration=0.5 --set 'initial[ws1.lateral]=0.01'");
  CHECK(ok.exit_code == 0);
}
