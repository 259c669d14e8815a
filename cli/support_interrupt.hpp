// Ctrl-C and SIGTERM for the commands that can stop cleanly (run,
// critical-speed): once such a command asks for the stop request, the first
// signal asks it to stop (core/stop_request.hpp: runs and sweeps poll it
// between output points, write and close what they finished and throw
// InterruptedError; main() prints where it stopped and exits 130 or 143);
// a second signal ends the program at once (the default action). Commands
// that do not poll keep the default: Ctrl-C ends them at once.
#pragma once

#include "core/stop_request.hpp"

namespace railsim::cli {

// A stop request set by the first SIGINT or SIGTERM; installs the handlers
// (a signal the program was started ignoring stays ignored).
StopRequest interrupt_request();

// The exit code for the signal received: 130 (SIGINT), 143 (SIGTERM).
int interrupt_exit_code();

}  // namespace railsim::cli
