// The railsim program on the bad-input corpus (tests/data/bad_input/) and on
// bad command-line options: exit 2 and one message naming the file, line and
// key, or the option, and the allowed range; legal but implausible inputs run
// (exit 0) with a warning naming the value and the usual range. The library
// readers' messages are checked in detail in tests/engine/io/test_bad_input.cpp.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "processes.hpp"
#include "core/output_lock.hpp"
#include "test_support.hpp"

using namespace railsim;

namespace {

std::string bad(const std::string& name) { return "'" + test::data_path("bad_input/" + name) + "'"; }

struct CliCase {
  std::string what, args;
  std::vector<std::string> parts;  // expected in the output, in this order
};

// Every case is bounded in time: timeout(1) stops the program after this
// many seconds (exit 124, or 137 after the KILL), far above a refusal's cost
// even under ASan, so a case that starts working instead of refusing fails.
constexpr int kBoundSeconds = 120;

test::RunResult run_bounded(const std::string& args) {
  return test::run_shell("timeout -k 5 " + std::to_string(kBoundSeconds) + " \"" + RAILSIM_BINARY + "\" " + args +
                         " 2>&1");
}

void check_exit_2(const std::vector<CliCase>& cases) {
  for (const auto& c : cases) {
    const auto r = run_bounded(c.args);
    INFO(c.what << ": railsim " << c.args << "\n" << r.output);
    CHECK(r.exit_code != 124);  // not stopped by the time bound
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
      // A duration shorter than the output interval names the --set that made it so.
      {"--set duration=1e-300",
       "run '" + test::source_path("scenarios/single_wheelset.yaml") + "' --set duration=1e-300" + out,
       {"--set duration=1e-300: ", "key 'output_interval': 0.005 s is longer than the run (key 'duration': 1e-300 s)"}},
      {"initial shift 0.5 m", "run " + bad("scenario_initial_lateral_huge.yaml") + out,
       {"scenario_initial_lateral_huge.yaml:10: key 'initial.ws1.lateral'", "[-0.05, 0.05] m", "got 0.5"}},
      {"initial yaw 2 rad", "run " + bad("scenario_initial_yaw_huge.yaml") + out,
       {"scenario_initial_yaw_huge.yaml:10: key 'initial.ws1.yaw'", "[-0.1, 0.1] rad", "got 2"}},
      {"rtol 1e-15", "run " + bad("scenario_rtol_tiny.yaml") + out,
       {"scenario_rtol_tiny.yaml:10: key 'integrator.rtol'", "[1e-12, 0.1]", "got 1e-15"}},
      // The rest of issue 19's examples, each through the program.
      {"key twice in a flow map", "run " + bad("scenario_duplicate_nested_key.yaml") + out,
       {"scenario_duplicate_nested_key.yaml:9: key 'contact.creep_coefficients.f11': given twice"}},
      {"start -1e6", "run " + bad("scenario_start_distance_minus_1e6.yaml") + out,
       {"scenario_start_distance_minus_1e6.yaml:10: key 'start_distance'", "[0, 400]", "got -1000000"}},
      {"start 1e300", "run " + bad("scenario_start_distance_1e300.yaml") + out,
       {"scenario_start_distance_1e300.yaml:10: key 'start_distance'", "[0, 400]", "got 1e+300"}},
      {"output_interval 1e-9", "run " + bad("scenario_output_interval_tiny.yaml") + out,
       {"scenario_output_interval_tiny.yaml:6: key 'output_interval'", "1000000000 output samples",
        "more than the limit of 1000000"}},
      {"nu 0", "run " + bad("scenario_nu_zero.yaml") + out,
       {"scenario_nu_zero.yaml:10: key 'contact.material.nu'", "(0, 0.5]", "got 0"}},
      {"mu 0", "run " + bad("scenario_mu_zero.yaml") + out,
       {"scenario_mu_zero.yaml:10: key 'contact.material.mu'", "(0, 2]", "got 0"}},
      {"table row with a = 0", "run " + bad("scenario_table_zero_a.yaml") + out,
       {"table_zero_a.dat:5: column 4 (a [m])", "(0, 0.1]", "got 0"}},
      {"table row with a negative normal force", "run " + bad("scenario_table_negative_n0.yaml") + out,
       {"table_negative_n0.dat:5: column 2 (N0 [N])", "(0, 1e+07]", "got -60000"}},
      {"deep nesting", "run " + bad("deep_nesting.yaml") + out, {"deep_nesting.yaml:2: YAML nested too deeply"}},
      {"max_steps 2.5", "run " + bad("scenario_max_steps_fraction.yaml") + out,
       {"scenario_max_steps_fraction.yaml:10: key 'integrator.max_steps'", "whole number in [1, 1000000000]",
        "got 2.5"}},
  });
  // The vehicle and track files of a scenario, swapped in with --set: the error is in that file.
  const std::string sc = "run '" + test::source_path("scenarios/single_wheelset.yaml") + "'" + out;
  check_exit_2({
      {"two elements of one name", sc + " --set vehicle=" + bad("vehicle_duplicate_element.yaml"),
       {"vehicle_duplicate_element.yaml:8: key 'elements[1].name'", "duplicate element name 'primary_L'"}},
      {"a spring and a damper of one name", sc + " --set vehicle=" + bad("vehicle_duplicate_element_kinds.yaml"),
       {"vehicle_duplicate_element_kinds.yaml:8: key 'elements[1].name'", "duplicate element name"}},
      {"mass 1e300 kg", sc + " --set vehicle=" + bad("vehicle_mass_huge.yaml"),
       {"vehicle_mass_huge.yaml:4: key 'bodies[0].mass'", "[1, 1000000]", "got 1e+300"}},
      {"mass 1e-6 kg", sc + " --set vehicle=" + bad("vehicle_mass_tiny.yaml"),
       {"vehicle_mass_tiny.yaml:4: key 'bodies[0].mass'", "[1, 1000000]", "got 1e-06"}},
      {"inertias against the triangle inequality", sc + " --set vehicle=" + bad("vehicle_inertia_triangle.yaml"),
       {"vehicle_inertia_triangle.yaml:4: key 'bodies[0].inertia'", "triangle inequality"}},
      {"a vehicle key twice", sc + " --set vehicle=" + bad("vehicle_duplicate_key.yaml"),
       {"vehicle_duplicate_key.yaml:4: key 'bodies[0].mass': given twice (first on line 4)"}},
      {"a folder as the vehicle", sc + " --set vehicle=" + test::data_path("bad_input"),
       {"key 'vehicle': '", "bad_input' is a folder; expected a file"}},
      {"an unknown tangential model", sc + " --set contact.tangential=nosuch",
       {"--set contact.tangential=nosuch: ", "key 'contact.tangential': unknown contact model 'nosuch'",
        "known models:"}},
      {"a track key twice", sc + " --set track=" + bad("track_duplicate_key.yaml"),
       {"track_duplicate_key.yaml:5: key 'segments': given twice (first on line 3)"}},
      // A wheel profile in mm under a metres header, in a profile-geometry scenario.
      {"profile in mm declared as metres",
       "run '" + test::source_path("scenarios/manchester_coach_curve_R300.yaml") + "'" + out +
           " --set contact.geometry.wheel=" + bad("profile_mm_declared_m.csv"),
       {"profile_mm_declared_m.csv: lateral extent 140000 mm, more than the plausible 500 mm", "length unit m",
        "line 1"}},
  });
  // A legal setting the integrator cannot work with: exit 3 naming the setting, its value and what to change.
  const auto r = test::run_railsim("run " + bad("scenario_max_steps_one.yaml") + out);
  INFO(r.output);
  CHECK(r.exit_code == 3);
  CHECK(r.output.find("raise integrator.max_steps (now 1, default 100000)") != std::string::npos);
  CHECK(r.output.find("place: track distance 0.00-0.40 m") != std::string::npos);
}

TEST_CASE("railsim contact on bad case files: exit 2 naming file, line, key and range, mu > 1 a warning",
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
      {"a/b 1000 with mim", "contact " + bad("contact_aspect_1000.yaml") + " --model mim --out '" + dir + "/a.csv'",
       {"contact_aspect_1000.yaml:4: key 'cases[0].a'", "a/b = 1000 outside [0.01, 100]"}},
      {"Fz 1e300", "contact " + bad("contact_fz_huge.yaml") + out,
       {"contact_fz_huge.yaml:4: key 'cases[0].Fz': expected a number in [1, 10000000] (got 1e+300)"}},
      {"E 1 Pa", "contact " + bad("contact_e_one.yaml") + out,
       {"contact_e_one.yaml:2: key 'material.E': expected a number in [1000000000, 10000000000000] (got 1)"}},
      {"flat curvatures", "contact " + bad("contact_flat_curvatures.yaml") + out,
       {"contact_flat_curvatures.yaml:4: key 'cases[0].Fz'", "outside [1e-06, 1] m"}},
      {"--out the case file", "contact " + bad("contact_one_case.yaml") + " --model linear --out " +
                                   bad("contact_one_case.yaml"),
       {"--out: ", "contact_one_case.yaml is the input file", "itself"}},
      {"--out the case file (wheelset-contact)",
       "wheelset-contact " + test::data_path("contact_geometry/mbench_a22.yaml") + " --out " +
           test::data_path("contact_geometry/mbench_a22.yaml"),
       {"--out: ", "mbench_a22.yaml is the input file", "itself"}},
      // The allowed maximum grid of MIM on a 6 x 4 mm patch: about 29 GB, refused before allocating.
      {"mim --grid 4000", "contact " + bad("contact_one_case.yaml") + " --model mim --grid 4000 --no-timing --out '" +
                              dir + "/m.csv'",
       // (Richardson extrapolation solves at grid 4000 and 2000: the message names whichever is refused
       // first, 6006 x 4004 or 3006 x 2004.)
       {"mim: a grid of ", "elements needs about", "GB of memory, more than the limit of 4.29 GB", "--grid"}},
  });
  const auto r = test::run_railsim("contact " + bad("contact_mu_high_warning.yaml") + out);
  INFO(r.output);
  CHECK(r.exit_code == 0);
  CHECK(r.output.find("[warning] ") != std::string::npos);
  CHECK(r.output.find("contact_mu_high_warning.yaml:2: key 'material.mu': 1.5 is legal but implausible") !=
        std::string::npos);
  CHECK(r.output.find("usual range 0.05-0.6") != std::string::npos);
}

// --out naming one of the command's input files: refused before anything is
// written, the file left as it was (geometry, conicity and wheelset-contact
// overwrote a wheel profile or table given as the result file, track its track file or the
// measured-irregularity file the track file reads).
TEST_CASE("railsim --out naming an input file (profile, table, track): exit 2, the file untouched",
          "[cli][bad_input]") {
  const std::string dir = test::temp_dir("bad_input_out_is_input");
  auto copy = [&](const std::string& from, const std::string& name) {
    const std::string to = dir + "/" + name;
    std::ofstream(to) << test::read_text(from);
    return to;
  };
  const std::string wheel = copy(test::data_path("contact_geometry/s1002_netter.csv"), "wheel.csv");
  const std::string table = copy(test::source_path("vehicles/contact_tables/RSGEO_S1002_UIC60_1in40.dat"), "t.dat");
  const std::string track = copy(test::source_path("tracks/curve_R300.yaml"), "track.yaml");
  // A track file's measured-irregularity file is an input of railsim track too (found by a probe: --out
  // naming it overwrote the survey); the track file names it relative to its own folder.
  const std::string survey = copy(test::data_path("tracks/measured_good.csv"), "survey.csv");
  const std::string surveyed = dir + "/surveyed.yaml";
  std::ofstream(surveyed) << "rail_spacing: 1.5\nsegments:\n  - {type: straight, length: 20}\n"
                             "irregularities:\n  - {type: measured, file: survey.csv, units: mm}\n";
  const std::string cases = dir + "/cases.yaml";
  std::ofstream(cases) << "wheel: wheel.csv\nrail: UIC60\ninclination: 1/40\nspeed: 20\n"
                          "positions:\n  - {y: 0.003, Fz: 6e4}\n";
  struct Case {
    std::string args, file;
  };
  for (const Case& c : {Case{"geometry --no-cache --wheel '" + wheel + "' --out '" + wheel + "'", wheel},
                        Case{"conicity --no-cache --wheel '" + wheel + "' --out '" + wheel + "'", wheel},
                        Case{"conicity --table '" + table + "' --out '" + table + "'", table},
                        Case{"track '" + track + "' --out '" + track + "'", track},
                        Case{"track '" + surveyed + "' --out '" + survey + "'", survey},
                        Case{"wheelset-contact '" + cases + "' --out '" + wheel + "'", wheel}}) {
    const std::string before = test::read_text(c.file);
    const auto r = test::run_railsim(c.args);
    INFO(c.args << "\n" << r.output);
    CHECK(r.exit_code == 2);
    CHECK(r.output.find("--out: ") != std::string::npos);
    CHECK(r.output.find("is the input file") != std::string::npos);
    CHECK(test::read_text(c.file) == before);
  }
  // A shipped profile name is no file: an output of that name is fine.
  const auto r = test::run_railsim("geometry --no-cache --wheel S1002 --out '" + dir + "/S1002'");
  INFO(r.output);
  CHECK(r.exit_code == 0);
}

TEST_CASE("railsim on bad options: exit 2 naming the option and the range", "[cli][bad_input]") {
  const std::string sc = "'" + test::source_path("scenarios/single_wheelset.yaml") + "'";
  const std::string dir = test::temp_dir("bad_input_options");
  check_exit_2({
      {"unknown subcommand", "frobnicate " + sc, {"unknown subcommand 'frobnicate' (known: version, run,"}},
      {"unknown subcommand after a global option", "--log-level warn frobnicate",
       {"unknown subcommand 'frobnicate'"}},
      {"no subcommand", "--log-level warn", {"railsim: no subcommand given (one of: version, run,"}},
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
      // Model options the chosen model does not read (they were ignored silently).
      {"--grid with chopaya", "contact '" + test::data_path("bad_input/contact_one_case.yaml") +
                                  "' --model chopaya --grid 30 --out '" + dir + "/g.csv'",
       {"--grid: model 'chopaya' does not use it (models that do: fastsim, fastsim_kalker, fastsim_parabolic, "
        "fastrip, mim, mim_table)"}},
      {"--cache-dir with mim", "contact '" + test::data_path("bad_input/contact_one_case.yaml") +
                                   "' --model mim --cache-dir '" + dir + "' --out '" + dir + "/g.csv'",
       {"--cache-dir: model 'mim' does not use it (models that do: mim_table)"}},
      {"--tolerance with fastsim in wheelset-contact",
       "wheelset-contact '" + test::data_path("contact_geometry/mbench_a22.yaml") +
           "' --model fastsim --tolerance 1e-6 --out '" + dir + "/w.csv'",
       {"--tolerance: model 'fastsim' does not use it (models that do: mim, mim_table)"}},
      {"--extrapolation with fastrip in wheelset-contact",
       "wheelset-contact '" + test::data_path("contact_geometry/mbench_a22.yaml") +
           "' --model fastrip --extrapolation none --out '" + dir + "/w.csv'",
       {"--extrapolation: model 'fastrip' does not use it (models that do: mim)"}},
      {"--v-step 1e-9 modes", "modes " + sc + " --v-step 1e-9 --out '" + dir + "/m'",
       {"--v-step 1e-09: 20..400 km/h would take 380000000001 speeds, more than the limit of 2000"}},
      {"--v-min -10 modes", "modes " + sc + " --v-min -10 --out '" + dir + "/m'",
       {"--v-min/--v-max: need 0 < v-min < v-max <= 720 km/h (got -10, 400)"}},
      {"--threads 1000", "critical-speed " + sc + " --threads 1000 --out '" + dir + "/c'",
       {"--threads: Value 1000 not in range 0 to 256"}},
      // Options that do not apply to the analysis (they were ignored silently).
      {"--duration with ramping", "critical-speed " + sc + " --method ramping --duration 3 --out '" + dir + "/c'",
       {"--duration: applies to the bifurcation sweep, not to ramping"}},
      {"--deceleration with the sweep", "critical-speed " + sc + " --deceleration 1 --out '" + dir + "/c'",
       {"--deceleration: applies to ramping"}},
      {"--models without --compare-models", "critical-speed " + sc + " --models she --out '" + dir + "/c'",
       {"--models: applies with --compare-models"}},
      {"--no-baseline without --reduction", "critical-speed " + sc + " --no-baseline --out '" + dir + "/c'",
       {"--no-baseline: applies with --reduction"}},
      {"--disturbance below --small-disturbance",
       "critical-speed " + sc + " --disturbance 0.01 --small-disturbance 2 --out '" + dir + "/c'",
       {"the down branch's disturbance (0.01 mm) must exceed the up branch's (2 mm)"}},
      {"--models twice", "critical-speed " + sc + " --compare-models --models she,chopaya,she --out '" + dir + "/c'",
       {"--models: model 'she' listed twice"}},
      {"--reduction 5", "critical-speed " + sc + " --reduction 5 --out '" + dir + "/c'",
       {"--reduction: k11 expected a number in (0, 1.5] (got 5)"}},
      {"--contact-audit 1e8", "run " + sc + " --contact-audit 100000000 --out '" + dir + "/r'",
       {"--contact-audit: expected a number in [1, 10000] (got 100000000)"}},
      {"--from -1e300 on track", "track '" + test::source_path("tracks/curve_R300.yaml") + "' --from -1e300 -o '" +
                                     dir + "/t.csv'",
       {"--from: expected a distance in [0, 710] m", "got -1e+300"}},
      {"--to 1e300 on track", "track '" + test::source_path("tracks/curve_R300.yaml") + "' --to 1e300 -o '" + dir +
                                  "/t.csv'",
       {"--to: expected a distance in [0, 710] m", "got 1e+300"}},
      {"--step 1e-9 on track", "track '" + test::source_path("tracks/curve_R300.yaml") + "' --step 1e-9 -o '" + dir +
                                   "/t.csv'",
       {"--step 1e-09 gives 710000000001 rows (limit 2e7)"}},
      // The geometry commands name the option of a refused track set-up or grid.
      {"--gauge -1", "geometry --gauge -1 --no-cache --out '" + dir + "/g.csv'", {"--gauge: ", "[0.5, 2.5] m (got -1)"}},
      {"--radius 0", "conicity --radius 0 --no-cache", {"--radius: ", "[0.1, 1.5] m (got 0)"}},
      {"--flange-back 1.2", "geometry --flange-back 1.2 --no-cache --out '" + dir + "/g.csv'",
       {"--wheel S1002 / --rail UIC60 with --gauge, --flange-back", "puts both wheels on their rails"}},
      {"--flange-back 1.5", "conicity --flange-back 1.5 --no-cache", {"--flange-back/--gauge: ", "smaller than"}},
      {"--y-step 1e-12", "geometry --y-step 1e-12 --no-cache --out '" + dir + "/g.csv'",
       {"--y-step: ", "y step 1e-12 m: expected a value in [1e-6, y_max - y_min] m"}},
      {"--y-max 1", "conicity --y-max 1 --no-cache", {"--y-min/--y-max: ", "-0.05 <= y_min < y_max <= 0.05 m"}},
      {"a table with a = 0 on conicity", "conicity --table " + bad("table_zero_a.dat"),
       {"table_zero_a.dat:5: column 4 (a [m])", "(0, 0.1]"}},
      // conicity: a table too narrow for every amplitude, geometry options that a table does not take,
      // a shift step too coarse for the regression (12 mm gave 0 at every amplitude).
      {"a +-0.5 mm table on conicity", "conicity --table " + bad("table_narrow.dat"),
       {"table_narrow.dat: the table covers shifts up to +-0.5 mm: no amplitude of 1..6 mm fits"}},
      {"+-0.5 mm shifts on conicity", "conicity --no-cache --y-min -0.0005 --y-max 0.0005",
       {"--y-min/--y-max: the shifts -0.5 .. 0.5 mm fit no amplitude of 1..6 mm", "--y-min at most -1 mm",
        "--y-max at least 1 mm"}},
      {"compare-yq into a compared run's folder", "compare-yq " + sc + " '" + dir + "/run_a' --out '" + dir + "/run_a/'",
       {"--out " + dir + "/run_a/: is the run folder " + dir + "/run_a being compared"}},
      // compare-yq labels: one per folder, none empty, none twice (the rows could not be told apart).
      {"--labels a,a", "compare-yq " + sc + " '" + dir + "/x' '" + dir + "/y' --labels a,a --out '" + dir + "/yq_labels'",
       {"--labels: 'a' is given twice (labels 1 and 2)"}},
      {"--labels ,b", "compare-yq " + sc + " '" + dir + "/x' '" + dir + "/y' --labels ,b --out '" + dir + "/yq_labels'",
       {"--labels: label 1 is empty"}},
      {"--labels a,", "compare-yq " + sc + " '" + dir + "/x' '" + dir + "/y' --labels a, --out '" + dir + "/yq_labels'",
       {"--labels: label 2 is empty"}},
      {"--gauge with --table", "conicity --table " + bad("table_narrow.dat") + " --gauge 99",
       {"--gauge: does not apply with --table"}},
      {"--y-step 0.012 on conicity", "conicity --y-step 0.012 --no-cache",
       {"--y-step: equivalent conicity at amplitude 1 mm: the table's y step 12 mm is too coarse",
        "(at most a quarter of the amplitude, 0.25 mm)"}},
  });
}

// conicity over shifts narrower than +-6 mm: the amplitudes whose sweep fits are computed (the same values as
// over the full range) and the others named in a warning, as with a narrow --table. It refused every
// amplitude below +-3 mm (found by a probe), where conicity --table of that range gave 1 and 2 mm.
TEST_CASE("railsim conicity over narrow shifts: the amplitudes that fit, a warning naming the others",
          "[cli][bad_input]") {
  const auto full = test::run_railsim("conicity --no-cache");
  const auto narrow = test::run_railsim("conicity --no-cache --y-min -0.0025 --y-max 0.0025");
  INFO(full.output << "\n" << narrow.output);
  REQUIRE(full.exit_code == 0);
  CHECK(narrow.exit_code == 0);
  auto row = [](const std::string& out, int a) {
    const std::string key = "\n" + std::to_string(a) + ",";
    const std::size_t k = out.find(key);
    return k == std::string::npos ? std::string() : out.substr(k + 1, out.find('\n', k + 1) - k - 1);
  };
  for (int a : {1, 2}) {
    CHECK_FALSE(row(narrow.output, a).empty());
    CHECK(row(narrow.output, a) == row(full.output, a));
  }
  for (int a : {3, 6}) CHECK(row(narrow.output, a).empty());
  CHECK(narrow.output.find("[warning] --y-min/--y-max: amplitudes 3..6 mm lie beyond the shifts -2.5 .. 2.5 mm: "
                           "not computed") != std::string::npos);
}

TEST_CASE("a second railsim writing the same output folder exits 2 naming the folder", "[cli][bad_input]") {
  const std::string dir = test::temp_dir("bad_input_lock") + "/out";
  const std::string sc = "'" + test::source_path("scenarios/single_wheelset.yaml") + "'";
  {
    const OutputLock held(dir);  // this process writes there
    for (const std::string& cmd :
         {"modes " + sc + " --v-min 20 --v-max 30", "run " + sc + " --set duration=0.1", "critical-speed " + sc,
          std::string("demo"), "compare-contact '" + test::data_path("compare_contact_small.yaml") + "'",
          "compare-yq " + sc + " '" + dir + "_run'"})
      check_exit_2({{cmd, cmd + " --out '" + dir + "'",
                     {dir + ": another railsim process (pid " + std::to_string(::getpid()) + ") is writing"}}});
  }
  // Released with its holder: the folder is free again.
  const auto r = test::run_railsim("modes " + sc + " --v-min 20 --v-max 30 --out '" + dir + "'");
  INFO(r.output);
  CHECK(r.exit_code == 0);
}

TEST_CASE("railsim on 50 MB of junk: exit 2, the message quotes at most a line of it", "[cli][bad_input]") {
  // Random bytes, and random YAML punctuation and words (a syntax error a few lines in), 50 MB each
  // (below the 64 MiB input limit, so read and parsed, not refused from the size).
  const std::string dir = test::temp_dir("bad_input_junk");
  std::mt19937 rng(19);
  const std::string alphabet = "abc:{}[]- ,\n\"";
  for (const std::string kind : {"bytes", "yaml"}) {
    const std::string path = dir + "/junk_" + kind + ".yaml";
    {
      std::ofstream f(path, std::ios::binary);
      std::string chunk(1 << 20, ' ');
      for (int mb = 0; mb < 50; ++mb) {
        for (char& ch : chunk)
          ch = kind == "bytes" ? static_cast<char>(rng() & 0xffu) : alphabet[rng() % alphabet.size()];
        f.write(chunk.data(), static_cast<std::streamsize>(chunk.size()));
      }
    }
    const std::string q = "'" + path + "'";
    check_exit_2({
        {kind + " as a scenario", "run " + q + " --out '" + dir + "/r'", {path + ":", "YAML syntax error"}},
        {kind + " as a track", "track " + q + " -o '" + dir + "/t.csv'", {path + ":", "YAML syntax error"}},
        {kind + " as contact cases", "contact " + q + " --model linear --out '" + dir + "/c.csv'",
         {path + ":", "YAML syntax error"}},
    });
  }
}

TEST_CASE("two railsim processes on one output folder: the second exits 2 naming the first, whose result is whole",
          "[cli][bad_input]") {
  const std::string dir = test::temp_dir("bad_input_two");
  // Two critical-speed sweeps of different steps (the finer one used to fail with exit 3, "point ... has no
  // result", when the other deleted the shared partial file).
  const std::string sc = "critical-speed '" + test::data_path("scenarios/single_wheelset_flange.yaml") + "'";
  const std::string coarse = " --v-min 150 --v-max 180 --v-step 10 --duration 4 --threads 1 --no-continuation";
  const std::string fine = " --v-min 150 --v-max 190 --v-step 5 --duration 4 --threads 1 --no-continuation";
  const auto ref = test::run_railsim(sc + coarse + " --out '" + dir + "/ref'");
  REQUIRE(ref.exit_code == 0);
  const std::string shared = dir + "/shared";
  const auto first = test::start_railsim(sc + coarse + " --out '" + shared + "'", dir + "/first");
  REQUIRE(first.pid > 0);
  // The second starts while the first is sweeping (its finished points on disk).
  REQUIRE(test::wait_until([&] { return !test::read_text(shared + "/bifurcation.csv.part0").empty(); }, 60.0));
  const std::string holder = shared + ": another railsim process (pid " + std::to_string(first.pid) + ") is writing";
  check_exit_2({{"a finer sweep beside it", sc + fine + " --out '" + shared + "'", {holder}}});
  REQUIRE(first.wait(kBoundSeconds) == 0);
  INFO(first.output());
  CHECK(test::read_text(shared + "/bifurcation.csv") == test::read_text(dir + "/ref/bifurcation.csv"));
  // Afterwards the finer sweep has the folder: all of its 9 speeds, both branches.
  const auto after = test::run_railsim(sc + fine + " --out '" + shared + "'");
  INFO(after.output);
  CHECK(after.exit_code == 0);
  const std::string fine_csv = test::read_text(shared + "/bifurcation.csv");
  CHECK(std::count(fine_csv.begin(), fine_csv.end(), '\n') == 1 + 2 * 9);

  // Two runs: the second is refused while the first writes its channels (they used to collide on one
  // temporary file name), and the first's channels are those of a run alone.
  const std::string run = "run '" + test::source_path("scenarios/manchester_coach_curve_R300.yaml") + "'";
  const auto alone = test::run_railsim(run + " --out '" + dir + "/alone'");
  REQUIRE(alone.exit_code == 0);
  const std::string out = dir + "/run";
  const auto a = test::start_railsim(run + " --out '" + out + "'", dir + "/run_a");
  REQUIRE(a.pid > 0);
  REQUIRE(test::wait_until([&] { return !test::read_text(out + "/channels.csv").empty(); }, 60.0));
  check_exit_2({{"a second run", run + " --out '" + out + "'",
                 {out + ": another railsim process (pid " + std::to_string(a.pid) + ") is writing"}}});
  REQUIRE(a.wait(kBoundSeconds) == 0);
  CHECK(test::read_text(out + "/channels.csv") == test::read_text(dir + "/alone/channels.csv"));
}

TEST_CASE("the message that ends a run reaches stderr at every --log-level", "[cli][bad_input]") {
  // --log-level off and critical hid it: exit 2 (or 3) without a word.
  for (const char* level : {"off", "critical", "info"}) {
    const auto r = test::run_railsim(std::string("--log-level ") + level + " run /nonexistent/scenario.yaml");
    INFO(level << ": " << r.output);
    CHECK(r.exit_code == 2);
    CHECK(r.output.find("/nonexistent/scenario.yaml: YAML input not found") != std::string::npos);
  }
}
