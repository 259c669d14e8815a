// One writer per output folder: a process that writes into DIR holds an
// exclusive advisory lock (flock(2)) on DIR/.railsim.lock for as long as the
// OutputLock lives. A second process asking for the same folder gets an
// InputError naming the folder and the holder's pid (exit 2) instead of
// writing over, or deleting, the first one's partial files. The kernel drops
// the lock when the holder exits, even by kill -9, so a folder is never left
// locked (the empty lock file stays; it is harmless and reused).
// Given the analysis that writes the folder ("run", "critical-speed", ...),
// the lock also records it in DIR/.railsim.analysis and refuses a folder that
// holds another analysis's results (its summary.json, its verdict, would be
// replaced by a different kind of document). A folder without the record
// (from before it, or written by hand) is judged by the analyses' own files
// (channels.csv: run; bifurcation.csv, ramping.csv, reductions.csv:
// critical-speed; modes.csv; comparison.csv; yq_comparison.csv), and a
// summary.json of none of them is refused too.
// A folder the lock created (with any parent it had to create) that holds
// nothing but the markers when the lock is released (a command refused after
// taking it) is removed again.
#pragma once

#include <string>
#include <vector>

namespace railsim {

class OutputLock {
 public:
  // Creates `dir` if needed, then locks it; throws InputError when another
  // process holds the lock or the lock file cannot be created, or when
  // `analysis` is given and the folder holds the results of another one.
  explicit OutputLock(const std::string& dir, const std::string& analysis = "");
  ~OutputLock();
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;

 private:
  int fd_ = -1;
  std::vector<std::string> created_;  // folders this lock created, innermost first
};

}  // namespace railsim
