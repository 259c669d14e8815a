// Bounded input-file reads (core/input_file.hpp): folders, devices and files
// beyond the size limit are refused naming the file before any byte is read;
// quotes of input text are one line of at most 80 characters.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "core/errors.hpp"
#include "core/input_file.hpp"
#include "test_support.hpp"

using namespace railsim;

namespace {
std::string error_of(const std::string& path, std::uintmax_t limit = kMaxInputFileBytes) {
  try {
    read_input_file(path, "test input", limit);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST_CASE("input files: regular, at most the size limit, else an error naming the file", "[core][input]") {
  const std::string dir = test::temp_dir("input_file");
  const std::string f = dir + "/ten.txt";
  { std::ofstream(f) << "0123456789"; }
  CHECK(read_input_file(f, "test input") == "0123456789");
  CHECK(read_input_file(f, "test input", 10) == "0123456789");
  CHECK(error_of(f, 9) == f + ": test input: 10 bytes, larger than the limit of 9 bytes for input files");
  CHECK(error_of(dir) == dir + ": test input: is a folder, expected a file");
  CHECK(error_of("/dev/zero") == "/dev/zero: test input: not a regular file (a device, pipe or socket); give a file");
  CHECK(error_of(dir + "/none") == dir + "/none: test input not found (cannot open file for reading)");
}

TEST_CASE("quote_input keeps one line of at most 80 characters", "[core][input]") {
  CHECK(quote_input("short") == "short");
  CHECK(quote_input("first\nsecond") == "first...");
  CHECK(quote_input(std::string(81, 'a')) == std::string(80, 'a') + "...");
  CHECK(quote_input(std::string(80, 'a')) == std::string(80, 'a'));
  // Control bytes of junk input are shown, not sent to the terminal; other bytes (UTF-8 names) kept.
  CHECK(quote_input(std::string("a\x1b[2Jb\tc") + '\0' + "d") == "a\\x1b[2Jb\\x09c\\x00d");
  CHECK(quote_input("Z\xc3\xbcrich") == "Z\xc3\xbcrich");
}
