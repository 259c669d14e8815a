// Helpers shared by the test suites: paths of reference data and a way to run
// the railsim program and capture its exit code and output.
#pragma once

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <sys/wait.h>
#include <system_error>
#include <vector>
#include <unistd.h>

namespace railsim::test {

// tests/data folder (our own validation data files).
inline std::string data_path(const std::string& rel) { return std::string(RAILSIM_TEST_DATA_DIR) + "/" + rel; }
// Reference results of other programs copied into the repository with their
// NOTICE (tests/data/reference/: CONTACT's results in contact/).
inline std::string reference_path(const std::string& rel) { return data_path("reference/" + rel); }
// Cache folder shared by all test processes of this build (contact tables are
// built once and written atomically, so concurrent tests may share it).
inline std::string cache_dir() { return RAILSIM_TEST_CACHE_DIR; }
inline std::string source_path(const std::string& rel) { return std::string(RAILSIM_SOURCE_DIR) + "/" + rel; }

// The whole content of a file (empty when it cannot be read).
inline std::string read_text(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

// The data rows of a CSV file (after its header): how many, how many have
// another number of cells than the header (a torn row), and the last one.
struct CsvRows {
  int rows = 0;
  int torn = 0;
  std::string last;
  double last_first_cell() const { return last.empty() ? 0.0 : std::stod(last.substr(0, last.find(','))); }
};
inline CsvRows csv_rows(const std::string& path) {
  CsvRows r;
  std::ifstream in(path);
  std::string header, line;
  std::getline(in, header);
  const auto cells = std::count(header.begin(), header.end(), ',');
  while (std::getline(in, line)) {
    if (std::count(line.begin(), line.end(), ',') != cells) ++r.torn;
    r.last = line;
    ++r.rows;
  }
  return r;
}

// Prefix for `mpirun ...` command lines. Under AddressSanitizer, OpenMPI's own
// allocations (in plugins it unloads before exit, so no suppression can name
// them) fail LeakSanitizer's exit check: leak checking is off for the MPI
// processes only; our code's leaks are checked by the thread-based tests.
inline std::string mpirun_prefix() {
#ifdef __SANITIZE_ADDRESS__
  return "ASAN_OPTIONS=detect_leaks=0 ";
#else
  return "";
#endif
}

struct RunResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr together
};

// Run `railsim <args>` through the shell; args are passed verbatim.
inline RunResult run_railsim(const std::string& args) {
  RunResult r;
  const std::string cmd = std::string("\"") + RAILSIM_BINARY + "\" " + args + " 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return r;
  std::array<char, 4096> buf{};
  std::size_t n = 0;
  while ((n = fread(buf.data(), 1, buf.size(), p)) > 0) r.output.append(buf.data(), n);
  const int status = pclose(p);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

// A fresh temporary folder for one test's outputs.
// The folders made by temp_dir in this process, removed when it exits (set
// RAILSIM_KEEP_TEST_DIRS=1 to keep them for a look after a failure).
inline std::vector<std::string>& temp_dirs_made() {
  static std::vector<std::string> dirs;
  return dirs;
}

inline void remove_temp_dirs() {
  if (std::getenv("RAILSIM_KEEP_TEST_DIRS")) return;
  for (const auto& d : temp_dirs_made()) {
    std::error_code ec;
    std::filesystem::remove_all(d, ec);
  }
}

inline std::string temp_dir(const std::string& name) {
  const char* base = std::getenv("TMPDIR");
  std::string dir = std::string(base ? base : "/tmp") + "/railsim_test_" + name + "_" + std::to_string(::getpid());
  std::string cmd = "rm -rf '" + dir + "' && mkdir -p '" + dir + "'";
  if (std::system(cmd.c_str()) != 0) return "/tmp";
  if (temp_dirs_made().empty()) std::atexit(remove_temp_dirs);
  temp_dirs_made().push_back(dir);
  return dir;
}

}  // namespace railsim::test
