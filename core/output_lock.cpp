// Output-folder lock; see output_lock.hpp.
#include "core/output_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "core/errors.hpp"

namespace railsim {

OutputLock::OutputLock(const std::string& dir, const std::string& analysis) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw InputError(dir + ": cannot create the output folder (" + ec.message() + ")");
  const std::string path = dir + "/.railsim.lock";
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) throw InputError(path + ": cannot create the output folder's lock file (" + std::strerror(errno) + ")");
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int err = errno;
    char buf[32] = {};
    const ssize_t n = ::pread(fd_, buf, sizeof buf - 1, 0);
    const std::string holder = n > 0 ? std::string(buf, static_cast<std::size_t>(n)) : std::string("unknown");
    ::close(fd_);
    fd_ = -1;
    if (err == EWOULDBLOCK)
      throw InputError(dir + ": another railsim process (pid " + holder +
                       ") is writing this output folder; wait for it to finish or give another --out");
    throw InputError(path + ": cannot lock the output folder (" + std::strerror(err) + ")");
  }
  const std::string pid = std::to_string(static_cast<long>(::getpid()));
  if (::ftruncate(fd_, 0) == 0 && ::pwrite(fd_, pid.data(), pid.size(), 0) < 0) {
    // The pid is for messages only.
  }
  if (analysis.empty()) return;
  // Whose results the folder holds (written by the holder of the lock only).
  const std::string marker = dir + "/.railsim.analysis";
  std::string before;
  if (std::ifstream in(marker); in) std::getline(in, before);
  if (!before.empty() && before != analysis) {
    ::close(fd_);
    fd_ = -1;
    throw InputError(dir + ": holds the results of `railsim " + before + "` (" + marker + "); `railsim " + analysis +
                     "` would replace its summary.json: give another output folder, or remove this one first");
  }
  if (before.empty()) {
    std::ofstream out(marker, std::ios::trunc);
    out << analysis << "\n";
    if (!out.flush()) {
      ::close(fd_);
      fd_ = -1;
      throw InputError(marker + ": cannot write (" + std::strerror(errno) + ")");
    }
  }
}

OutputLock::~OutputLock() {
  if (fd_ >= 0) ::close(fd_);  // closing releases the lock
}

}  // namespace railsim
