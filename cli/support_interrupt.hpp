// Ctrl-C and SIGTERM for the program: the first signal asks the running
// command to stop (core/stop_request.hpp: runs and sweeps poll it between
// output points, write and close what they finished and throw
// InterruptedError; main() prints where it stopped and exits 130 or 143);
// a second signal ends the program at once (the default action).
#pragma once

#include "core/stop_request.hpp"

namespace railsim::cli {

// Installs the handlers for SIGINT and SIGTERM (once, from main()).
void install_interrupt_handlers();

// A stop request set by the first SIGINT or SIGTERM.
StopRequest interrupt_request();

// The exit code for the signal received: 130 (SIGINT), 143 (SIGTERM).
int interrupt_exit_code();

}  // namespace railsim::cli
