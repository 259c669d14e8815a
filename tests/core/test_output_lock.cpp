// Output-folder lock (core/output_lock.hpp): a second writer of a folder is
// refused naming the folder and the holder's pid; the lock goes with its holder.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <optional>

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
