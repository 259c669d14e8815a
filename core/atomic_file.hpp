// Writing a file so that readers never see it half written: the content goes
// to a temporary file beside the target, "<path>.tmp.<pid>.<thread>.<n>" (n a
// per-process counter: every call gets a fresh name), which
// is then renamed over the target (rename(2) replaces it atomically on one
// file system). Two processes or threads writing the same file each use their
// own temporary; the last rename wins and the file is always complete.
//
// Failures throw railsim::InputError naming the file; the temporary is removed.
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

// Write through a stream callback to `path` atomically.
void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write);

}  // namespace railsim
