// The railsim program on outputs that cannot be written: every kind of file it
// writes (CSV, JSON summaries, PNG charts, a sweep's finished points, the
// critical-speed state store, standard output) on a full disk gives exit 2
// and an error naming the file, never exit 0 with the output lost.
//
// A full disk is /dev/full (every write fails with ENOSPC): given as the
// output file, or linked from an output folder under the name the program
// writes; and a file-size limit (ulimit -f: writes beyond it fail with
// EFBIG) for a whole run.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "processes.hpp"
#include "test_support.hpp"

using namespace railsim;
namespace fs = std::filesystem;

namespace {

struct WriteCase {
  std::string what, args, file;  // the file the message must name
};

// Exit 2 and "FILE: write failed" in the output; the device is still a device.
void check_failed_write(const WriteCase& c, const test::RunResult& r) {
  INFO(c.what << ": railsim " << c.args << "\n" << r.output);
  CHECK(r.exit_code == 2);
  CHECK(r.output.find(c.file + ": write failed") != std::string::npos);
  CHECK(r.output.size() < 4000);
  CHECK(fs::is_character_file("/dev/full"));
}

// An output folder whose file `name` is a link to /dev/full.
std::string folder_with_full(const std::string& tag, const std::string& name) {
  const std::string dir = test::temp_dir("full_" + tag);
  fs::create_symlink("/dev/full", dir + "/" + name);
  return dir;
}

std::string q(const std::string& s) { return "'" + s + "'"; }

const std::string kBinary = std::string("'") + RAILSIM_BINARY + "'";

const std::string kWheelset = test::source_path("scenarios/single_wheelset.yaml");
const std::string kFlange = test::data_path("scenarios/single_wheelset_flange.yaml");

}  // namespace

TEST_CASE("railsim writing a file to a full disk: exit 2 naming the file", "[cli][bad_input][write]") {
  if (!fs::is_character_file("/dev/full")) return;
  const std::vector<WriteCase> cases = {
      {"contact CSV", "contact " + q(test::source_path("scenarios/contact_cases.yaml")) + " --model fastsim --out /dev/full",
       "/dev/full"},
      {"track CSV (rows buffered)", "track " + q(test::source_path("tracks/curve_R300.yaml")) + " --out /dev/full",
       "/dev/full"},
      {"wheelset-contact CSV",
       "wheelset-contact " + q(test::data_path("contact_geometry/mbench_a22.yaml")) + " --model chopaya --out /dev/full",
       "/dev/full"},
  };
  for (const auto& c : cases) check_failed_write(c, test::run_railsim(c.args));
  // Printed results: standard output on a full disk.
  const auto r = test::run_shell(kBinary + " conicity --wheel S1002 --rail UIC60 --inclination 1/40 2>&1 >/dev/full");
  INFO(r.output);
  CHECK(r.exit_code == 2);
  CHECK(r.output.find("standard output: write failed (No space left on device)") != std::string::npos);
}

TEST_CASE("railsim run: channels, summary and charts on a full disk: exit 2 naming the file",
          "[cli][bad_input][write]") {
  if (!fs::is_character_file("/dev/full")) return;
  for (const std::string name : {"channels.csv", "summary.json", "yq.png", "yq.png.json"}) {
    const std::string dir = folder_with_full("run", name);
    const WriteCase c{"run, " + name, "run " + q(kWheelset) + " --out " + q(dir), dir + "/" + name};
    check_failed_write(c, test::run_railsim(c.args));
  }
}

TEST_CASE("railsim critical-speed and modes: points, states and tables on a full disk: exit 2 naming the file",
          "[cli][bad_input][write]") {
  if (!fs::is_character_file("/dev/full")) return;
  const std::string sweep = " --v-min 150 --v-max 160 --v-step 10 --duration 2 --threads 1";
  const std::vector<std::pair<std::string, std::string>> files = {
      {"bifurcation.csv.part0", " --no-continuation"},            // finished points of the sweep
      {"bifurcation.csv.down.states", " --continuation"},         // the state store of the down branch
      {"bifurcation.csv", " --no-continuation"},                  // the merged points
      {"summary.json", " --no-continuation"},
  };
  for (const auto& [name, mode] : files) {
    const std::string dir = folder_with_full("cs", name);
    const WriteCase c{"critical-speed, " + name, "critical-speed " + q(kFlange) + " --out " + q(dir) + sweep + mode,
                      dir + "/" + name};
    check_failed_write(c, test::run_railsim(c.args));
  }
  const std::string dir = folder_with_full("modes", "modes.csv");
  const WriteCase c{"modes.csv", "modes " + q(kWheelset) + " --v-min 50 --v-max 100 --v-step 50 --out " + q(dir),
                    dir + "/modes.csv"};
  check_failed_write(c, test::run_railsim(c.args));
}

TEST_CASE("railsim run under a file-size limit (as a disk filling up): exit 2 naming a file, no exit 0",
          "[cli][bad_input][write]") {
  // ulimit -f: writes beyond a few kB fail with EFBIG (the signal ignored: a full disk sends none).
  const std::string dir = test::temp_dir("full_limit");
  const auto lim = test::run_shell("sh -c \"trap '' XFSZ; ulimit -f 4; exec " + kBinary + " run " + q(kWheelset) +
                             " --out " + q(dir + "/limited") + "\" 2>&1");
  INFO(lim.output);
  CHECK(lim.exit_code == 2);
  CHECK(lim.output.find(dir + "/limited/") != std::string::npos);
  CHECK(lim.output.find(": write failed (File too large)") != std::string::npos);
  // Without the trap: SIGXFSZ's default action would kill railsim (exit 153, no message); it ignores the
  // signal itself, so the limit is a failed write as above.
  const auto sig = test::run_shell("sh -c \"ulimit -f 4; exec " + kBinary + " run " + q(kWheelset) + " --out " +
                                   q(dir + "/limited_nosig") + "\" 2>&1");
  INFO(sig.output);
  CHECK(sig.exit_code == 2);
  CHECK(sig.output.find(dir + "/limited_nosig/") != std::string::npos);
  CHECK(sig.output.find(": write failed (File too large)") != std::string::npos);
}
