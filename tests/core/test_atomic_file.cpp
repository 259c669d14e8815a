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

namespace {
// The message of the InputError `f` throws ("" when it throws none).
template <class F>
std::string input_error_of(F f) {
  try {
    f();
  } catch (const railsim::InputError& e) {
    return e.what();
  }
  return "";
}
bool has(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }
}  // namespace

TEST_CASE("checked writes: a full disk (/dev/full) is an error naming the file, the device stays",
          "[core][atomic_file][write]") {
  // /dev/full accepts the open and fails every write with ENOSPC (Linux).
  if (!fs::is_character_file("/dev/full")) return;
  const std::string m = input_error_of([] { railsim::write_file_atomically("/dev/full", std::string("x")); });
  INFO(m);
  CHECK(has(m, "/dev/full: write failed (No space left on device)"));
  CHECK(has(m, "disk is full"));
  // Written in place: no temporary beside it in /dev, and the device is not replaced.
  CHECK(fs::is_character_file("/dev/full"));
  for (const auto& e : fs::directory_iterator("/dev")) CHECK(e.path().string().rfind("/dev/full.tmp.", 0) != 0);
  // Through a link in an output folder (how the program's tests fill a disk).
  const std::string dir = railsim::test::temp_dir("atomic_file_full");
  fs::create_symlink("/dev/full", dir + "/summary.json");
  const std::string l = input_error_of([&] {
    railsim::write_file_atomically(dir + "/summary.json", [](std::ostream& o) { o << std::string(100000, 'y'); });
  });
  CHECK(has(l, dir + "/summary.json: write failed (No space left on device)"));
  CHECK(fs::is_symlink(dir + "/summary.json"));
  // A log (resume records, states) on a full disk.
  railsim::AppendFile log(dir + "/summary.json");
  CHECK(has(input_error_of([&] { log.write("1,key,2\n"); }), dir + "/summary.json: write failed"));
  CHECK_NOTHROW(log.close());
  // Nothing read back from a device: a resume file that is one reads as empty (not forever).
  CHECK(railsim::read_own_file(dir + "/summary.json").empty());
  CHECK(railsim::read_own_file("/dev/zero").empty());
}

TEST_CASE("checked writes: unwritable places name the file and the reason", "[core][atomic_file][write]") {
  const std::string dir = railsim::test::temp_dir("atomic_file_place");
  railsim::write_file_atomically(dir + "/plain", std::string("x"));
  // A folder where a file is expected, a file where a folder is expected.
  CHECK(has(input_error_of([&] { railsim::write_file_atomically(dir, std::string("x")); }), dir + ": is a folder"));
  const std::string under = dir + "/plain/f.txt";
  const std::string m = input_error_of([&] { railsim::write_file_atomically(under, std::string("x")); });
  CHECK(has(m, under + ": cannot create the temporary file"));
  CHECK(has(m, "(Not a directory)"));
  CHECK(has(input_error_of([&] { railsim::AppendFile f(under); }), under + ": cannot open for writing (Not a directory)"));
  // Append and truncate modes; records reach the file at once (no buffer).
  railsim::AppendFile log(dir + "/log");
  log.write("a\n");
  CHECK(railsim::test::read_text(dir + "/log") == "a\n");
  log.close();
  railsim::AppendFile again(dir + "/log");
  again.write("b\n");
  CHECK(railsim::test::read_text(dir + "/log") == "a\nb\n");
  railsim::AppendFile fresh(dir + "/log", railsim::AppendFile::Mode::truncate);
  fresh.write("c\n");
  CHECK(railsim::test::read_text(dir + "/log") == "c\n");
  CHECK(railsim::read_own_file(dir + "/log") == "c\n");
  CHECK(railsim::read_own_file(dir + "/missing").empty());
}
