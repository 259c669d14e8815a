// The data folder: $RAILSIM_DATA_DIR, else share/railsim found from the binary
// (in the build tree <build>/share/railsim, filled by the build); never a source path.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>

#include "core/data_dir.hpp"
#include "core/errors.hpp"
#include "test_support.hpp"

namespace fs = std::filesystem;

TEST_CASE("the data folder is found relative to the binary", "[core][data_dir]") {
  unsetenv("RAILSIM_DATA_DIR");
  const fs::path bin = railsim::binary_path();
  CHECK(bin.filename() == "test_core");
  const fs::path d = railsim::data_dir();
  CHECK(fs::exists(d / "railsim-data.txt"));
  CHECK(fs::exists(d / "profiles" / "MBench_S1002_v3.prw"));
  CHECK(fs::exists(d / "plots" / "render_chart.py"));
  CHECK(fs::exists(d / "scenarios" / "manchester_coach_critical_speed.yaml"));
  CHECK(fs::exists(d / "vehicles" / "contact_tables" / "RSGEO_S1002_UIC60_1in40.dat"));
  // Beside the binary's build tree, not in the sources.
  CHECK(d.string().rfind(bin.parent_path().parent_path().parent_path().string(), 0) == 0);
  CHECK(fs::canonical(d).string().rfind(fs::canonical(RAILSIM_SOURCE_DIR).string() + "/share", 0) != 0);
  // The copies are the sources' files.
  CHECK(railsim::test::read_text((d / "profiles" / "MBench_S1002_v3.prw").string()) ==
        railsim::test::read_text(railsim::test::source_path("profiles/MBench_S1002_v3.prw")));
  CHECK(railsim::data_path("tracks") == d.string() + "/tracks");
}

TEST_CASE("RAILSIM_DATA_DIR overrides, and a wrong one is a clear error", "[core][data_dir]") {
  const std::string good = railsim::data_dir();
  const std::string dir = railsim::test::temp_dir("data_dir");
  setenv("RAILSIM_DATA_DIR", dir.c_str(), 1);
  try {
    railsim::data_dir();
    FAIL("no error");
  } catch (const railsim::InputError& e) {
    CHECK(std::string(e.what()).find("RAILSIM_DATA_DIR=" + dir + ": not a railsim data folder") == 0);
  }
  setenv("RAILSIM_DATA_DIR", good.c_str(), 1);
  CHECK(railsim::data_dir() == good);
  unsetenv("RAILSIM_DATA_DIR");
}
