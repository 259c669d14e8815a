// Y/Q comparison of runs (engine/analysis/yq_comparison.cpp) on synthetic
// channel files: the leading wheelset and its distance, peaks, the length and
// duration above Nadal's limit (crossings interpolated), and bad input.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "core/errors.hpp"
#include "engine/analysis/safety_limits.hpp"
#include "engine/analysis/yq_comparison.hpp"
#include "test_support.hpp"

using namespace railsim::engine;

namespace {

// channels.csv with time, distance (vehicle reference at 10 m/s from 0) and
// the ws1 columns the comparison reads: |Y/Q| of the right wheel a triangle of
// height `peak` centred at t = 5 s, half width 1 s; left wheel -0.2.
void write_run(const std::string& dir, double peak) {
  std::filesystem::create_directories(dir);
  std::ofstream f(dir + "/channels.csv");
  f << "time,distance,speed,ws1.L.YQ,ws1.R.YQ\n";
  for (int i = 0; i <= 1000; ++i) {
    const double t = 0.01 * i;
    const double tri = std::max(0.0, 1.0 - std::fabs(t - 5.0)) * peak;
    f << t << "," << 10.0 * t << ",10," << -0.2 << "," << tri << "\n";
  }
  std::ofstream(dir + "/summary.json") << R"({"status": "ok"})";  // a finished run
}

}  // namespace

TEST_CASE("Y/Q comparison: peaks, places and how long Nadal's limit is exceeded", "[yq_comparison]") {
  const Scenario sc = load_scenario(railsim::test::data_path("scenarios/single_wheelset_flange.yaml"));
  const std::string dir = railsim::test::temp_dir("yq_cmp");
  write_run(dir + "/a", 2.0);
  write_run(dir + "/b", 1.0);
  const YqComparison c = compare_yq(sc, {dir + "/a", dir + "/b"}, {"k = 1", "k = 0.5"});
  // The single wheelset: its own offset (0); conical wheels fall back to a 70 deg flange angle.
  CHECK(c.wheelset == "ws1");
  CHECK(c.nadal == Approx(nadal_limit(70.0 * M_PI / 180.0, 0.3)).epsilon(1e-12));
  REQUIRE(c.runs.size() == 2);
  const auto& a = c.runs[0].wheel[1];
  CHECK(a.peak == Approx(2.0));
  CHECK(a.peak_distance == Approx(50.0 + c.offset));
  CHECK(a.peak_time == Approx(5.0));
  // Above the limit L where 2 (1 - |t - 5|) > L: for |t - 5| < 1 - L/2, i.e. 2 - L seconds at 10 m/s.
  REQUIRE(a.exceeded);
  CHECK(a.exceed_time == Approx(2.0 - c.nadal).epsilon(1e-9));
  CHECK(a.exceed_length == Approx(10.0 * (2.0 - c.nadal)).epsilon(1e-9));
  CHECK(a.first_exceed == Approx(10.0 * (4.0 + c.nadal / 2.0)).epsilon(1e-9));
  CHECK(a.last_exceed == Approx(10.0 * (6.0 - c.nadal / 2.0)).epsilon(1e-9));
  const auto& b = c.runs[1].wheel[1];
  CHECK(b.peak == Approx(1.0));
  CHECK_FALSE(b.exceeded);
  CHECK(b.exceed_length == 0.0);
  CHECK(c.runs[1].wheel[0].peak == Approx(0.2));
  CHECK(c.runs[1].wheel[0].peak_signed == Approx(-0.2));
  // Chart and summary carry the limit and each run.
  const auto chart = yq_comparison_chart(c);
  REQUIRE(chart.lines.size() == 2);
  CHECK(chart.lines[0].value == Approx(c.nadal));
  CHECK(chart.series[2].label.find("k = 1, right wheel: peak 2 at") == 0);
  CHECK(chart.series[2].label.find("above the limit over") != std::string::npos);
  const std::string s = yq_comparison_summary(c).dump();
  CHECK(s.find("\"exceeds_nadal\": true") != std::string::npos);
  CHECK(s.find("\"label\": \"k = 0.5\"") != std::string::npos);
  // Default labels: the folder names. Bad input names the file or option.
  CHECK(compare_yq(sc, {dir + "/b"}, {}).runs[0].label == "b");
  // Folders of the same name (k1/out, k05/out) were both labelled "out":
  // rows, legend and summary could not be told apart. Their parents tell them apart.
  write_run(dir + "/k1/out", 2.0);
  write_run(dir + "/k05/out", 1.0);
  write_run(dir + "/deep/k1/out", 1.5);
  const YqComparison same = compare_yq(sc, {dir + "/k1/out", dir + "/k05/out/", dir + "/a"}, {});
  CHECK(same.runs[0].label == "k1/out");
  CHECK(same.runs[1].label == "k05/out");
  CHECK(same.runs[2].label == "a");  // a name nobody else has stays short
  const YqComparison deep = compare_yq(sc, {dir + "/k1/out", dir + "/deep/k1/out", dir + "/k05/out"}, {});
  CHECK(deep.runs[0].label == std::filesystem::path(dir).filename().string() + "/k1/out");
  CHECK(deep.runs[1].label == "deep/k1/out");
  CHECK(deep.runs[2].label == "k05/out");
  const auto legend = yq_comparison_chart(same);
  CHECK(legend.series[0].label.find("k1/out, left wheel") == 0);
  // The same folder twice is not a comparison.
  CHECK_THROWS_WITH(compare_yq(sc, {dir + "/a", dir + "/./a/"}, {}),
                    Catch::Contains("run folders 1 and 2") && Catch::Contains("are the same folder"));
  CHECK_THROWS_WITH(compare_yq(sc, {dir + "/missing"}, {}), Catch::Contains("missing/channels.csv"));
  CHECK_THROWS_WITH(compare_yq(sc, {dir + "/a"}, {"x", "y"}), Catch::Contains("--labels"));
  CHECK_THROWS_WITH(compare_yq(sc, {dir + "/a"}, {}, "ws9"), Catch::Contains("--wheelset") && Catch::Contains("ws1"));
  std::filesystem::create_directories(dir + "/c");
  std::ofstream(dir + "/c/channels.csv") << "time,distance,ws2.L.YQ\n0,0,0\n";
  std::ofstream(dir + "/c/summary.json") << R"({"status": "ok"})";
  CHECK_THROWS_WITH(compare_yq(sc, {dir + "/c"}, {}), Catch::Contains("c/channels.csv"));
}

TEST_CASE("Y/Q comparison refuses non-finite channels and failed runs, and warns on another scenario's run",
          "[yq_comparison][robustness]") {
  const Scenario sc = load_scenario(railsim::test::data_path("scenarios/single_wheelset_flange.yaml"));
  const std::string dir = railsim::test::temp_dir("yq_cmp_status");
  // A NaN in a Y/Q column (line 4 of the file: header, then rows 0, 1, 2): an error naming line and column,
  // not a peak or an exceedance of Nadal's limit.
  std::filesystem::create_directories(dir + "/nan");
  std::ofstream(dir + "/nan/summary.json") << R"({"status": "ok"})";
  std::ofstream(dir + "/nan/channels.csv") << "time,distance,ws1.L.YQ,ws1.R.YQ\n0,0,0,0.1\n0.01,0.1,0,0.2\n"
                                              "0.02,0.2,0,nan\n0.03,0.3,0,0.1\n";
  CHECK_THROWS_WITH(compare_yq(sc, {dir + "/nan"}, {}),
                    Catch::Contains("nan/channels.csv: line 4, column 'ws1.R.YQ'") &&
                        Catch::Contains("not a finite number"));
  std::filesystem::create_directories(dir + "/inf");
  std::ofstream(dir + "/inf/summary.json") << R"({"status": "ok"})";
  std::ofstream(dir + "/inf/channels.csv") << "time,distance,ws1.L.YQ,ws1.R.YQ\n0,0,0,0.1\n0.01,inf,0,0.2\n";
  CHECK_THROWS_WITH(compare_yq(sc, {dir + "/inf"}, {}), Catch::Contains("line 3, column 'distance'"));
  // A run that failed numerically: no verdict on its Y/Q.
  write_run(dir + "/failed", 2.0);
  std::ofstream(dir + "/failed/summary.json")
      << R"({"scenario": "single_wheelset_flange", "status": "failed", "error": "integrator: step collapse at t = 4.2 s"})";
  CHECK_THROWS_WITH(compare_yq(sc, {dir + "/failed"}, {}),
                    Catch::Contains("failed/summary.json: status 'failed'") && Catch::Contains("step collapse"));
  // A derailed run is physics: compared, its status kept.
  write_run(dir + "/derailed", 2.0);
  std::ofstream(dir + "/derailed/summary.json") << R"({"scenario": ")" << sc.name << R"(", "status": "derailed"})";
  const YqComparison d = compare_yq(sc, {dir + "/derailed"}, {});
  CHECK(d.runs[0].status == "derailed");
  CHECK(d.runs[0].warning.empty());
  CHECK(d.runs[0].wheel[1].exceeded);
  // A run of another scenario: compared, with a warning in the summary.
  write_run(dir + "/other", 1.0);
  std::ofstream(dir + "/other/summary.json") << R"({"scenario": "manchester_coach", "status": "ok"})";
  const YqComparison o = compare_yq(sc, {dir + "/other"}, {});
  CHECK(o.runs[0].warning.find("scenario 'manchester_coach'") != std::string::npos);
  CHECK(yq_comparison_summary(o).dump().find("\"warning\"") != std::string::npos);
  // A run without summary.json did not finish (killed): no verdict.
  write_run(dir + "/killed", 2.0);
  std::filesystem::remove(dir + "/killed/summary.json");
  CHECK_THROWS_WITH(compare_yq(sc, {dir + "/killed"}, {}),
                    Catch::Contains("killed/summary.json: not found") && Catch::Contains("did not finish"));
  // A summary.json that is not JSON: named.
  write_run(dir + "/junk", 1.0);
  std::ofstream(dir + "/junk/summary.json") << "{not json";
  CHECK_THROWS_WITH(compare_yq(sc, {dir + "/junk"}, {}), Catch::Contains("junk/summary.json: not a JSON object"));
  // A truncated channels.csv of a run that ended normally (10 s, 0.01 s output): refused, not a pass with
  // a peak of 0 (4 rows of a finished run gave "Nadal not exceeded").
  write_run(dir + "/cut", 2.0);
  std::ofstream(dir + "/cut/summary.json") << R"({"status": "ok", "duration": 10, "output_interval": 0.01})";
  CHECK_NOTHROW(compare_yq(sc, {dir + "/cut"}, {}));  // whole: up to t = 10 s
  std::ofstream(dir + "/cut/channels.csv") << "time,distance,speed,ws1.L.YQ,ws1.R.YQ\n0,0,10,0,0\n0.01,0.1,10,0,0\n"
                                              "0.02,0.2,10,0,0\n";
  CHECK_THROWS_WITH(compare_yq(sc, {dir + "/cut"}, {}),
                    Catch::Contains("cut/channels.csv: ends at t = 0.02 s, but its run lasted 10 s") &&
                        Catch::Contains("truncated"));
  // Samples out of time order: named by line.
  std::ofstream(dir + "/cut/channels.csv") << "time,distance,speed,ws1.L.YQ,ws1.R.YQ\n0,0,10,0,0\n0.02,0.2,10,0,0\n"
                                              "0.01,0.1,10,0,0\n";
  CHECK_THROWS_WITH(compare_yq(sc, {dir + "/cut"}, {}),
                    Catch::Contains("cut/channels.csv: line 4: time 0.01 s does not follow 0.02 s"));
}
