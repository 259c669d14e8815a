// Checked file writes, the one way railsim writes a file: every write and
// close is checked, and a failure (disk full, no permission, a lost device)
// throws railsim::InputError naming the file and the system's reason
// ("PATH: write failed (No space left on device)"), exit 2 in the program.
//
// Whole files: the content goes to a temporary file beside the target,
// "<path>.tmp.<pid>.<thread>.<n>" (n a per-process counter: every call gets a
// fresh name), which is then renamed over the target (rename(2) replaces it
// atomically on one file system). Two processes or threads writing the same
// file each use their own temporary; the last rename wins and the file is
// always complete; on failure the temporary is removed and the old file kept.
// A target that exists and is not a regular file (a device such as
// /dev/stdout or /dev/full, a pipe) is written in place: it cannot be
// replaced, and must not be.
//
// Logs (resumable sweeps' finished points, kept states, table builds):
// AppendFile writes each record straight to the operating system (no
// buffer), so a killed process loses at most the record being written.
#pragma once

#include <functional>
#include <iosfwd>
#include <string>
#include <string_view>

namespace railsim {

// A fresh temporary file name for `path`, unique to this process, thread and call.
std::string temporary_path_for(const std::string& path);

// Write `content` to `path` atomically (binary, exactly these bytes).
void write_file_atomically(const std::string& path, std::string_view content);

// Write through a stream callback to `path` atomically (the content is
// collected in memory, then written as above).
void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write);

// The content of a file railsim wrote itself and reads back (a resume log,
// kept states): empty when it does not exist or is not a regular file (a
// device such as /dev/full given as an output is written, never read: it
// would read forever).
std::string read_own_file(const std::string& path);

// The error of a failed write of `path` (errno value `err`; 0 for none known):
// "PATH: <what> (<strerror>)".
[[noreturn]] void throw_write_error(const std::string& path, const std::string& what, int err);

// An append-only file, written record by record without a buffer.
class AppendFile {
 public:
  enum class Mode { append, truncate };
  AppendFile() = default;
  // Opens (creating it when missing); throws InputError naming the file.
  explicit AppendFile(const std::string& path, Mode mode = Mode::append) { open(path, mode); }
  ~AppendFile();  // closes; call close() to see a failure
  AppendFile(const AppendFile&) = delete;
  AppendFile& operator=(const AppendFile&) = delete;

  void open(const std::string& path, Mode mode = Mode::append);
  // All of `bytes` reach the operating system, or InputError naming the file.
  void write(std::string_view bytes);
  // Closes; InputError naming the file when the system reports a failure.
  void close();
  bool is_open() const { return fd_ >= 0; }
  const std::string& path() const { return path_; }

 private:
  int fd_ = -1;
  std::string path_;
};

}  // namespace railsim
