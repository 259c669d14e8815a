// Running programs from the CLI tests: a shell command line to its end (its
// output and exit code), and the railsim program in the background (for tests
// that kill it, or run a second one beside it): its pid, output, exit status.
#pragma once

#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>

#include "test_support.hpp"

namespace railsim::test {

// Run a shell command line (which starts the program itself); its output and exit code.
inline RunResult run_shell(const std::string& cmd) {
  RunResult r;
  if (FILE* p = popen(cmd.c_str(), "r")) {
    char buf[4096];
    for (std::size_t n; (n = fread(buf, 1, sizeof buf, p)) > 0;) r.output.append(buf, n);
    const int status = pclose(p);
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  return r;
}

// Wait until `done()` holds, polling every 10 ms for at most `seconds`; whether it held.
inline bool wait_until(const std::function<bool()>& done, double seconds) {
  for (int i = 0; i < static_cast<int>(seconds * 100); ++i) {
    if (done()) return true;
    usleep(10000);
  }
  return done();
}

// `railsim <args>` in the background: `pid` is the program's own (the one a
// lock message names); its output goes to `tag`.log and, once it has ended
// (also by a signal), its exit status to `tag`.rc.
struct BackgroundRun {
  pid_t pid = -1;
  std::string tag;
  bool ended() const { return !read_text(tag + ".rc").empty(); }
  // The exit status (128 + N after signal N), or -1 if it is still running after `seconds`.
  int wait(double seconds) const {
    if (!wait_until([this] { return ended(); }, seconds)) return -1;
    return std::atoi(read_text(tag + ".rc").c_str());
  }
  std::string output() const { return read_text(tag + ".log"); }
};

inline BackgroundRun start_railsim(const std::string& args, const std::string& tag) {
  BackgroundRun b;
  b.tag = tag;
  const std::string q = "'" + tag;
  const std::string cmd = "( \"" + std::string(RAILSIM_BINARY) + "\" " + args + " > " + q + ".log' 2>&1 & echo $! > " +
                          q + ".pid.tmp'; mv " + q + ".pid.tmp' " + q + ".pid'; wait $!; echo $? > " + q +
                          ".rc.tmp'; mv " + q + ".rc.tmp' " + q + ".rc' ) > /dev/null 2>&1 &";
  if (std::system(cmd.c_str()) != 0) return b;
  if (wait_until([&] { return !read_text(tag + ".pid").empty(); }, 10.0))
    b.pid = static_cast<pid_t>(std::atol(read_text(tag + ".pid").c_str()));
  return b;
}

}  // namespace railsim::test
