// `railsim run`: channels.csv and summary.json are written; bad input exits 2,
// numerical failure exits 3 with the diagnostic (and a summary saying so).
#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>

#include "results/csv_writer.hpp"
#include "test_support.hpp"

using namespace railsim;

namespace {
std::string slurp(const std::string& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}
}  // namespace

TEST_CASE("railsim run writes channels and summary", "[engine][cli]") {
  const std::string out = test::temp_dir("run_single");
  const auto r = test::run_railsim("run " + test::source_path("scenarios/single_wheelset.yaml") + " --out " + out);
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const auto csv = results::read_csv(out + "/channels.csv");
  CHECK(csv.rows.size() == 801);  // 4 s every 5 ms, plus t = 0
  // The 10 mm defect displaces the wheelset by several mm; max shift in the summary matches the channel.
  double maxy = 0;
  for (std::size_t i = 0; i < csv.rows.size(); ++i) maxy = std::max(maxy, std::abs(csv.number(i, "ws1.y")));
  CHECK(maxy > 0.005);
  const std::string js = slurp(out + "/summary.json");
  CHECK(js.find("\"status\": \"ok\"") != std::string::npos);
  CHECK(js.find("\"rhs_calls\"") != std::string::npos);
  CHECK(js.find("\"real_time_factor\"") != std::string::npos);
  CHECK(js.find("\"max_lateral_shift\"") != std::string::npos);
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
  CHECK(slurp(out + "/summary.json").find("\"status\": \"failed\"") != std::string::npos);
}
