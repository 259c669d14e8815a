// Bounded reading of input files; see input_file.hpp.
#include "core/input_file.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/errors.hpp"

namespace railsim {

namespace fs = std::filesystem;

void check_input_file(const std::string& path, std::string_view what, std::uintmax_t max_bytes) {
  const std::string head = path + ": " + std::string(what);
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (ec || !fs::exists(st)) throw InputError(head + " not found (cannot open file for reading)");
  if (fs::is_directory(st)) throw InputError(head + ": is a folder, expected a file");
  if (!fs::is_regular_file(st))
    throw InputError(head + ": not a regular file (a device, pipe or socket); give a file");
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) throw InputError(head + ": cannot read its size (" + ec.message() + ")");
  if (size > max_bytes)
    throw InputError(head + ": " + std::to_string(size) + " bytes, larger than the limit of " +
                     std::to_string(max_bytes) + " bytes for input files");
}

std::string read_input_file(const std::string& path, std::string_view what, std::uintmax_t max_bytes) {
  check_input_file(path, what, max_bytes);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open file for reading");
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) throw InputError(path + ": read error");
  std::string s = ss.str();
  // The file may have grown between the check and the read.
  if (s.size() > max_bytes)
    throw InputError(path + ": " + std::string(what) + ": larger than the limit of " + std::to_string(max_bytes) +
                     " bytes for input files");
  return s;
}

std::string quote_input(std::string_view text) {
  const std::size_t eol = text.find_first_of("\r\n");
  std::string_view line = text.substr(0, eol);
  bool cut = eol != std::string_view::npos;
  if (line.size() > kMaxQuotedChars) {
    line = line.substr(0, kMaxQuotedChars);
    cut = true;
  }
  std::string out;
  for (const char ch : line) {
    const auto b = static_cast<unsigned char>(ch);
    if (b < 0x20 || b == 0x7f) {  // control bytes (a terminal escape, a NUL) shown as \xNN
      static const char* const hex = "0123456789abcdef";
      out += {'\\', 'x', hex[b >> 4], hex[b & 0xf]};
    } else {
      out += ch;
    }
  }
  if (cut) out += "...";
  return out;
}

}  // namespace railsim
