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

namespace {

// A folder without the record (written before it existed, or by hand): the
// analysis whose own file is there ("?" for a summary.json of none of them),
// "" for a folder without results. `evidence` names the file.
std::string analysis_of_files(const std::string& dir, std::string& evidence) {
  static const std::pair<const char*, const char*> kOwnFiles[] = {
      {"run", "channels.csv"},
      {"critical-speed", "bifurcation.csv.settings"},
      {"critical-speed", "bifurcation.csv"},
      {"critical-speed", "ramping.csv"},
      {"critical-speed", "reductions.csv"},
      {"critical-speed", "compare_models.csv"},
      {"modes", "modes.csv"},
      {"compare-contact", "comparison.csv"},
      {"compare-yq", "yq_comparison.csv"},
  };
  // Regular files only: a link or a device in their place is the user's.
  const auto is_file = [](const std::string& p) {
    std::error_code ec;
    return std::filesystem::is_regular_file(std::filesystem::symlink_status(p, ec));
  };
  for (const auto& [name, file] : kOwnFiles)
    if (is_file(dir + "/" + file)) {
      evidence = dir + "/" + file;
      return name;
    }
  if (is_file(dir + "/summary.json")) {
    evidence = dir + "/summary.json";
    return "?";
  }
  return "";
}

// The folder's record of whose results it holds (DIR/.railsim.analysis, or
// the analyses' own files when unrecorded): InputError when they are another
// analysis's; records `analysis` when there is no record yet.
void claim_for_analysis(const std::string& dir, const std::string& analysis) {
  const std::string marker = dir + "/.railsim.analysis";
  std::string before, evidence = marker;
  if (std::ifstream in(marker); in) std::getline(in, before);
  const bool recorded = !before.empty();
  if (!recorded) before = analysis_of_files(dir, evidence);
  if (!before.empty() && before != analysis) {
    const std::string holds = before == "?" ? "holds a summary.json that no railsim analysis wrote ("
                                            : "holds the results of `railsim " + before + "` (";
    throw InputError(dir + ": " + holds + evidence + "); `railsim " + analysis +
                     "` would replace its summary.json: give another output folder, or remove this one first");
  }
  if (recorded) return;
  std::ofstream out(marker, std::ios::trunc);
  out << analysis << "\n";
  if (!out.flush()) throw InputError(marker + ": cannot write (" + std::strerror(errno) + ")");
}

}  // namespace

OutputLock::OutputLock(const std::string& dir, const std::string& analysis) {
  std::error_code ec;
  // The folders this lock creates (the output folder and any missing parent),
  // innermost first: removed again if the command leaves nothing in them.
  for (std::filesystem::path p = std::filesystem::absolute(dir, ec); !ec && !p.empty() && !std::filesystem::exists(p, ec);
       p = p.parent_path()) {
    created_.push_back(p.string());
    if (p == p.parent_path()) break;
  }
  ec.clear();
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
  try {
    claim_for_analysis(dir, analysis);
  } catch (...) {
    ::close(fd_);  // refused: the folder is not left locked
    fd_ = -1;
    throw;
  }
}

OutputLock::~OutputLock() {
  // A folder this lock created and the command left without results (bad
  // input found after the lock, say) is removed with its markers, so that a
  // refused command leaves no trace. Everything else stays as it is.
  if (fd_ >= 0 && !created_.empty()) {
    std::error_code ec;
    bool only_markers = true;
    // (increment(ec), not ++: a destructor must not throw)
    for (std::filesystem::directory_iterator it(created_.front(), ec), end; !ec && it != end; it.increment(ec)) {
      const std::string name = it->path().filename().string();
      if (name != ".railsim.lock" && name != ".railsim.analysis") only_markers = false;
    }
    if (!ec && only_markers) {
      std::filesystem::remove(created_.front() + "/.railsim.analysis", ec);
      std::filesystem::remove(created_.front() + "/.railsim.lock", ec);
      for (const auto& d : created_)
        if (!std::filesystem::remove(d, ec)) break;  // (remove() refuses a folder that is not empty)
    }
  }
  if (fd_ >= 0) ::close(fd_);  // closing releases the lock
}

}  // namespace railsim
