// Streaming CSV writer and a small reader; see csv_writer.hpp.
#include "results/csv_writer.hpp"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

#include "core/errors.hpp"

namespace railsim::results {

CsvWriter::CsvWriter(const std::string& path, std::vector<std::string> columns, bool append,
                     int flush_every, int precision)
    : path_(path), columns_(std::move(columns)), flush_every_(flush_every < 1 ? 1 : flush_every),
      precision_(precision) {
  bool write_header = true;
  if (append) {
    if (std::FILE* probe = std::fopen(path.c_str(), "rb")) {
      std::fseek(probe, 0, SEEK_END);
      write_header = std::ftell(probe) == 0;
      std::fclose(probe);
    }
  }
  file_ = std::fopen(path.c_str(), append ? "ab" : "wb");
  if (!file_) throw InputError(path + ": cannot open for writing (" + std::strerror(errno) + ")");
  if (write_header) {
    for (std::size_t i = 0; i < columns_.size(); ++i)
      std::fprintf(file_, "%s%s", i ? "," : "", columns_[i].c_str());
    std::fputc('\n', file_);
    if (std::fflush(file_) != 0 || std::ferror(file_)) {
      const int err = errno;
      std::fclose(file_);
      file_ = nullptr;
      throw InputError(path + ": write failed (" + std::strerror(err) + ")");
    }
  }
}

CsvWriter::~CsvWriter() {
  if (file_) std::fclose(file_);  // unchecked here: close() reports a failure
}

void CsvWriter::close() {
  if (!file_) return;
  flush();
  std::FILE* f = file_;
  file_ = nullptr;
  if (std::fclose(f) != 0)
    throw InputError(path_ + ": write failed at close (" + std::strerror(errno) + "): the last rows may be lost");
}

void CsvWriter::separator() {
  if (cells_in_row_ > 0) std::fputc(',', file_);
  ++cells_in_row_;
}

CsvWriter& CsvWriter::cell(double v) {
  separator();
  if (std::isnan(v)) {
    std::fputs("nan", file_);
    return *this;
  }
  // std::to_chars with a precision formats exactly as printf's %.*g does,
  // several times faster (it sets the cost of writing long runs).
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, precision_);
  std::fwrite(buf, 1, std::size_t(r.ptr - buf), file_);
  return *this;
}

CsvWriter& CsvWriter::cell(long v) {
  separator();
  std::fprintf(file_, "%ld", v);
  return *this;
}

CsvWriter& CsvWriter::cell(std::string_view text) {
  separator();
  const bool quote = text.find_first_of(",\"\n") != std::string_view::npos;
  if (!quote) {
    std::fwrite(text.data(), 1, text.size(), file_);
    return *this;
  }
  std::fputc('"', file_);
  for (char c : text) {
    if (c == '"') std::fputc('"', file_);
    std::fputc(c, file_);
  }
  std::fputc('"', file_);
  return *this;
}

void CsvWriter::end_row() {
  if (cells_in_row_ != columns_.size())
    throw std::logic_error(path_ + ": row has " + std::to_string(cells_in_row_) + " cells, header has " +
                           std::to_string(columns_.size()));
  std::fputc('\n', file_);
  cells_in_row_ = 0;
  // A buffered write that already failed (the buffer went out full) shows at once.
  if (++rows_since_flush_ >= flush_every_ || std::ferror(file_)) flush();
}

void CsvWriter::row(const std::vector<double>& values) {
  for (double v : values) cell(v);
  end_row();
}

void CsvWriter::flush() {
  // A full disk or a lost device shows here (the rows are buffered): an
  // error naming the file, never a run that ends as if its rows were kept.
  if (!file_) throw std::logic_error(path_ + ": write after close");
  if (std::fflush(file_) != 0 || std::ferror(file_))
    throw InputError(path_ + ": write failed (" + std::strerror(errno) + "): the rows since the last flush are lost");
  rows_since_flush_ = 0;
}

namespace {

std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> out;
  std::string cur;
  bool in_quotes = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (in_quotes) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        cur += '"';
        ++i;
      } else if (c == '"') {
        in_quotes = false;
      } else {
        cur += c;
      }
    } else if (c == '"') {
      in_quotes = true;
    } else if (c == ',') {
      out.push_back(cur);
      cur.clear();
    } else if (c != '\r') {
      cur += c;
    }
  }
  out.push_back(cur);
  return out;
}

}  // namespace

CsvTable read_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open file for reading");
  CsvTable t;
  t.file = path;
  std::string line;
  int lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    if (line.empty() || line[0] == '#') continue;
    auto cells = split_csv_line(line);
    if (t.header.empty()) {
      t.header = std::move(cells);
      continue;
    }
    if (cells.size() != t.header.size())
      throw InputError(path + ":" + std::to_string(lineno) + ": expected " + std::to_string(t.header.size()) +
                       " cells, found " + std::to_string(cells.size()));
    t.rows.push_back(std::move(cells));
  }
  if (t.header.empty()) throw InputError(path + ": empty CSV file (no header line)");
  return t;
}

std::size_t CsvTable::column(std::string_view name) const {
  for (std::size_t i = 0; i < header.size(); ++i)
    if (header[i] == name) return i;
  throw InputError(file + ": no column named '" + std::string(name) + "'");
}

double CsvTable::number(std::size_t row, std::string_view col) const {
  const std::string& s = rows.at(row).at(column(col));
  std::size_t used = 0;
  double v = 0;
  try {
    v = std::stod(s, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0) throw InputError(file + ": row " + std::to_string(row + 2) + " column '" + std::string(col) +
                                  "': expected a number (got '" + s + "')");
  return v;
}

}  // namespace railsim::results
