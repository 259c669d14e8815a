// railsim run killed (SIGKILL) while it writes its channels, then started
// again on the same folder: the restarted run's files are byte-identical to
// those of a run never interrupted (channels.csv, both charts and their
// sidecars; summary.json apart from its wall-clock and CPU-time figures). The
// killed process's output lock does not outlive it.
#include <catch2/catch.hpp>

#include <signal.h>

#include <sstream>
#include <string>

#include "processes.hpp"
#include "test_support.hpp"

using namespace railsim;

namespace {

// summary.json without the lines of measured times (wall_time, cpu_time, real_time_factor*, evaluation_*,
// charts_wall_time): the rest is the result.
std::string without_timings(const std::string& json) {
  std::istringstream in(json);
  std::string out, line;
  while (std::getline(in, line))
    if (line.find("_time\"") == std::string::npos && line.find("real_time_factor") == std::string::npos &&
        line.find("share_of_run") == std::string::npos)
      out += line + "\n";
  return out;
}

}  // namespace

TEST_CASE("railsim run killed while writing, then restarted, gives byte-identical files", "[cli][run][restart]") {
  const std::string dir = test::temp_dir("cli_run_kill");
  const std::string run = "run '" + test::source_path("scenarios/manchester_coach_curve_R300.yaml") + "'";
  const auto clean = test::run_railsim(run + " --out '" + dir + "/clean'");
  INFO(clean.output);
  REQUIRE(clean.exit_code == 0);

  const std::string out = dir + "/killed";
  const auto first = test::start_railsim(run + " --out '" + out + "'", dir + "/first");
  REQUIRE(first.pid > 0);
  // Killed once rows are on disk and before the summary (mid-simulation).
  REQUIRE(test::wait_until([&] { return !test::read_text(out + "/channels.csv").empty(); }, 120.0));
  const bool finished_before_kill = !test::read_text(out + "/summary.json").empty();
  ::kill(first.pid, SIGKILL);
  CHECK(first.wait(60.0) == 128 + SIGKILL);
  REQUIRE_FALSE(finished_before_kill);
  CHECK(test::read_text(out + "/channels.csv") != test::read_text(dir + "/clean/channels.csv"));  // cut short

  const auto again = test::run_railsim(run + " --out '" + out + "'");
  INFO(again.output);
  REQUIRE(again.exit_code == 0);
  for (const std::string f : {"channels.csv", "yq.png", "yq.png.json", "sum_y_rms.png", "sum_y_rms.png.json"}) {
    INFO(f);
    const std::string a = test::read_text(dir + "/clean/" + f);
    CHECK_FALSE(a.empty());
    CHECK(test::read_text(out + "/" + f) == a);
  }
  const std::string summary = test::read_text(dir + "/clean/summary.json");
  REQUIRE(summary.find("\"wall_time\"") != std::string::npos);  // the filter has something to drop
  CHECK(without_timings(test::read_text(out + "/summary.json")) == without_timings(summary));
}
