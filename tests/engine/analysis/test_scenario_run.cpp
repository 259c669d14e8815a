// run_scenario (engine/analysis/scenario_run.hpp): the warnings of a legal but
// implausible scenario (issue 19 item 6) reach summary.json, with the file,
// key, value and the usual range, and the run itself goes on.
#include <catch2/catch.hpp>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>

#include "core/errors.hpp"
#include "core/stop_request.hpp"
#include "engine/analysis/scenario_run.hpp"
#include "engine/io/scenario.hpp"
#include "json_support.hpp"
#include "test_support.hpp"

using namespace railsim;
using namespace railsim::engine;

TEST_CASE("run_scenario: the scenario reader's warnings are in summary.json", "[analysis][bad_input]") {
  Scenario sc = load_scenario(test::source_path("tests/data/bad_input/scenario_mu_high_warning.yaml"));
  REQUIRE(sc.warnings.size() == 1);
  sc.duration = 0.1;
  const std::string out = test::temp_dir("scenario_run_warnings");
  ScenarioRunOptions o;
  o.out_dir = out;
  const ScenarioRunResult r = run_scenario(sc, o);
  CHECK(r.run.outputs > 0);
  const auto js = test::read_json(out + "/summary.json");
  REQUIRE(js.contains("warnings"));
  bool found = false;
  for (const auto& w : js["warnings"]) {
    const std::string s = w.get<std::string>();
    if (s.find("scenario_mu_high_warning.yaml:10: key 'contact.material.mu': 1.5") != std::string::npos &&
        s.find("usual range 0.05-0.6") != std::string::npos)
      found = true;
  }
  CHECK(found);
  // A plausible scenario writes none from the reader.
  Scenario ok = load_scenario(test::source_path("scenarios/single_wheelset.yaml"));
  ok.duration = 0.1;
  const std::string out2 = test::temp_dir("scenario_run_no_warnings");
  o.out_dir = out2;
  run_scenario(ok, o);
  const auto js2 = test::read_json(out2 + "/summary.json");
  for (const auto& w : js2["warnings"]) CHECK(w.get<std::string>().find("implausible") == std::string::npos);
}

// summary.json records the track under the wheels: rigid rails, or the
// flexible track's values as the run's wheelset model uses them.
TEST_CASE("run_scenario: summary.json records rigid rails or the flexible track", "[analysis][track]") {
  ScenarioRunOptions o;
  Scenario rigid = load_scenario(test::source_path("scenarios/single_wheelset.yaml"));
  rigid.duration = 0.05;
  o.out_dir = test::temp_dir("scenario_run_rigid_track");
  rigid.integrator.method = "cvode_bdf";
  rigid.integrator.jacobian_max_age = 51;
  run_scenario(rigid, o);
  CHECK(test::read_json(o.out_dir + "/summary.json")["model_choices"]["track_flexibility"] == "rigid rails");
  // The integrator settings that change results are recorded too.
  CHECK(test::read_json(o.out_dir + "/summary.json")["model_choices"]["jacobian_max_age"] == 51);
  CHECK(test::read_json(o.out_dir + "/summary.json")["model_choices"]["atol_contact_modes"] == 0.0);
  Scenario flex = load_scenario(test::source_path("scenarios/manchester_coach_curve_twist.yaml"));
  flex.duration = 0.05;
  o.out_dir = test::temp_dir("scenario_run_flexible_track_lateral");
  run_scenario(flex, o);  // the lateral model: the vertical track does not act
  CHECK(test::read_json(o.out_dir + "/summary.json")["model_choices"]["track_flexibility"] == "rigid rails");
  std::string text;
  {
    std::ifstream in(test::source_path("scenarios/manchester_coach_curve_twist.yaml"));
    std::stringstream ss;
    ss << in.rdbuf();
    text = ss.str();
  }
  text.replace(text.find("wheelset_model: lateral"), 23, "wheelset_model: full");
  const Scenario full = load_scenario(config::InputNode::load_string(text, test::source_path("scenarios/curve_twist_full.yaml")),
                                      test::source_path("scenarios"));
  Scenario f = full;
  f.duration = 0.05;
  o.out_dir = test::temp_dir("scenario_run_flexible_track_full");
  run_scenario(f, o);
  const auto js = test::read_json(o.out_dir + "/summary.json");
  const auto& v = js["model_choices"]["track_flexibility"]["vertical"];
  CHECK(v["mass_kg"] == 180.0);
  CHECK(v["stiffness_N_per_m"] == 7.15e7);
  CHECK(v["rail_bending_stiffness_Nm2"] == 6.38e6);
  CHECK_FALSE(js["model_choices"]["track_flexibility"].contains("lateral"));
}

// Issue 14's robustness point: the coach on its profiles through curve_twist
// at 40, 60 and 80 km/h runs to the end with both wheelset models (the full
// one on the scenario's flexible track) and the verdict is physics, the same
// in both models: no flange climb (Nadal on every wheel; |Y/Q| stays near 0.5
// against Nadal's 1.3), the same pass/fail and the same failing quantities,
// and the largest wheel unloading dQ/Q0 of the run within 3 % between the two
// models; at 40 and 60 km/h the run passes (a coach does not derail here).
TEST_CASE("run_scenario: curve_twist at 40, 60, 80 km/h runs to the end with both wheelset models",
          "[analysis][safety][robustness]") {
  std::string base;
  {
    std::ifstream in(test::source_path("scenarios/manchester_coach_curve_twist.yaml"));
    std::stringstream ss;
    ss << in.rdbuf();
    base = ss.str();
  }
  for (int v : {40, 60, 80}) {
    bool pass[2] = {false, false};
    std::vector<std::string> failing[2];
    double unloading[2] = {0.0, 0.0};
    for (int k = 0; k < 2; ++k) {
      const std::string model = k == 0 ? "lateral" : "full";
      std::string t = base;
      t.replace(t.find("wheelset_model: lateral"), 23, "wheelset_model: " + model);
      t.replace(t.find("speed_kmh: 60"), 13, "speed_kmh: " + std::to_string(v));
      const Scenario sc = load_scenario(config::InputNode::load_string(t, test::source_path("scenarios/curve_twist.yaml")),
                                        test::source_path("scenarios"));
      INFO(model << " model, " << v << " km/h");
      ScenarioRunResult r;
      REQUIRE_NOTHROW(r = run_scenario(sc, ScenarioRunOptions{}));
      CHECK_FALSE(r.derailed);
      CHECK(r.run.outputs == std::lround(sc.duration / sc.output_interval) + 1);  // to the end
      const auto js = nlohmann::json::parse(r.summary.dump());
      CHECK(js["status"] == "ok");
      const auto& rs = js["running_safety"];
      for (const auto& ws : rs["wheelsets"])
        for (const char* side : {"left", "right"}) CHECK(ws["wheels"][side]["nadal"]["pass"] == true);
      pass[k] = rs["pass"].get<bool>();
      for (const auto& q : rs["quantities"]) {
        if (q["pass"] == false) failing[k].push_back(q["quantity"].get<std::string>());
        if (q["quantity"] == "wheel_unloading") unloading[k] = q["worst"]["value"].get<double>();
      }
    }
    INFO(v << " km/h: dQ/Q0 lateral / full " << unloading[0] << " / " << unloading[1]);
    CHECK(pass[0] == pass[1]);
    CHECK(failing[0] == failing[1]);
    CHECK(unloading[0] > 0.0);
    CHECK(unloading[1] == Approx(unloading[0]).epsilon(0.03));
    if (v < 80) CHECK(pass[0]);
  }
}

// A stop request (Ctrl-C in the program, KeyboardInterrupt in Python) ends the
// run between output points: InterruptedError naming the time reached,
// channels.csv with every row up to it (whole rows, the time column up to
// that time), summary.json "interrupted" with no running-safety verdict. The
// request is polled after each output point, so the run stops right after
// the output at which it was asked for.
TEST_CASE("run_scenario: a stop request ends the run, keeping what it ran", "[analysis][interrupt]") {
  Scenario sc = load_scenario(test::source_path("scenarios/single_wheelset.yaml"));
  sc.duration = 1.0;
  sc.output_interval = 0.01;
  const std::string out = test::temp_dir("scenario_run_interrupted");
  ScenarioRunOptions o;
  o.out_dir = out;
  o.keep_channels = true;
  int polls = 0;
  o.stop = StopRequest([&] { return ++polls >= 25; });  // asked for at the 25th output after t = 0
  std::string msg;
  try {
    run_scenario(sc, o);
  } catch (const InterruptedError& e) {
    msg = e.what();
  }
  INFO(msg);
  CHECK(msg.find("interrupted at t = 0.25 s of 1 s") != std::string::npos);
  const auto js = test::read_json(out + "/summary.json");
  CHECK(js["status"] == "interrupted");
  CHECK(js["interrupted"].get<std::string>().find("t = 0.25 s") != std::string::npos);
  CHECK(js["running_safety"].is_string());  // not evaluated: no verdict
  // channels.csv: the header and the rows t = 0, 0.01, ..., 0.25, all whole.
  const test::CsvRows rows = test::csv_rows(out + "/channels.csv");
  CHECK(rows.torn == 0);
  CHECK(rows.rows == 26);
  CHECK(rows.last_first_cell() == Approx(0.25));

  // Never asked for: the run ends normally (the default request never stops).
  ScenarioRunOptions plain;
  sc.duration = 0.05;
  CHECK_NOTHROW(run_scenario(sc, plain));
}
