// Checked file writes (atomic whole files, unbuffered logs); see atomic_file.hpp.
#include "core/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <thread>

#include "core/errors.hpp"

namespace railsim {

namespace {

// Write all bytes to fd (short writes and interrupted calls continued); false
// with errno set on failure.
bool write_all(int fd, std::string_view bytes) {
  const char* p = bytes.data();
  std::size_t left = bytes.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, p, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    if (n == 0) {
      errno = EIO;
      return false;
    }
    p += n;
    left -= static_cast<std::size_t>(n);
  }
  return true;
}

int open_for_writing(const std::string& path, int flags) {
  int fd = -1;
  do {
    fd = ::open(path.c_str(), flags | O_WRONLY | O_CLOEXEC, 0666);
  } while (fd < 0 && errno == EINTR);
  return fd;
}

// Write into an existing non-regular file (a device or pipe) in place.
void write_in_place(const std::string& path, std::string_view content) {
  const int fd = open_for_writing(path, 0);
  if (fd < 0) throw_write_error(path, "cannot open for writing", errno);
  if (!write_all(fd, content)) {
    const int err = errno;
    ::close(fd);
    throw_write_error(path, "write failed", err);
  }
  if (::close(fd) != 0) throw_write_error(path, "write failed at close", errno);
}

}  // namespace

void throw_write_error(const std::string& path, const std::string& what, int err) {
  std::string m = path + ": " + what;
  if (err != 0) m += std::string(" (") + std::strerror(err) + ")";
  if (err == ENOSPC || err == EDQUOT || err == EFBIG) m += ": the disk is full or the file exceeds a size limit";
  throw InputError(m);
}

std::string temporary_path_for(const std::string& path) {
  // pid and thread keep processes and threads apart; the counter keeps two
  // writes of one thread apart (a write nested in another's callback).
  static std::atomic<unsigned long> counter{0};
  return path + ".tmp." + std::to_string(static_cast<long>(::getpid())) + "." +
         std::to_string(std::hash<std::thread::id>{}(std::this_thread::get_id())) + "." +
         std::to_string(counter.fetch_add(1, std::memory_order_relaxed));
}

void write_file_atomically(const std::string& path, std::string_view content) {
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) {
    if (S_ISDIR(st.st_mode)) throw InputError(path + ": is a folder, cannot write a file in its place");
    write_in_place(path, content);
    return;
  }
  const std::string tmp = temporary_path_for(path);
  const int fd = open_for_writing(tmp, O_CREAT | O_EXCL);
  if (fd < 0) throw_write_error(path, "cannot create the temporary file '" + tmp + "'", errno);
  const auto fail = [&](const std::string& what, int err) {
    ::unlink(tmp.c_str());
    throw_write_error(path, what, err);
  };
  if (!write_all(fd, content)) {
    const int err = errno;
    ::close(fd);
    fail("write failed", err);
  }
  if (::close(fd) != 0) fail("write failed at close", errno);
  if (::rename(tmp.c_str(), path.c_str()) != 0) fail("cannot rename the temporary file '" + tmp + "' to it", errno);
}

void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write) {
  std::ostringstream out(std::ios::binary);
  write(out);
  if (!out) throw InputError(path + ": the content could not be formatted");
  write_file_atomically(path, out.view());
}

std::string read_own_file(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return {};
  std::ifstream in(path, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// ---------------------------------------------------------------- AppendFile

AppendFile::~AppendFile() {
  if (fd_ >= 0) ::close(fd_);
}

void AppendFile::open(const std::string& path, Mode mode) {
  if (fd_ >= 0) close();
  path_ = path;
  fd_ = open_for_writing(path, O_CREAT | (mode == Mode::append ? O_APPEND : O_TRUNC));
  if (fd_ < 0) throw_write_error(path, "cannot open for writing", errno);
}

void AppendFile::write(std::string_view bytes) {
  if (fd_ < 0) throw InputError(path_ + ": write to a file that is not open");
  if (!write_all(fd_, bytes)) throw_write_error(path_, "write failed", errno);
}

void AppendFile::close() {
  if (fd_ < 0) return;
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) throw_write_error(path_, "write failed at close", errno);
}

}  // namespace railsim
