// The railsim program on the bad-input corpus (tests/data/bad_input/) and on
// bad command-line options: exit 2 and one message naming the file, line and
// key, or the option, and the allowed range; legal but implausible inputs run
// (exit 0) with a warning naming the value and the usual range. The library
// readers' messages are checked in detail in tests/engine/io/test_bad_input.cpp.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <string>
#include <vector>

#include "core/output_lock.hpp"
#include "test_support.hpp"

using namespace railsim;

namespace {

std::string bad(const std::string& name) { return "'" + test::data_path("bad_input/" + name) + "'"; }

struct CliCase {
  std::string what, args;
  std::vector<std::string> parts;  // expected in the output, in this order
};

void check_exit_2(const std::vector<CliCase>& cases) {
  for (const auto& c : cases) {
    const auto r = test::run_railsim(c.args);
    INFO(c.what << ": railsim " << c.args << "\n" << r.output);
    CHECK(r.exit_code == 2);
    std::size_t at = 0;
    for (const auto& p : c.parts) {
      const std::size_t k = r.output.find(p, at);
      CHECK(k != std::string::npos);
      if (k != std::string::npos) at = k + p.size();
    }
    CHECK(r.output.size() < 2000);  // a message, not an echo of the input
  }
}

}  // namespace

TEST_CASE("railsim on bad scenario files: exit 2 naming file, line, key and range", "[cli][bad_input]") {
  const std::string out = " --out '" + test::temp_dir("bad_input_run") + "'";
  check_exit_2({
      {"max_step 0", "run " + bad("scenario_max_step_zero.yaml") + out,
       {"scenario_max_step_zero.yaml:10: key 'integrator.max_step'", "(0, 1] s", "omit max_step"}},
      {"min_step 10", "run " + bad("scenario_min_step_above_duration.yaml") + out,
       {"scenario_min_step_above_duration.yaml:10: key 'integrator.min_step'", "[0, 0.002) s", "got 10"}},
      {"key twice", "run " + bad("scenario_duplicate_key.yaml") + out,
       {"scenario_duplicate_key.yaml:10: key 'speed': given twice (first on line 4)"}},
      {"start off the track", "run " + bad("scenario_start_distance_1e6.yaml") + out,
       {"scenario_start_distance_1e6.yaml:10: key 'start_distance'", "[0, 400]"}},
      {"acceleration 1e6", "run " + bad("scenario_acceleration_huge.yaml") + out,
       {"scenario_acceleration_huge.yaml:10: key 'acceleration'", "[-10, 10]"}},
      {"duration 1e9", "run " + bad("scenario_duration_huge.yaml") + out,
       {"scenario_duration_huge.yaml", "output samples, more than the limit of 1000000"}},
      {"spring to itself", "run " + bad("scenario_vehicle_self_spring.yaml") + out,
       {"vehicle_self_spring.yaml:6: key 'elements[0].other'", "to itself"}},
      {"negative C11", "run " + bad("scenario_table_negative_c11.yaml") + out,
       {"table_negative_c11.dat:5: column 8 (C11 [-])", "(0, 100]", "got -5"}},
      {"a device", "run /dev/zero" + out, {"/dev/zero: YAML input: not a regular file"}},
      {"a folder", "run '" + test::data_path("bad_input") + "'" + out, {"bad_input: YAML input: is a folder"}},
      {"a long junk line", "run " + bad("junk_long_line.yaml") + out, {"junk_long_line.yaml:1: expected a mapping"}},
      {"--speed-kmh nan", "run '" + test::source_path("scenarios/single_wheelset.yaml") + "' --speed-kmh nan" + out,
       {"--speed-kmh: expected a finite number (got 'nan')"}},
      {"initial shift 0.5 m", "run " + bad("scenario_initial_lateral_huge.yaml") + out,
       {"scenario_initial_lateral_huge.yaml:10: key 'initial.ws1.lateral'", "[-0.05, 0.05] m", "got 0.5"}},
      {"initial yaw 2 rad", "run " + bad("scenario_initial_yaw_huge.yaml") + out,
       {"scenario_initial_yaw_huge.yaml:10: key 'initial.ws1.yaw'", "[-0.1, 0.1] rad", "got 2"}},
      {"rtol 1e-15", "run " + bad("scenario_rtol_tiny.yaml") + out,
       {"scenario_rtol_tiny.yaml:10: key 'integrator.rtol'", "[1e-12, 0.1]", "got 1e-15"}},
  });
  // A legal setting the integrator cannot work with: exit 3 naming the setting, its value and what to change.
  const auto r = test::run_railsim("run " + bad("scenario_max_steps_one.yaml") + out);
  INFO(r.output);
  CHECK(r.exit_code == 3);
  CHECK(r.output.find("raise integrator.max_steps (now 1, default 100000)") != std::string::npos);
  CHECK(r.output.find("place: track distance 0.00-0.40 m") != std::string::npos);
}

TEST_CASE("railsim contact on bad case files: exit 2 naming file, line, key and range; mu > 1 a warning",
          "[cli][bad_input]") {
  const std::string dir = test::temp_dir("bad_input_contact");
  const std::string out = " --model linear --out '" + dir + "/r.csv'";
  check_exit_2({
      {"mu 10", "contact " + bad("contact_mu_10.yaml") + out,
       {"contact_mu_10.yaml:2: key 'material.mu': expected a number in (0, 2] (got 10)"}},
      {"mu 0", "contact " + bad("contact_mu_zero.yaml") + out,
       {"contact_mu_zero.yaml:2: key 'material.mu': expected a number in (0, 2] (got 0)"}},
      {"key twice", "contact " + bad("contact_duplicate_key.yaml") + out,
       {"contact_duplicate_key.yaml:4: key 'cases[0].id': given twice (first on line 4)"}},
      // The allowed maximum grid of MIM on a 6 x 4 mm patch: about 29 GB, refused before allocating.
      {"mim --grid 4000", "contact " + bad("contact_one_case.yaml") + " --model mim --grid 4000 --no-timing --out '" +
                              dir + "/m.csv'",
       {"mim: a grid of 6006 x 4004 elements needs about", "GB of memory, more than the limit of 4.29 GB",
        "--grid"}},
  });
  const auto r = test::run_railsim("contact " + bad("contact_mu_high_warning.yaml") + out);
  INFO(r.output);
  CHECK(r.exit_code == 0);
  CHECK(r.output.find("[warning] ") != std::string::npos);
  CHECK(r.output.find("contact_mu_high_warning.yaml:2: key 'material.mu': 1.5 is legal but implausible") !=
        std::string::npos);
  CHECK(r.output.find("usual range 0.05-0.6") != std::string::npos);
}

TEST_CASE("railsim on bad options: exit 2 naming the option and the range", "[cli][bad_input]") {
  const std::string sc = "'" + test::source_path("scenarios/single_wheelset.yaml") + "'";
  const std::string dir = test::temp_dir("bad_input_options");
  check_exit_2({
      {"unknown subcommand", "frobnicate " + sc, {"unknown subcommand 'frobnicate' (known: version, run,"}},
      {"unknown subcommand after a global option", "--log-level warn frobnicate",
       {"unknown subcommand 'frobnicate'"}},
      {"--speed-kmh nan on track", "track '" + test::source_path("tracks/curve_R300.yaml") + "' --out '" + dir +
                                       "/t.csv' --speed-kmh nan",
       {"--speed-kmh: expected a finite number (got 'nan')"}},
      {"--speed-kmh 1e4 on track", "track '" + test::source_path("tracks/curve_R300.yaml") + "' --out '" + dir +
                                       "/t.csv' --speed-kmh 1e4",
       {"--speed-kmh: expected a speed in (0, 720] km/h (got 10000)"}},
      {"--v-min nan", "critical-speed " + sc + " --v-min nan --out '" + dir + "/c'",
       {"--v-min: expected a finite number (got 'nan')"}},
      {"--v-max inf", "critical-speed " + sc + " --v-max inf --out '" + dir + "/c'",
       {"--v-max: expected a finite number (got 'inf')"}},
      {"--v-max 1e300", "critical-speed " + sc + " --v-max 1e300 --out '" + dir + "/c'",
       {"--v-min/--v-max: need 0 < v-min < v-max <= 720 km/h"}},
      {"--v-step 1e-9 critical-speed", "critical-speed " + sc + " --v-step 1e-9 --out '" + dir + "/c'",
       {"--v-step 1e-09: 80..300 km/h would take 220000000001 speeds, more than the limit of 2000"}},
      {"--v-step 1e-12 modes", "modes " + sc + " --v-step 1e-12 --out '" + dir + "/m'",
       {"--v-step 1e-12: 20..400 km/h would take", "speeds, more than the limit of 2000", "use a step of at least"}},
      {"--duration nan", "critical-speed " + sc + " --duration nan --out '" + dir + "/c'", {"--duration: "}},
      {"--out ''", "modes " + sc + " --out ''", {"--out: expected a file or folder name (got '')"}},
      {"negative --grid", "contact '" + test::data_path("bad_input/contact_one_case.yaml") +
                              "' --model mim --grid -5 --out '" + dir + "/g.csv'",
       {"--grid: Value -5 not in range 0 to 4000"}},
      {"-o ''", "track '" + test::source_path("tracks/curve_R300.yaml") + "' -o ''", {"expected a file or folder name"}},
  });
}

TEST_CASE("a second railsim writing the same output folder exits 2 naming the folder", "[cli][bad_input]") {
  const std::string dir = test::temp_dir("bad_input_lock") + "/out";
  const std::string sc = "'" + test::source_path("scenarios/single_wheelset.yaml") + "'";
  {
    const OutputLock held(dir);  // this process writes there
    for (const std::string& cmd : {"modes " + sc + " --v-min 20 --v-max 30", "run " + sc + " --set duration=0.1",
                                  "critical-speed " + sc})
      check_exit_2({{cmd, cmd + " --out '" + dir + "'",
                     {dir + ": another railsim process (pid " + std::to_string(::getpid()) + ") is writing"}}});
  }
  // Released with its holder: the folder is free again.
  const auto r = test::run_railsim("modes " + sc + " --v-min 20 --v-max 30 --out '" + dir + "'");
  INFO(r.output);
  CHECK(r.exit_code == 0);
}
