// Atomic file writes (temporary file then rename); see atomic_file.hpp.
#include "core/atomic_file.hpp"

#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <thread>

#include "core/errors.hpp"

namespace railsim {

std::string temporary_path_for(const std::string& path) {
  // pid and thread keep processes and threads apart; the counter keeps two
  // writes of one thread apart (a write nested in another's callback).
  static std::atomic<unsigned long> counter{0};
  return path + ".tmp." + std::to_string(static_cast<long>(::getpid())) + "." +
         std::to_string(std::hash<std::thread::id>{}(std::this_thread::get_id())) + "." +
         std::to_string(counter.fetch_add(1, std::memory_order_relaxed));
}

void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write) {
  const std::string tmp = temporary_path_for(path);
  std::error_code ec;
  try {
    std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
    if (!f) throw InputError(path + ": cannot open '" + tmp + "' for writing");
    write(f);
    f.flush();
    if (!f) throw InputError(path + ": write failed (disk full or no permission?)");
  } catch (...) {
    std::filesystem::remove(tmp, ec);
    throw;
  }
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw InputError(path + ": cannot rename the temporary file '" + tmp + "' to it: " + ec.message());
  }
}

void write_file_atomically(const std::string& path, std::string_view content) {
  write_file_atomically(path, [content](std::ostream& f) { f.write(content.data(), static_cast<std::streamsize>(content.size())); });
}

}  // namespace railsim
