// railsim: command-line front end. Parses arguments (CLI11), sets up logging
// (spdlog, to stderr), runs one subcommand and maps failures to exit codes:
// 0 success, 2 bad input or a failed write (also of standard output), 3
// numerical failure. `railsim --version` prints
// "railsim X.Y.Z" (as help2man expects); `railsim version` says more.
// Every numeric option is refused unless finite (cli/support_option_checks.hpp).
// SIGXFSZ is ignored, so a file past the size limit is a failed write (exit 2).
// SIGINT / SIGTERM stop `run` and `critical-speed` between output points,
// keeping what they finished (cli/support_interrupt.hpp): exit 130 / 143.
// Under mpirun, MPI is started here for the whole run (engine::MpiSession).
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <string>

#include "cli/commands.hpp"
#include "cli/support_interrupt.hpp"
#include "cli/support_option_checks.hpp"
#include "core/errors.hpp"
#include "core/version.hpp"
#include "engine/analysis/sweep_runner.hpp"

int main(int argc, char** argv) {
  // MPI, when launched by mpirun, for the whole run (finalised when main returns).
  const railsim::engine::MpiSession mpi(&argc, &argv);
  // A file that outgrows the process's size limit (ulimit -f) is a failed
  // write, reported by the writer with its file name (exit 2), not a kill by SIGXFSZ.
  std::signal(SIGXFSZ, SIG_IGN);
  CLI::App app{"railsim: railway vehicle dynamics with pluggable wheel-rail contact"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("railsim ") + railsim::kVersion, "Print the version and exit");
  std::string log_level = "info";
  app.add_option("--log-level", log_level, "Logging level: trace, debug, info, warn, error, off")
      ->check(CLI::IsMember({"trace", "debug", "info", "warn", "error", "critical", "off"}))
      ->capture_default_str();

  railsim::cli::CommandRunner run;
  railsim::cli::register_version(app, run);
  railsim::cli::register_run(app, run);
  railsim::cli::register_critical_speed(app, run);
  railsim::cli::register_modes(app, run);
  railsim::cli::register_contact(app, run);
  railsim::cli::register_compare_contact(app, run);
  railsim::cli::register_demo(app, run);
  railsim::cli::register_geometry(app, run);
  railsim::cli::register_conicity(app, run);
  railsim::cli::register_track(app, run);
  railsim::cli::register_wheelset_contact(app, run);
  railsim::cli::register_compare_yq(app, run);

  railsim::cli::add_common_checks(app);
  if (const std::string bad = railsim::cli::unknown_subcommand(app, argc, argv); !bad.empty()) {
    std::cerr << "railsim: unknown subcommand '" << bad << "' (known: " << railsim::cli::subcommand_names(app)
              << "; see railsim --help)\n";
    return railsim::kExitBadInput;
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (dynamic_cast<const CLI::RequiredError*>(&e) != nullptr && app.get_subcommands().empty()) {
      std::cerr << "railsim: no subcommand given (one of: " << railsim::cli::subcommand_names(app)
                << "; see railsim --help)\n";
      return railsim::kExitBadInput;
    }
    const int code = app.exit(e);
    // --help and --version are successes (if they reached standard output);
    // everything else is bad input.
    if (code != 0) return railsim::kExitBadInput;
    std::cout.flush();
    if (std::fflush(stdout) != 0 || std::ferror(stdout) || !std::cout) {
      std::cerr << "railsim: standard output: write failed (" << std::strerror(errno) << ")\n";
      return railsim::kExitBadInput;
    }
    return railsim::kExitSuccess;
  }

  // The message that ends a run reaches stderr at any --log-level (off and
  // critical hid it: exit 2 or 3 without a word).
  const auto fatal = [](spdlog::level::level_enum level, const std::string& msg) {
    if (spdlog::default_logger_raw()->should_log(level)) spdlog::log(level, "{}", msg);
    else std::fprintf(stderr, "railsim: %s\n", msg.c_str());
  };
  auto logger = spdlog::stderr_color_mt("railsim");
  spdlog::set_default_logger(logger);
  spdlog::set_level(spdlog::level::from_str(log_level));
  spdlog::set_pattern("[%H:%M:%S.%e] [%^%l%$] %v");

  try {
    const int code = run ? run() : railsim::kExitSuccess;
    // Printed results count as output: a full disk behind
    // standard output is a failed write (exit 2), not a success.
    std::cout.flush();
    if (std::fflush(stdout) != 0 || std::ferror(stdout) || !std::cout)
      throw railsim::InputError(std::string("standard output: write failed (") + std::strerror(errno) + ")");
    return code;
  } catch (const railsim::InputError& e) {
    fatal(spdlog::level::err, e.what());
    return railsim::kExitBadInput;
  } catch (const railsim::InterruptedError& e) {
    fatal(spdlog::level::warn, std::string(e.what()) + " (stopped by a signal)");
    return railsim::cli::interrupt_exit_code();
  } catch (const railsim::NumericalError& e) {
    fatal(spdlog::level::err, std::string("numerical failure: ") + e.what());
    return railsim::kExitNumericalFailure;
  } catch (const std::exception& e) {
    fatal(spdlog::level::critical, std::string("internal error: ") + e.what());
    return 1;
  }
}
