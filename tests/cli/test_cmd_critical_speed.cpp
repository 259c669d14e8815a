// `railsim critical-speed` through the railsim binary: summary.json contents
// (consistent with the eigenvalue analysis and with the unreduced baseline),
// charts, resuming into the same folder, and every bad-input path (exit 2);
// the --reductions study on its files (table, summary, charts, a killed job
// restarting to byte-identical files, MPI == threads).
#include <catch2/catch.hpp>

#include <signal.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "results/csv_writer.hpp"
#include "json_support.hpp"
#include "test_support.hpp"

using railsim::test::run_railsim;

namespace {

using railsim::test::json_number;

// A number of a summary.json file (NaN when null or absent), parsed with nlohmann.
double summary_number(const std::string& path, const std::string& key) {
  return json_number(railsim::test::read_json(path), key);
}

const std::string kScenario = railsim::test::data_path("scenarios/single_wheelset_flange.yaml");
// Around the linear critical speed of the wheelset (45.59 m/s = 164.1 km/h).
const std::string kSweep = " --v-min 150 --v-max 180 --v-step 5 --duration 10 --threads 2";

}  // namespace

TEST_CASE("railsim critical-speed: summary, charts and the reduction baseline", "[cli][critical_speed]") {
  const std::string dir = railsim::test::temp_dir("cli_cs");
  const auto r = run_railsim("critical-speed '" + kScenario + "' --out '" + dir + "'" + kSweep + " --reduction 0.6");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const auto s = railsim::test::read_json(dir + "/summary.json");
  for (const char* key : {"critical_speed_kmh", "linear_critical_speed_kmh", "method", "contact_model", "reduction",
                          "unreduced", "settings"})
    CHECK(s.contains(key));
  CHECK(s["unreduced"].contains("critical_speed_change_percent"));
  CHECK(s["method"] == "bifurcation");
  CHECK(s["reduction"].get<std::string>().rfind("uniform 0.6", 0) == 0);
  CHECK(std::filesystem::exists(dir + "/bifurcation.png"));
  CHECK(std::filesystem::exists(dir + "/unreduced/bifurcation.png"));

  // Linear wheelset: the sweep finds the eigenvalue critical speed within one
  // 5 km/h step, with and without the reduction.
  const double v = json_number(s, "critical_speed_kmh"), v_lin = json_number(s, "linear_critical_speed_kmh");
  CHECK(std::abs(v - v_lin) <= 5.0);
  const auto& base = s["unreduced"];
  const double v0 = json_number(base, "critical_speed_kmh"), v0_lin = json_number(base, "linear_critical_speed_kmh");
  CHECK(std::abs(v0 - v0_lin) <= 5.0);
  CHECK(v0_lin == Approx(164.1).margin(0.3));  // physics-reference.md 8.1: 45.59 m/s
  CHECK(json_number(base, "critical_speed_change_percent") == Approx(100.0 * (v - v0) / v0).margin(1e-6));
  CHECK(v_lin != Approx(v0_lin).margin(0.3));  // the reduction reached the creep forces (+0.5 %)

  // Started again in the same folder: every point is skipped, nothing is added.
  const auto before = railsim::results::read_csv(dir + "/bifurcation.csv");
  const auto again = run_railsim("critical-speed '" + kScenario + "' --out '" + dir + "'" + kSweep + " --reduction 0.6");
  REQUIRE(again.exit_code == 0);
  const auto after = railsim::results::read_csv(dir + "/bifurcation.csv");
  CHECK(after.rows.size() == before.rows.size());
  CHECK(after.rows.size() == 14);  // 7 speeds x 2 branches
  std::set<std::string> keys;
  for (const auto& row : after.rows) keys.insert(row.front());
  CHECK(keys.size() == after.rows.size());
  CHECK(summary_number(dir + "/summary.json", "critical_speed_kmh") == v);
}

TEST_CASE("railsim critical-speed --method ramping writes the ramp record", "[cli][critical_speed]") {
  const std::string dir = railsim::test::temp_dir("cli_cs_ramp");
  const auto r = run_railsim("critical-speed '" + kScenario + "' --method ramping --v-min 140 --v-max 185 --deceleration 0.5 --out '" + dir + "'");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const auto s = railsim::test::read_json(dir + "/summary.json");
  const double v = json_number(s, "critical_speed_kmh"), v_lin = json_number(s, "linear_critical_speed_kmh");
  // Ramping at 0.5 m/s^2 trails the eigenvalue answer by the decay time of the
  // transients: within 3 % below it (measured 1.6 %).
  CHECK(v <= v_lin * 1.002);
  CHECK(v >= v_lin * 0.97);
  CHECK(std::filesystem::exists(dir + "/ramping.png"));
  CHECK(railsim::results::read_csv(dir + "/ramping.csv").rows.size() > 100);
}

TEST_CASE("railsim critical-speed rejects bad input with exit code 2", "[cli][critical_speed]") {
  const std::string dir = railsim::test::temp_dir("cli_cs_bad");
  auto run = [&](const std::string& args) {
    return run_railsim("critical-speed '" + kScenario + "' --out '" + dir + "/o' " + args);
  };
  auto r = run("--v-min 200 --v-max 100");
  CHECK(r.exit_code == 2);
  CHECK(r.output.find("--v-min/--v-max") != std::string::npos);
  r = run("--reduction 1.7");
  CHECK(r.exit_code == 2);
  CHECK(r.output.find("--reduction") != std::string::npos);
  r = run("--model no_such_model");
  CHECK(r.exit_code == 2);
  r = run("--method sideways");
  CHECK(r.exit_code == 2);
  r = run("--duration 0.01");
  CHECK(r.exit_code == 2);
  // Empty lists are not "not given"; a model the scenario's contact cannot feed is named before any work.
  for (const char* opt : {"--models", "--reductions", "--reduction", "--model"}) {
    r = run(std::string("--compare-models ") + opt + " ''");
    INFO(opt << "\n" << r.output);
    CHECK(r.exit_code == 2);
    CHECK(r.output.find(std::string(opt) + ": expected a value (got '')") != std::string::npos);
  }
  r = run_railsim("critical-speed '" + railsim::test::source_path("scenarios/single_wheelset.yaml") +
                  "' --model chopaya --out '" + dir + "/o'");
  CHECK(r.exit_code == 2);
  CHECK(r.output.find("--model chopaya: tangential model 'chopaya' needs a contact patch") != std::string::npos);
  r = run_railsim("critical-speed '" + railsim::test::source_path("scenarios/single_wheelset.yaml") +
                  "' --compare-models --models coefficients,fastsim --out '" + dir + "/o'");
  CHECK(r.exit_code == 2);
  CHECK(r.output.find("--models: tangential model 'fastsim' needs a contact patch") != std::string::npos);

  // A scenario whose critical_speed section has an unknown key and a bad range.
  std::string text = railsim::test::read_text(kScenario);
  text.replace(text.find("vehicle: ../../../"), 18, "vehicle: " + railsim::test::source_path(""));
  std::ofstream(dir + "/bad_key.yaml") << text << "critical_speed: {v_min_kmh: 100, v_maximum: 200}\n";
  r = run_railsim("critical-speed '" + dir + "/bad_key.yaml' --out '" + dir + "/o'");
  CHECK(r.exit_code == 2);
  CHECK(r.output.find("bad_key.yaml:") != std::string::npos);
  CHECK(r.output.find("v_maximum") != std::string::npos);
  std::ofstream(dir + "/bad_range.yaml") << text << "critical_speed: {v_min_kmh: 300, v_max_kmh: 200}\n";
  r = run_railsim("critical-speed '" + dir + "/bad_range.yaml' --out '" + dir + "/o'");
  CHECK(r.exit_code == 2);
  CHECK(r.output.find("v_min_kmh < v_max_kmh") != std::string::npos);
}

#ifdef RAILSIM_HAVE_MPI
TEST_CASE("railsim critical-speed under mpirun -np 2 gives the thread run's sweep", "[cli][critical_speed][mpi]") {
  const std::string dir = railsim::test::temp_dir("cli_cs_mpi");
  const std::string sweep = " --v-min 150 --v-max 180 --v-step 5 --duration 6";
  const auto thr = run_railsim("critical-speed '" + kScenario + "' --out '" + dir + "/threads'" + sweep);
  REQUIRE(thr.exit_code == 0);
  const std::string mpi = railsim::test::mpirun_prefix() + "mpirun --allow-run-as-root --oversubscribe -np 2 \"" + std::string(RAILSIM_BINARY) +
                          "\" critical-speed '" + kScenario + "' --threads 1 --out '" + dir + "/mpi'" + sweep +
                          " > '" + dir + "/mpi.log' 2>&1";
  REQUIRE(std::system(mpi.c_str()) == 0);
  // Same points, same values, same order; the part files of the ranks are merged away.
  CHECK(railsim::test::read_text(dir + "/mpi/bifurcation.csv") == railsim::test::read_text(dir + "/threads/bifurcation.csv"));
  CHECK_FALSE(std::filesystem::exists(dir + "/mpi/bifurcation.csv.part0"));
  CHECK(summary_number(dir + "/mpi/summary.json", "critical_speed_kmh") ==
        summary_number(dir + "/threads/summary.json", "critical_speed_kmh"));
}
#endif

namespace {

const std::string kStudySweep = " --v-min 150 --v-max 180 --v-step 10 --duration 6 --threads 2";

}  // namespace

TEST_CASE("railsim critical-speed --reductions: table, summary and charts for every entry", "[cli][critical_speed][reductions]") {
  const std::string dir = railsim::test::temp_dir("cli_cs_reductions");
  const auto r = run_railsim("critical-speed '" + kScenario + "' --out '" + dir + "'" + kStudySweep +
                             " --reductions '0.5,third_body,(0.72,0.56,0.56),elastic_fe'");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  // The console table names the reference that was added (no k = 1 in the list).
  CHECK(r.output.find("added as the k = 1 reference") != std::string::npos);
  const auto t = railsim::results::read_csv(dir + "/reductions.csv");
  REQUIRE(t.rows.size() == 5);
  // A preset name only where the preset was chosen: 0.5 stays a number, third_body is named.
  CHECK(t.rows[0][t.column("label")] == "uniform 0.5");
  CHECK(t.rows[1][t.column("label")] == "third_body");
  CHECK(t.rows[2][t.column("label")] == "0.72,0.56,0.56");
  CHECK(t.rows[3][t.column("label")] == "elastic_fe");
  CHECK(t.rows[4][t.column("label")] == "uniform 1");
  CHECK(t.number(4, "critical_speed_change_percent") == 0.0);
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    // The same factors give the same critical speeds, whatever their name.
    if (i == 1) CHECK(t.number(1, "critical_speed_kmh") == t.number(0, "critical_speed_kmh"));
    if (i == 3) CHECK(t.number(3, "linear_critical_speed_kmh") == t.number(2, "linear_critical_speed_kmh"));
    const double v = t.number(i, "critical_speed_kmh"), v0 = t.number(4, "critical_speed_kmh");
    CHECK(t.number(i, "critical_speed_change_percent") == Approx(100.0 * (v - v0) / v0).margin(1e-9));
    CHECK(t.number(i, "limit_cycle_amplitude_at_fold_mm") > 0.5);  // above the threshold at the fold
    CHECK(std::filesystem::exists(dir + "/" + t.rows[i][t.column("folder")] + "/bifurcation.png"));
  }
  const std::string s = railsim::test::read_text(dir + "/summary.json");
  for (const char* key : {"\"rule\"", "\"duration_per_point_s\": 6", "\"mu\": 0.3", "\"wheelset_model\": \"lateral\"",
                          "\"equivalent_conicity\"", "\"saturation_law\"", "\"geometry\": \"conical",
                          "\"limit_cycle_amplitude_at_fold_mm\"", "\"points_by_state\""})
    CHECK(s.find(key) != std::string::npos);
  CHECK(s.find("wall_time") == std::string::npos);
  CHECK(railsim::test::read_text(dir + "/timing.json").find("wall_time_s") != std::string::npos);
  // Charts: one curve per entry with its critical speed, the rule under the plot.
  const std::string chart = railsim::test::read_text(dir + "/reductions.png.json");
  CHECK(std::filesystem::exists(dir + "/reductions.png"));
  CHECK(chart.find("uniform 1") == std::string::npos);  // the legend says k = 1
  for (const char* label : {"\"k = 0.5: critical speed", "\"third_body (0.5,0.5,0.5): critical speed",
                            "\"k = 0.72,0.56,0.56: critical speed", "\"elastic_fe (0.72,0.56,0.56): critical speed",
                            "\"k = 1: critical speed", "still decaying at the end of the run",
                            "Critical speed: the lowest speed of the down branch"})
    CHECK(chart.find(label) != std::string::npos);
  const std::string vs_k = railsim::test::read_text(dir + "/critical_speed_vs_k.png.json");
  CHECK(std::filesystem::exists(dir + "/critical_speed_vs_k.png"));
  CHECK(vs_k.find("linear critical speed (eigenvalues), uniform k") != std::string::npos);
  CHECK(vs_k.find("elastic_fe (0.72,0.56,0.56)") != std::string::npos);

  // Bad input: exit 2, naming the option and the entry.
  auto bad = run_railsim("critical-speed '" + kScenario + "' --out '" + dir + "/b'" + kStudySweep + " --reductions '1,2'");
  CHECK(bad.exit_code == 2);
  CHECK(bad.output.find("--reductions entry 2") != std::string::npos);
  bad = run_railsim("critical-speed '" + kScenario + "' --out '" + dir + "/b'" + kStudySweep +
                    " --reductions 1 --reduction 0.5");
  CHECK(bad.exit_code == 2);
  // The conical test wheelset prescribes its creep coefficients: no patch for a layer.
  bad = run_railsim("critical-speed '" + kScenario + "' --out '" + dir + "/b'" + kStudySweep +
                    " --reduction layer:h=125e-6,G3=820e6");
  CHECK(bad.exit_code == 2);
  CHECK(bad.output.find("contact patch") != std::string::npos);
  // The same folder with other settings is refused (its points would not match).
  bad = run_railsim("critical-speed '" + kScenario + "' --out '" + dir + "' --v-min 150 --v-max 180 --v-step 10 "
                    "--duration 7 --threads 2 --reductions '0.5,third_body,(0.72,0.56,0.56),elastic_fe'");
  CHECK(bad.exit_code == 2);
  CHECK(bad.output.find("other settings") != std::string::npos);
}

TEST_CASE("railsim critical-speed --reductions: a killed job restarts to byte-identical files", "[cli][critical_speed][reductions]") {
  const std::string dir = railsim::test::temp_dir("cli_cs_kill");
  const std::string args = " --v-min 150 --v-max 180 --v-step 5 --duration 30 --threads 2 --continuation "
                           "--reductions '1,0.7,elastic_fe'";
  // Uninterrupted reference.
  const auto ref = run_railsim("critical-speed '" + kScenario + "' --out '" + dir + "/clean'" + args);
  INFO(ref.output);
  REQUIRE(ref.exit_code == 0);
  // The same job, killed (SIGKILL) once some points are on disk, then started again.
  const std::string start = std::string("\"") + RAILSIM_BINARY + "\" critical-speed '" + kScenario + "' --out '" + dir +
                            "/killed'" + args + " > '" + dir + "/killed.log' 2>&1 & echo $! > '" + dir + "/pid'";
  REQUIRE(std::system(start.c_str()) == 0);
  const pid_t pid = static_cast<pid_t>(std::stol(railsim::test::read_text(dir + "/pid")));
  bool some_points = false;
  for (int i = 0; i < 2000 && !some_points; ++i) {
    std::error_code ec;
    if (std::filesystem::exists(dir + "/killed", ec))
      for (const auto& e : std::filesystem::recursive_directory_iterator(dir + "/killed", ec))
        if (e.path().filename().string().find(".part0") != std::string::npos && e.file_size(ec) > 0) some_points = true;
    if (!some_points) usleep(20000);
  }
  REQUIRE(some_points);
  const bool finished_before_kill = std::filesystem::exists(dir + "/killed/reductions.csv");
  ::kill(pid, SIGKILL);
  for (int i = 0; i < 500; ++i) {  // until it is gone (or a zombie)
    const std::string stat = railsim::test::read_text("/proc/" + std::to_string(pid) + "/stat");
    if (stat.empty() || stat.find(") Z") != std::string::npos) break;
    usleep(10000);
  }
  REQUIRE_FALSE(finished_before_kill);
  const auto again = run_railsim("critical-speed '" + kScenario + "' --out '" + dir + "/killed'" + args);
  INFO(again.output);
  REQUIRE(again.exit_code == 0);
  CHECK(again.output.find("resuming") != std::string::npos);
  const auto t = railsim::results::read_csv(dir + "/clean/reductions.csv");
  std::vector<std::string> files = {"reductions.csv", "summary.json", "linear_critical_speeds.csv",
                                    "reductions.png.json", "critical_speed_vs_k.png.json"};
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    files.push_back(t.rows[i][t.column("folder")] + "/bifurcation.csv");
    files.push_back(t.rows[i][t.column("folder")] + "/bifurcation.png.json");
  }
  for (const auto& f : files) {
    INFO(f);
    const std::string a = railsim::test::read_text(dir + "/clean/" + f);
    CHECK_FALSE(a.empty());
    CHECK(railsim::test::read_text(dir + "/killed/" + f) == a);
  }
}

TEST_CASE("railsim critical-speed: summaries record the variant, ramping names its start speed and marks the reading",
          "[cli][critical_speed]") {
  const std::string dir = railsim::test::temp_dir("cli_cs_record");
  const auto r = run_railsim("critical-speed '" + kScenario + "' --method ramping --v-min 140 --v-max 185 "
                             "--deceleration 1 --reduction third_body --no-baseline --out '" + dir + "'");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK(r.output.find("ramping from 185.0 km/h (--v-max)") != std::string::npos);
  const std::string s = railsim::test::read_text(dir + "/summary.json");
  for (const char* key : {"\"mu\": 0.3", "\"wheelset_model\": \"lateral\"", "\"geometry\": \"conical",
                          "\"saturation_law\": \"none (linear creep forces", "\"reduction\": \"third_body\"",
                          "\"given\": \"third_body\"", "\"start_speed_kmh\": 185", "\"critical_speed_read_at_time_s\"",
                          "\"conicity\": 0.2"})
    CHECK(s.find(key) != std::string::npos);
  const std::string chart = railsim::test::read_text(dir + "/ramping.png.json");
  CHECK(chart.find("ramp from 185.0 km/h") != std::string::npos);
  CHECK(chart.find("critical speed read here") != std::string::npos);
  // A number stays a number.
  const auto n = run_railsim("critical-speed '" + kScenario + "' --method ramping --v-min 140 --v-max 185 "
                             "--deceleration 1 --reduction 0.5 --no-baseline --out '" + dir + "/n'");
  REQUIRE(n.exit_code == 0);
  const std::string sn = railsim::test::read_text(dir + "/n/summary.json");
  CHECK(sn.find("third_body") == std::string::npos);
  CHECK(sn.find("\"reduction\": \"uniform 0.5\"") != std::string::npos);
}

#ifdef RAILSIM_HAVE_MPI
TEST_CASE("railsim critical-speed --reductions under mpirun -np 2 gives the thread run's files", "[cli][critical_speed][mpi]") {
  const std::string dir = railsim::test::temp_dir("cli_cs_red_mpi");
  const std::string args = kStudySweep.substr(0, kStudySweep.find(" --threads")) + " --no-continuation --reductions '1,0.6'";
  const auto thr = run_railsim("critical-speed '" + kScenario + "' --out '" + dir + "/threads'" + args);
  REQUIRE(thr.exit_code == 0);
  const std::string mpi = railsim::test::mpirun_prefix() + "mpirun --allow-run-as-root --oversubscribe -np 2 \"" +
                          std::string(RAILSIM_BINARY) + "\" critical-speed '" + kScenario + "' --threads 1 --out '" + dir +
                          "/mpi'" + args + " > '" + dir + "/mpi.log' 2>&1";
  REQUIRE(std::system(mpi.c_str()) == 0);
  for (const char* f : {"reductions.csv", "summary.json", "linear_critical_speeds.csv"})
    CHECK(railsim::test::read_text(dir + "/mpi/" + f) == railsim::test::read_text(dir + "/threads/" + f));
}
#endif

TEST_CASE("railsim critical-speed: a sweep whose runs fail numerically or are too short exits non-zero, no verdict",
          "[cli][critical_speed][robustness]") {
  const std::string dir = railsim::test::temp_dir("cli_cs_no_verdict");
  // A forced blow-up: an integrator allowed three steps. Exit 3, no critical speed, the reason named.
  std::string text = railsim::test::read_text(kScenario);
  text.replace(text.find("vehicle: ../../../"), 18, "vehicle: " + railsim::test::source_path(""));
  const std::size_t at = text.find("integrator:");
  REQUIRE(at != std::string::npos);
  text = text.substr(0, at) + "integrator: {method: cvode_bdf, max_steps: 3}\n" +
         text.substr(text.find('\n', at) + 1);
  std::ofstream(dir + "/max_steps_3.yaml") << text;
  auto r = run_railsim("critical-speed '" + dir + "/max_steps_3.yaml' --v-min 160 --v-max 170 --v-step 5 "
                       "--duration 6 --threads 2 --no-up-branch --out '" + dir + "/failed'");
  INFO(r.output);
  CHECK(r.exit_code == 3);
  CHECK(r.output.find("no critical speed") != std::string::npos);
  CHECK(r.output.find("numerical failure") != std::string::npos);
  auto s = railsim::test::read_json(dir + "/failed/summary.json");
  CHECK(std::isnan(json_number(s, "critical_speed_kmh")));
  CHECK(s["points_by_state"]["failed"] == 3);
  CHECK(s["points_by_state"]["stopped"] == 0);
  // The same forced blow-up by ramping, alone and in a --reductions study: exit 3, the reason named.
  r = run_railsim("critical-speed '" + dir + "/max_steps_3.yaml' --method ramping --v-min 150 --v-max 170 --out '" +
                  dir + "/ramp_failed'");
  INFO(r.output);
  CHECK(r.exit_code == 3);
  CHECK(r.output.find("numerical failure while settling") != std::string::npos);
  r = run_railsim("critical-speed '" + dir + "/max_steps_3.yaml' --method ramping --v-min 150 --v-max 170 "
                  "--reductions 1,0.9 --threads 2 --out '" + dir + "/ramp_reductions_failed'");
  INFO(r.output);
  CHECK(r.exit_code == 3);
  CHECK(r.output.find("uniform 0.9: no critical speed: the ramp stopped on a numerical failure") != std::string::npos);
  CHECK(railsim::test::read_text(dir + "/ramp_reductions_failed/summary.json").find("\"stopped\"") !=
        std::string::npos);
  // Runs of 0.5 s: a tail of 0.15 s holds no cycle. Exit 2 (a setting to raise), naming --duration.
  r = run_railsim("critical-speed '" + kScenario + "' --v-min 160 --v-max 170 --v-step 5 --duration 0.5 --threads 2 "
                  "--no-up-branch --out '" + dir + "/short'");
  INFO(r.output);
  CHECK(r.exit_code == 2);
  CHECK(r.output.find("too short") != std::string::npos);
  CHECK(r.output.find("--duration") != std::string::npos);
  s = railsim::test::read_json(dir + "/short/summary.json");
  CHECK(std::isnan(json_number(s, "critical_speed_kmh")));
  CHECK(s["undetermined"].get<std::string>().find("too short") != std::string::npos);
  // A sweep whose lowest speed still hunts (the shipped single wheelset, linear critical speed 176.5 km/h,
  // swept from 190 km/h): the fold is below the range. It reported 190 km/h, exit 0. Now exit 2, no
  // critical speed, the bound and --v-min named.
  r = run_railsim("critical-speed '" + railsim::test::source_path("scenarios/single_wheelset.yaml") +
                  "' --v-min 190 --v-max 200 --v-step 10 --duration 3 --threads 2 --out '" + dir + "/above'");
  INFO(r.output);
  CHECK(r.exit_code == 2);
  CHECK(r.output.find("still hunts at the lowest speed of the sweep, 190.0 km/h: the critical speed lies at or "
                      "below it") != std::string::npos);
  s = railsim::test::read_json(dir + "/above/summary.json");
  CHECK(std::isnan(json_number(s, "critical_speed_kmh")));
  CHECK(s["undetermined"].get<std::string>().find("--v-min") != std::string::npos);
}

TEST_CASE("railsim critical-speed: runs that lift a wheel after their motion grew count as hunting",
          "[cli][critical_speed][robustness]") {
  // The shipped single wheelset (lateral model, conical wheels, no flange) with the default sweep, 80-300 km/h:
  // above its linear critical speed (176.5 km/h) the hunting grows until a wheel unloads, which the lateral model
  // cannot follow (it stops the run). That is the instability, not a numerical failure: such points count as
  // hunting and the critical speed is the first sweep speed above the linear one.
  const std::string dir = railsim::test::temp_dir("cli_cs_wheel_lift");
  const auto r = run_railsim("critical-speed '" + railsim::test::source_path("scenarios/single_wheelset.yaml") +
                             "' --threads 2 --out '" + dir + "'");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const auto s = railsim::test::read_json(dir + "/summary.json");
  const double v = json_number(s, "critical_speed_kmh"), v_lin = json_number(s, "linear_critical_speed_kmh");
  CHECK(v >= v_lin);
  CHECK(v <= v_lin + 10.0);  // the sweep's step
  CHECK(s["points_by_state"]["failed"] == 0);
  CHECK(s["points_by_state"]["stopped"].get<int>() > 0);
  CHECK(r.output.find("run stopped after its lateral motion grew") != std::string::npos);
}

TEST_CASE("railsim critical-speed --method ramping: a ramp whose grown motion leaves the model's range is a result",
          "[cli][critical_speed][robustness]") {
  // The shipped single wheelset from 300 km/h (default --v-max): settling there, the hunting grows from the
  // 5 mm disturbance until a wheel unloads at t = 0.18 s, which the lateral model cannot follow. As in the sweep
  // above, that is the instability (a result, exit 0: no critical speed by ramping from there), not a numerical
  // failure (it was exit 3 "numerical failure while settling").
  const std::string dir = railsim::test::temp_dir("cli_cs_ramp_range");
  const auto r = run_railsim("critical-speed '" + railsim::test::source_path("scenarios/single_wheelset.yaml") +
                             "' --method ramping --out '" + dir + "'");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK(r.output.find("critical speed     none (left the model's range, see below)") != std::string::npos);
  CHECK(r.output.find("the lateral motion grew by") != std::string::npos);
  CHECK(r.output.find("while settling at the start speed 300.0 km/h") != std::string::npos);
  const auto s = railsim::test::read_json(dir + "/summary.json");
  CHECK(s["critical_speed_kmh"].is_null());
  CHECK(s["hunting_at_start"] == true);
  CHECK(std::string(s["left_model_range"]).find("loss of contact") != std::string::npos);
  CHECK_FALSE(s.contains("derailment"));
  // (A ramp stopped by the integrator stays a numerical failure, exit 3: the forced blow-up test above.)
  // The same stop in a --reductions study is named as such (it said "the vehicle derailed during the ramp").
  const auto rr = run_railsim("critical-speed '" + railsim::test::source_path("scenarios/single_wheelset.yaml") +
                              "' --method ramping --v-min 160 --v-max 200 --reductions 1,0.5 --threads 2 --out '" +
                              dir + "/reductions'");
  INFO(rr.output);
  REQUIRE(rr.exit_code == 0);
  const auto st = railsim::test::read_json(dir + "/reductions/summary.json");
  REQUIRE(st["entries"].size() == 2);
  for (const auto& e : st["entries"]) {
    const std::string stopped = e["stopped"];
    CHECK(stopped.find("left the model's range") != std::string::npos);
    CHECK(stopped.find("derailed") == std::string::npos);
  }
}

TEST_CASE("railsim critical-speed: a folder swept with other settings is refused, not resumed",
          "[cli][critical_speed][robustness]") {
  // Before: a rerun with --duration 6 in the folder of a 0.5 s sweep said "resuming, 3 of 3 points already
  // finished" and reported the 0.5 s points as the 6 s sweep's; an edited scenario (creep coefficients
  // doubled) was resumed over as well. The folder's settings file (bifurcation.csv.settings) holds the
  // sweep's options, the integrator's settings and a hash of the model's equations.
  const std::string dir = railsim::test::temp_dir("cli_cs_resume_settings");
  const std::string src = railsim::test::source_path("scenarios/single_wheelset.yaml");
  const std::string sweep = " --v-min 100 --v-max 200 --v-step 50 --no-up-branch --out '" + dir + "/out'";
  auto r = run_railsim("critical-speed '" + src + "' --duration 0.5" + sweep);
  INFO(r.output);
  REQUIRE(r.exit_code == 2);  // too short for a verdict, as it should be
  REQUIRE(std::filesystem::exists(dir + "/out/bifurcation.csv.settings"));
  r = run_railsim("critical-speed '" + src + "' --duration 6" + sweep);
  INFO(r.output);
  CHECK(r.exit_code == 2);
  CHECK(r.output.find("other settings") != std::string::npos);
  CHECK(r.output.find("'duration_s 0.5', now 'duration_s 6'") != std::string::npos);
  CHECK(r.output.find("resuming") == std::string::npos);
  // The same settings resume (every point already there).
  r = run_railsim("critical-speed '" + src + "' --duration 0.5" + sweep);
  CHECK(r.output.find("resuming, 3 of 3 points already finished") != std::string::npos);
  // The scenario edited (creep coefficients doubled): the model's equations differ.
  std::string text = railsim::test::read_text(src);
  const auto veh = text.find("../vehicles/");
  REQUIRE(veh != std::string::npos);
  text.replace(veh, 12, railsim::test::source_path("vehicles/"));
  const auto f = text.find("{f11: 1.0e7, f22: 1.0e7}");
  REQUIRE(f != std::string::npos);
  text.replace(f, 24, "{f11: 2.0e7, f22: 2.0e7}");
  std::ofstream(dir + "/single_wheelset.yaml") << text;
  r = run_railsim("critical-speed '" + dir + "/single_wheelset.yaml' --duration 0.5" + sweep);
  INFO(r.output);
  CHECK(r.exit_code == 2);
  CHECK(r.output.find("other settings") != std::string::npos);
  CHECK(r.output.find("equations") != std::string::npos);
  // Points without a settings file (an earlier version's folder) cannot be checked: refused.
  std::filesystem::remove(dir + "/out/bifurcation.csv.settings");
  r = run_railsim("critical-speed '" + src + "' --duration 0.5" + sweep);
  CHECK(r.exit_code == 2);
  CHECK(r.output.find("without their settings file") != std::string::npos);
}

// A run's folder holds its verdict (summary.json): critical-speed (and modes)
// refuse to write there instead of replacing it; the run itself may run again.
TEST_CASE("railsim critical-speed and modes refuse a run's output folder", "[cli][critical_speed][bad_input]") {
  const std::string dir = railsim::test::temp_dir("cli_cs_run_folder");
  const std::string sc = railsim::test::source_path("scenarios/single_wheelset.yaml");
  const auto r = run_railsim("run '" + sc + "' --set duration=0.05 --out '" + dir + "/run'");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const std::string summary = railsim::test::read_text(dir + "/run/summary.json");
  for (const std::string& cmd : {"critical-speed '" + sc + "' --v-min 150 --v-max 160 --v-step 10 --duration 0.5",
                                "modes '" + sc + "' --v-min 100 --v-max 120 --v-step 10"}) {
    const auto c = run_railsim(cmd + " --out '" + dir + "/run'");
    INFO(c.output);
    CHECK(c.exit_code == 2);
    CHECK(c.output.find("holds the results of `railsim run`") != std::string::npos);
  }
  CHECK(railsim::test::read_text(dir + "/run/summary.json") == summary);
  const auto again = run_railsim("run '" + sc + "' --set duration=0.05 --out '" + dir + "/run'");
  CHECK(again.exit_code == 0);
}
