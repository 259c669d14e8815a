// Streaming CSV writer for result channels.
//
// Rows are written as they come and flushed at once (flush_every = 1) or every
// N rows, so an interrupted run keeps what it had computed. Every flush and
// the close() are checked: a full disk is an InputError naming the file. Numbers are written
// with 10 significant digits by default (enough for SI channels), text cells are
// quoted when they contain a comma or quote.
#pragma once

#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

namespace railsim::results {

class CsvWriter {
 public:
  // Open `path` for writing (truncate) or appending; throws InputError when the
  // file cannot be opened. With append=true and an existing non-empty file the
  // header is not written again.
  CsvWriter(const std::string& path, std::vector<std::string> columns, bool append = false,
            int flush_every = 1, int precision = 10);
  ~CsvWriter();
  CsvWriter(const CsvWriter&) = delete;
  CsvWriter& operator=(const CsvWriter&) = delete;

  // Cell-by-cell row building; end_row() checks the cell count.
  CsvWriter& cell(double v);
  CsvWriter& cell(long v);
  CsvWriter& cell(int v) { return cell(static_cast<long>(v)); }
  CsvWriter& cell(std::string_view text);
  CsvWriter& cell(const char* text) { return cell(std::string_view(text)); }
  CsvWriter& cell(bool v) { return cell(static_cast<long>(v ? 1 : 0)); }
  void end_row();
  // A whole numeric row at once.
  void row(const std::vector<double>& values);

  const std::vector<std::string>& columns() const { return columns_; }
  const std::string& path() const { return path_; }
  void flush();
  // Flush and close, reporting a failure (InputError naming the file). Call it
  // when the file is complete: the destructor closes without reporting.
  void close();

 private:
  void separator();
  void write_pending(std::size_t bytes);  // the first `bytes` of pending_ to the file, unbuffered
  std::string path_;
  // Rows not yet written, the current one last: the file receives whole rows
  // only, in one write each flush (a run stopped by a signal leaves no torn row).
  std::string pending_;
  std::vector<std::string> columns_;
  std::FILE* file_ = nullptr;
  int flush_every_;
  int precision_;
  int rows_since_flush_ = 0;
  std::size_t cells_in_row_ = 0;
};

// Read a CSV file written by CsvWriter (or any simple CSV with a header line):
// returns the header and the rows as text cells. Throws InputError naming the
// file and line on ragged rows.
struct CsvTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  // Index of a column; throws InputError naming the file when missing.
  std::size_t column(std::string_view name) const;
  double number(std::size_t row, std::string_view col) const;
  std::string file;
};
CsvTable read_csv(const std::string& path);

}  // namespace railsim::results
