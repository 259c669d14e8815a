// CSV writer: rows are on disk as soon as they are written; append resumes without a second header.
#include <catch2/catch.hpp>

#include <sys/resource.h>

#include <csignal>

#include <fstream>
#include <string>

#include "core/errors.hpp"
#include "results/csv_writer.hpp"
#include "test_support.hpp"

using namespace railsim::results;

TEST_CASE("rows are flushed as they are written and read back", "[results]") {
  const std::string dir = railsim::test::temp_dir("csv");
  const std::string path = dir + "/a.csv";
  {
    CsvWriter w(path, {"id", "x", "note"});
    w.cell("c1").cell(1.5).cell("a, \"quoted\" note").end_row();
    // Before the writer is destroyed the row must already be readable.
    const auto t = read_csv(path);
    REQUIRE(t.rows.size() == 1);
    CHECK(t.rows[0][2] == "a, \"quoted\" note");
    CHECK(t.number(0, "x") == 1.5);
  }
  {
    CsvWriter w(path, {"id", "x", "note"}, /*append=*/true);
    w.cell("c2").cell(2.0).cell("").end_row();
  }
  const auto t = read_csv(path);
  REQUIRE(t.rows.size() == 2);
  CHECK(t.rows[1][0] == "c2");
}

TEST_CASE("a wrong cell count and unreadable files are reported", "[results]") {
  const std::string dir = railsim::test::temp_dir("csv2");
  CsvWriter w(dir + "/b.csv", {"a", "b"});
  w.cell(1.0);
  CHECK_THROWS_AS(w.end_row(), std::logic_error);
  CHECK_THROWS_AS(read_csv(dir + "/missing.csv"), railsim::InputError);
  CHECK_THROWS_AS(CsvWriter(dir + "/no/such/dir/c.csv", {"a"}), railsim::InputError);
}

TEST_CASE("a write that fails (full disk) is an error naming the file, not lost rows", "[results][csv][write]") {
  // /dev/full accepts the open and fails every write with ENOSPC (Linux).
  if (!std::ifstream("/dev/full").good()) return;
  try {
    // The header is flushed when the file is opened: a full disk shows before any work.
    CsvWriter w("/dev/full", {"a", "b"});
    w.cell(1.0).cell(2.0);
    w.end_row();  // flush_every = 1: the row is flushed here
    FAIL("no error on a full device");
  } catch (const railsim::InputError& e) {
    CHECK(std::string(e.what()).find("/dev/full") != std::string::npos);
    CHECK(std::string(e.what()).find("write failed") != std::string::npos);
  }
}

namespace {
// A file-size limit for this process (as a full disk: writes beyond it fail
// with EFBIG), lifted again on destruction.
struct FileSizeLimit {
  rlimit old{};
  void (*old_handler)(int) = nullptr;
  explicit FileSizeLimit(rlim_t bytes) {
    getrlimit(RLIMIT_FSIZE, &old);
    old_handler = std::signal(SIGXFSZ, SIG_IGN);  // the write fails instead of the signal ending the process
    rlimit r = old;
    r.rlim_cur = bytes;
    setrlimit(RLIMIT_FSIZE, &r);
  }
  ~FileSizeLimit() {
    setrlimit(RLIMIT_FSIZE, &old);
    std::signal(SIGXFSZ, old_handler);
  }
};
}  // namespace

TEST_CASE("buffered rows that cannot be written: the row that fills the buffer or close() names the file",
          "[results][csv][write]") {
  const std::string dir = railsim::test::temp_dir("csv_full");
  {
    // Rows buffered (flush every 100000): the failure shows when the buffer goes out, not at the end.
    const FileSizeLimit limit(1000);
    CsvWriter w(dir + "/many.csv", {"a", "b"}, false, 100000);
    std::string m;
    int rows = 0;
    try {
      for (; rows < 100000; ++rows) w.row({1.0 * rows, 2.0});
    } catch (const railsim::InputError& e) {
      m = e.what();
    }
    INFO(m);
    CHECK(m.find(dir + "/many.csv: write failed (File too large)") != std::string::npos);
    CHECK(rows < 2000);  // the buffer (BUFSIZ) of rows, not the whole run
  }
  {
    // The last rows, still buffered, fail at close().
    const FileSizeLimit limit(20);
    CsvWriter w(dir + "/few.csv", {"a", "b"}, false, 100000);
    for (int i = 0; i < 10; ++i) w.row({1.0, 2.0});  // 40 bytes after a 4-byte header: buffered
    std::string m;
    try {
      w.close();
    } catch (const railsim::InputError& e) {
      m = e.what();
    }
    CHECK(m.find(dir + "/few.csv: write failed") != std::string::npos);
  }
  // Without a limit the same rows are all there after close().
  CsvWriter ok(dir + "/few.csv", {"a", "b"}, false, 100000);
  for (int i = 0; i < 10; ++i) ok.row({1.0, 2.0});
  ok.close();
  CHECK(read_csv(dir + "/few.csv").rows.size() == 10);
}

TEST_CASE("the file holds whole rows only, whatever is pending", "[results][csv][write]") {
  // Rows are written whole (a run stopped by a signal left a torn last row: 29 of 103 cells): between
  // flushes the file ends with a complete row, and rows pending at destruction are written whole.
  const std::string dir = railsim::test::temp_dir("csv_whole_rows");
  const std::string path = dir + "/rows.csv";
  auto ends_with_whole_row = [&] {
    const std::string t = railsim::test::read_text(path);
    return !t.empty() && t.back() == '\n';
  };
  {
    CsvWriter w(path, {"a", "b", "c"}, false, 1000000);
    for (int i = 0; i < 5000; ++i) {  // 8 KiB chunks go out on the way
      w.cell(1.0 * i).cell(0.123456789);
      CHECK(ends_with_whole_row());  // the row being built is not in the file
      w.cell(2.0);
      w.end_row();
    }
    CHECK(ends_with_whole_row());
    CHECK(read_csv(path).rows.size() < 5000);  // some rows still pending
    w.cell(7.0).cell(8.0);                       // a row left half-built
  }                                              // destroyed without close()
  const auto t = read_csv(path);
  CHECK(t.rows.size() == 5000);  // the whole rows, not the half one
  CHECK(t.number(4999, "a") == 4999.0);
}
