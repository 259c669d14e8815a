// Output-folder lock (core/output_lock.hpp): a second writer of a folder is
// refused naming the folder and the holder's pid; the lock goes with its holder.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "core/output_lock.hpp"
#include "test_support.hpp"

using namespace railsim;

TEST_CASE("an output folder has one writer at a time", "[core][lock]") {
  const std::string dir = test::temp_dir("output_lock") + "/out";
  std::optional<OutputLock> first(std::in_place, dir);  // creates the folder
  std::string msg;
  try {
    OutputLock second(dir);
  } catch (const InputError& e) {
    msg = e.what();
  }
  CHECK(msg == dir + ": another railsim process (pid " + std::to_string(::getpid()) +
                   ") is writing this output folder; wait for it to finish or give another --out");
  first.reset();
  CHECK_NOTHROW(OutputLock(dir));
  CHECK_NOTHROW(OutputLock(test::temp_dir("output_lock") + "/other"));
}

// A folder holds one analysis's results: the same analysis may write it again
// (a rerun, a resume), another one is refused naming both (its summary.json
// would replace the first one's); a folder taken without naming the analysis
// (or one from before the record) accepts any.
TEST_CASE("an output folder holds the results of one analysis", "[core][lock]") {
  // A command that writes a file while it holds the lock (a folder left with
  // only the markers is removed: see the next test).
  const auto write_into = [](const std::string& d, const char* analysis) {
    OutputLock lock(d, analysis);
    std::ofstream(d + "/result.txt") << "x\n";
  };
  const std::string dir = test::temp_dir("output_lock_analysis") + "/out";
  CHECK_NOTHROW(write_into(dir, "run"));
  CHECK(test::read_text(dir + "/.railsim.analysis") == "run\n");
  CHECK_NOTHROW(OutputLock(dir, "run"));
  CHECK_NOTHROW(OutputLock(dir));
  std::string msg;
  try {
    OutputLock other(dir, "critical-speed");
  } catch (const InputError& e) {
    msg = e.what();
  }
  CHECK(msg == dir + ": holds the results of `railsim run` (" + dir + "/.railsim.analysis); `railsim critical-speed` "
                     "would replace its summary.json: give another output folder, or remove this one first");
  // Refused, the folder is not left locked.
  CHECK_NOTHROW(OutputLock(dir, "run"));
  const std::string plain = test::temp_dir("output_lock_analysis") + "/plain";
  CHECK_NOTHROW(write_into(plain, ""));
  CHECK_NOTHROW(OutputLock(plain, "modes"));
  CHECK_THROWS_AS(OutputLock(plain, "run"), InputError);
}

// A command refused after it took the lock (its input turned out bad) leaves
// no trace: the folders the lock created, parents included, go again when
// they hold nothing but the markers; a folder that existed before, or one
// the command wrote into, stays.
TEST_CASE("an output folder the lock created and nothing filled is removed", "[core][lock]") {
  namespace fs = std::filesystem;
  const std::string base = test::temp_dir("output_lock_cleanup");
  { OutputLock lock(base + "/a/b/c", "run"); }
  CHECK_FALSE(fs::exists(base + "/a"));
  CHECK(fs::exists(base));
  fs::create_directories(base + "/existing");
  { OutputLock lock(base + "/existing", "run"); }
  CHECK(fs::exists(base + "/existing/.railsim.lock"));
  { OutputLock lock(base + "/existing/sub/out", "run"); }
  CHECK(fs::exists(base + "/existing"));
  CHECK_FALSE(fs::exists(base + "/existing/sub"));
  {
    OutputLock lock(base + "/x/out", "run");
    std::ofstream(base + "/x/out/channels.csv") << "time\n";
  }
  CHECK(test::read_text(base + "/x/out/channels.csv") == "time\n");
  CHECK(test::read_text(base + "/x/out/.railsim.analysis") == "run\n");
  {  // a file beside the output folder keeps the parent
    OutputLock lock(base + "/y/out", "run");
    std::ofstream(base + "/y/note.txt") << "mine\n";
  }
  CHECK_FALSE(fs::exists(base + "/y/out"));
  CHECK(test::read_text(base + "/y/note.txt") == "mine\n");
}

// Folders without the record (written before it existed, or by hand): the
// analyses' own files say whose results they are; a summary.json of none of
// them is not replaced either.
TEST_CASE("an output folder without the record is judged by its files", "[core][lock]") {
  const std::string base = test::temp_dir("output_lock_files");
  auto folder_with = [&](const std::string& name, const std::vector<std::string>& files) {
    const std::string dir = base + "/" + name;
    std::filesystem::create_directories(dir);
    for (const auto& f : files) std::ofstream(dir + "/" + f) << "x\n";
    return dir;
  };
  auto error_of = [](const std::string& dir, const std::string& analysis) {
    try {
      OutputLock l(dir, analysis);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string cs = folder_with("cs", {"bifurcation.csv", "summary.json"});
  CHECK(error_of(cs, "run") == cs + ": holds the results of `railsim critical-speed` (" + cs +
                                   "/bifurcation.csv); `railsim run` would replace its summary.json: give another "
                                   "output folder, or remove this one first");
  CHECK(error_of(cs, "critical-speed").empty());  // the same analysis resumes, and records it
  CHECK(test::read_text(cs + "/.railsim.analysis") == "critical-speed\n");
  const std::string run = folder_with("run", {"channels.csv", "summary.json"});
  CHECK(error_of(run, "modes").find("holds the results of `railsim run` (" + run + "/channels.csv)") !=
        std::string::npos);
  const std::string foreign = folder_with("foreign", {"summary.json"});
  CHECK(error_of(foreign, "run").find("holds a summary.json that no railsim analysis wrote (" + foreign +
                                      "/summary.json)") != std::string::npos);
  const std::string other = folder_with("other", {"notes.txt"});
  CHECK(error_of(other, "run").empty());
}
