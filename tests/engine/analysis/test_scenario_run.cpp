// run_scenario (engine/analysis/scenario_run.hpp): the warnings of a legal but
// implausible scenario (issue 19 item 6) reach summary.json, with the file,
// key, value and the usual range, and the run itself goes on.
#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>
#include <string>

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
  run_scenario(rigid, o);
  CHECK(test::read_json(o.out_dir + "/summary.json")["model_choices"]["track_flexibility"] == "rigid rails");
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
