// Atomic file writes: complete content or the old file, never a torn one;
// failures name the file and leave no temporary behind.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "core/atomic_file.hpp"
#include "core/errors.hpp"
#include "test_support.hpp"

namespace fs = std::filesystem;

TEST_CASE("write_file_atomically writes, replaces and leaves no temporary", "[core][atomic_file]") {
  const std::string dir = railsim::test::temp_dir("atomic_file");
  const std::string path = dir + "/f.txt";
  railsim::write_file_atomically(path, std::string("first\n"));
  CHECK(railsim::test::read_text(path) == "first\n");
  railsim::write_file_atomically(path, [](std::ostream& o) { o << "second " << 2 << "\n"; });
  CHECK(railsim::test::read_text(path) == "second 2\n");
  const std::string binary("a\0b\xff", 4);
  railsim::write_file_atomically(path, binary);
  CHECK(railsim::test::read_text(path) == binary);
  int files = 0;
  for (const auto& e : fs::directory_iterator(dir)) files += e.is_regular_file() ? 1 : 0;
  CHECK(files == 1);
  CHECK(railsim::temporary_path_for(path).rfind(path + ".tmp.", 0) == 0);
}

TEST_CASE("write_file_atomically: failures name the file, keep the old content", "[core][atomic_file]") {
  const std::string dir = railsim::test::temp_dir("atomic_file_fail");
  try {
    railsim::write_file_atomically(dir + "/no/such/folder/f.txt", std::string("x"));
    FAIL("no error");
  } catch (const railsim::InputError& e) {
    CHECK(std::string(e.what()).find(dir + "/no/such/folder/f.txt") != std::string::npos);
  }
  const std::string path = dir + "/keep.txt";
  railsim::write_file_atomically(path, std::string("old"));
  CHECK_THROWS_AS(railsim::write_file_atomically(path, [](std::ostream&) { throw railsim::InputError("stop"); }),
                  railsim::InputError);
  CHECK(railsim::test::read_text(path) == "old");
  int files = 0;
  for (const auto& e : fs::directory_iterator(dir)) files += e.is_regular_file() ? 1 : 0;
  CHECK(files == 1);  // the temporary was removed
}

TEST_CASE("write_file_atomically: concurrent writers never leave a torn file", "[core][atomic_file]") {
  const std::string dir = railsim::test::temp_dir("atomic_file_threads");
  const std::string path = dir + "/shared.txt";
  const std::string a(200000, 'a'), b(100000, 'b');
  std::vector<std::thread> pool;
  for (int t = 0; t < 4; ++t)
    pool.emplace_back([&, t] {
      for (int i = 0; i < 20; ++i) railsim::write_file_atomically(path, t % 2 ? a : b);
    });
  for (auto& th : pool) th.join();
  const std::string got = railsim::test::read_text(path);
  CHECK((got == a || got == b));
}
