// CSV writer: rows are on disk as soon as they are written; append resumes without a second header.
#include <catch2/catch.hpp>

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

TEST_CASE("a write that fails (full disk) is an error naming the file, not lost rows", "[results][csv]") {
  // /dev/full accepts the open and fails every write with ENOSPC (Linux).
  if (!std::ifstream("/dev/full").good()) return;
  CsvWriter w("/dev/full", {"a", "b"});
  w.cell(1.0).cell(2.0);
  try {
    w.end_row();  // flush_every = 1: the row is flushed here
    FAIL("no error on a full device");
  } catch (const railsim::InputError& e) {
    CHECK(std::string(e.what()).find("/dev/full") != std::string::npos);
    CHECK(std::string(e.what()).find("write failed") != std::string::npos);
  }
}
