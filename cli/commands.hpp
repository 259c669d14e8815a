// Subcommands of the railsim program. Each command lives in its own file
// (cmd_<name>.cpp) and registers itself on the CLI11 application; the command
// parses its options, calls the libraries and reports. Errors are thrown as
// railsim::InputError (exit 2) or railsim::NumericalError (exit 3) and mapped to
// exit codes in main.cpp.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>
#include <string>

namespace railsim::cli {

// A registered command: after parsing, main() calls `run` for the chosen one.
using CommandRunner = std::function<int()>;

void register_version(CLI::App& app, CommandRunner& run);
void register_run(CLI::App& app, CommandRunner& run);
void register_critical_speed(CLI::App& app, CommandRunner& run);
void register_modes(CLI::App& app, CommandRunner& run);
void register_contact(CLI::App& app, CommandRunner& run);
void register_compare_contact(CLI::App& app, CommandRunner& run);
void register_demo(CLI::App& app, CommandRunner& run);
void register_geometry(CLI::App& app, CommandRunner& run);
void register_conicity(CLI::App& app, CommandRunner& run);
void register_track(CLI::App& app, CommandRunner& run);
void register_wheelset_contact(CLI::App& app, CommandRunner& run);
void register_compare_yq(CLI::App& app, CommandRunner& run);

}  // namespace railsim::cli
