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
  std::setvbuf(file_, nullptr, _IONBF, 0);  // rows are buffered in pending_ and written whole
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
  if (!file_) return;
  // The whole rows not yet written (unchecked here: close() reports a failure).
  const std::size_t whole = pending_.rfind('\n');
  if (whole != std::string::npos) std::fwrite(pending_.data(), 1, whole + 1, file_);
  std::fclose(file_);
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
  if (cells_in_row_ > 0) pending_ += ',';
  ++cells_in_row_;
}

CsvWriter& CsvWriter::cell(double v) {
  separator();
  if (std::isnan(v)) {
    pending_ += "nan";
    return *this;
  }
  // std::to_chars with a precision formats exactly as printf's %.*g does,
  // several times faster (it sets the cost of writing long runs).
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, precision_);
  pending_.append(buf, std::size_t(r.ptr - buf));
  return *this;
}

CsvWriter& CsvWriter::cell(long v) {
  separator();
  pending_ += std::to_string(v);
  return *this;
}

CsvWriter& CsvWriter::cell(std::string_view text) {
  separator();
  const bool quote = text.find_first_of(",\"\n") != std::string_view::npos;
  if (!quote) {
    pending_.append(text.data(), text.size());
    return *this;
  }
  pending_ += '"';
  for (char c : text) {
    if (c == '"') pending_ += '"';
    pending_ += c;
  }
  pending_ += '"';
  return *this;
}

void CsvWriter::end_row() {
  if (cells_in_row_ != columns_.size())
    throw std::logic_error(path_ + ": row has " + std::to_string(cells_in_row_) + " cells, header has " +
                           std::to_string(columns_.size()));
  pending_ += '\n';
  cells_in_row_ = 0;
  // Every flush_every rows, and whenever 8 KiB are pending (as a stdio buffer:
  // bounded memory, and a failing disk shows within a few hundred rows).
  constexpr std::size_t kChunk = 8192;
  if (++rows_since_flush_ >= flush_every_ || pending_.size() >= kChunk) flush();
}

void CsvWriter::row(const std::vector<double>& values) {
  for (double v : values) cell(v);
  end_row();
}

void CsvWriter::flush() {
  // A full disk or a lost device shows here (the rows are buffered): an
  // error naming the file, never a run that ends as if its rows were kept.
  if (!file_) throw std::logic_error(path_ + ": write after close");
  write_pending(pending_.size());
  rows_since_flush_ = 0;
}

void CsvWriter::write_pending(std::size_t bytes) {
  const std::size_t written = bytes > 0 ? std::fwrite(pending_.data(), 1, bytes, file_) : 0;
  const bool failed = written != bytes || std::fflush(file_) != 0 || std::ferror(file_);
  const int err = errno;
  pending_.erase(0, bytes);
  if (failed)
    throw InputError(path_ + ": write failed (" + std::strerror(err) + "): the rows since the last flush are lost");
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
