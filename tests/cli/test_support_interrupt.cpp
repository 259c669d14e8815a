// SIGTERM / SIGINT (cli/support_interrupt.hpp) stop `railsim run` and
// `railsim critical-speed` between output points: exit 143 / 130, a message
// saying where it stopped, channels.csv with whole rows up to that time and
// summary.json "interrupted" (no running-safety verdict, refused by
// compare-yq); a sweep keeps its finished points and the same command resumes
// them to the same result. (The tests send SIGTERM: a background job of the
// test's shell starts with SIGINT ignored, which the program then keeps, as
// a background job should; both signals take the same path.)
#include <catch2/catch.hpp>

#include <signal.h>

#include <algorithm>
#include <fstream>
#include <string>

#include "json_support.hpp"
#include "processes.hpp"
#include "test_support.hpp"

using namespace railsim;

namespace {

// `railsim <args>` in the background, sent SIGTERM once `started` has content;
// its exit status and output, and whether `finished` (written at its end)
// already existed then (the stop came too late to test anything).
struct Stopped {
  int code = -1;
  std::string output;
  bool finished_before = false;
};
Stopped sigterm_once(const std::string& args, const std::string& tag, const std::string& started,
                     const std::string& finished) {
  Stopped s;
  const auto job = test::start_railsim(args, tag);
  REQUIRE(job.pid > 0);
  REQUIRE(test::wait_until([&] { return !test::read_text(started).empty(); }, 120.0));
  s.finished_before = !test::read_text(finished).empty();
  ::kill(job.pid, SIGTERM);
  s.code = job.wait(60.0);
  s.output = job.output();
  return s;
}

}  // namespace

TEST_CASE("railsim run stopped by SIGTERM keeps its rows and says so in summary.json", "[cli][run][interrupt]") {
  const std::string dir = test::temp_dir("cli_run_sigterm");
  const std::string scenario = test::source_path("scenarios/manchester_coach_curve_R300.yaml");
  const std::string out = dir + "/run";
  // 240 s simulated (the scenario's 24.5 s take about a second): the stop comes from the signal.
  const Stopped job = sigterm_once("run '" + scenario + "' --set duration=240 --out '" + out + "'", dir + "/job",
                                   out + "/channels.csv", out + "/summary.json");
  INFO(job.output);
  REQUIRE_FALSE(job.finished_before);
  CHECK(job.code == 128 + SIGTERM);
  CHECK(job.output.find("interrupted at t = ") != std::string::npos);
  CHECK(job.output.find("stopped by a signal") != std::string::npos);
  const auto js = test::read_json(out + "/summary.json");
  CHECK(js["status"] == "interrupted");
  CHECK(js["running_safety"].is_string());
  // channels.csv: whole rows, the last at the time the message names.
  const test::CsvRows rows = test::csv_rows(out + "/channels.csv");
  CHECK(rows.torn == 0);
  CHECK(rows.rows > 1);
  const std::string said = js["interrupted"].get<std::string>();
  const auto at = said.find("t = ");
  REQUIRE(at != std::string::npos);
  const double t_said = std::stod(said.substr(at + 4));
  CHECK(rows.last_first_cell() == Approx(t_said).margin(1e-5));
  CHECK(t_said < 240.0);
  // compare-yq refuses the interrupted run (it has no verdict).
  const auto yq = test::run_railsim("compare-yq '" + scenario + "' '" + out + "' --out '" + dir + "/yq'");
  INFO(yq.output);
  CHECK(yq.exit_code == 2);
  CHECK(yq.output.find("status 'interrupted'") != std::string::npos);
}

TEST_CASE("railsim critical-speed stopped by SIGTERM keeps its points and resumes them", "[cli][critical_speed][interrupt]") {
  const std::string dir = test::temp_dir("cli_cs_sigterm");
  const std::string cmd = "critical-speed '" + test::data_path("scenarios/single_wheelset_flange.yaml") +
                          "' --v-min 150 --v-max 180 --v-step 10 --duration 200 --threads 1 --out '";  // ~4 s
  const auto clean = test::run_railsim(cmd + dir + "/clean'");
  INFO(clean.output);
  REQUIRE(clean.exit_code == 0);
  const std::string out = dir + "/stopped";
  const Stopped job =
      sigterm_once(cmd + out + "'", dir + "/job", out + "/bifurcation.csv.part0", out + "/bifurcation.csv");
  INFO(job.output);
  REQUIRE_FALSE(job.finished_before);
  CHECK(job.code == 128 + SIGTERM);
  CHECK(job.output.find("points of this run are kept in") != std::string::npos);
  CHECK(job.output.find("the same command in the same folder resumes") != std::string::npos);
  const auto again = test::run_railsim(cmd + out + "'");
  INFO(again.output);
  REQUIRE(again.exit_code == 0);
  CHECK(again.output.find("resuming") != std::string::npos);
  CHECK(test::read_text(out + "/bifurcation.csv") == test::read_text(dir + "/clean/bifurcation.csv"));
}
