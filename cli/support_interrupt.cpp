// Ctrl-C and SIGTERM: see support_interrupt.hpp. The handler only stores the
// signal number in a lock-free atomic (async-signal-safe) and restores the
// default action, so a second signal ends the program.
#include "cli/support_interrupt.hpp"

#include <atomic>
#include <csignal>

#include "core/errors.hpp"

namespace railsim::cli {

namespace {

// The program's one signal state (a signal reaches the process, not an object).
std::atomic<int> g_signal{0};
static_assert(std::atomic<int>::is_always_lock_free);

extern "C" void on_stop_signal(int sig) {
  g_signal.store(sig, std::memory_order_relaxed);
  std::signal(sig, SIG_DFL);
}

}  // namespace

StopRequest interrupt_request() {
  // A signal the program was started ignoring stays ignored (a background
  // job of a shell script ignores SIGINT: Ctrl-C at the terminal is not for it).
  static const bool installed = [] {
    for (const int sig : {SIGINT, SIGTERM})
      if (std::signal(sig, on_stop_signal) == SIG_IGN) std::signal(sig, SIG_IGN);
    return true;
  }();
  (void)installed;
  return StopRequest([] { return g_signal.load(std::memory_order_relaxed) != 0; });
}

int interrupt_exit_code() {
  const int sig = g_signal.load(std::memory_order_relaxed);
  return sig != 0 ? 128 + sig : kExitInterrupted;
}

}  // namespace railsim::cli
