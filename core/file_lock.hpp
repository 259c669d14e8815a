// Exclusive advisory lock on a file (flock(2)), held for the lifetime of the
// object and waited for when another process or thread holds it: the cache
// builders take it on "<cache file>.lock" so that a table is built once while
// the others wait and then load the finished file. The lock file is created
// when missing (and left in place: harmless, reused). When it cannot be
// created (read-only cache folder) there is no lock and each caller works on
// its own. The kernel drops the lock when the holder exits, even by kill -9.
// Compare core/output_lock.hpp: one writer per output folder, refusing (not
// waiting for) a second one.
#pragma once

#include <string>

namespace railsim {

class FileLock {
 public:
  explicit FileLock(const std::string& lock_path);
  ~FileLock();
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;
  bool held() const { return fd_ >= 0; }

 private:
  int fd_ = -1;  // -1: no lock
};

}  // namespace railsim
