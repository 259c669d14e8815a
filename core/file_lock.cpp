// Exclusive advisory file lock; see file_lock.hpp.
#include "core/file_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

namespace railsim {

FileLock::FileLock(const std::string& lock_path) : fd_(::open(lock_path.c_str(), O_RDWR | O_CREAT, 0644)) {
  if (fd_ >= 0 && ::flock(fd_, LOCK_EX) != 0) {
    ::close(fd_);
    fd_ = -1;
  }
}

FileLock::~FileLock() {
  if (fd_ >= 0) {
    ::flock(fd_, LOCK_UN);
    ::close(fd_);
  }
}

}  // namespace railsim
