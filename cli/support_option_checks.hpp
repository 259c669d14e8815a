// Checks shared by every subcommand's options, applied once in main():
// a numeric option (CLI11 type FLOAT) must be a finite number ("nan", "inf"
// refused naming the option: CLI::Range lets NaN through); a whole-number
// option (type INT) must be one that fits (1.5 and 99999999999 named, not
// CLI11's "Could not convert"); an output option
// (--out, -o) must not be empty; an unknown subcommand is named in the error.
#pragma once

#include <CLI/CLI.hpp>
#include <vector>
#include <string>

#include "contact/registry.hpp"

namespace railsim::cli {

// Add the finite-number and non-empty-output checks to every option of
// every subcommand of `app` (call after all subcommands are registered).
void add_common_checks(CLI::App& app);

// The first command-line word that should name a subcommand but names none
// ("" when there is none), skipping the values of the top-level options.
std::string unknown_subcommand(const CLI::App& app, int argc, const char* const* argv);

// A number in [lo, hi], the bounds printed as given ("--reference-tolerance:
// expected a number in [1e-12, 0.001] (got 0)"); CLI::Range prints them with
// six decimals, so a bound of 1e-12 reads as 0.000000.
CLI::Validator number_range(double lo, double hi);

// A value that is not empty ("--models: expected a value (got '')"): an
// empty list or name would otherwise be read as "not given".
const CLI::Validator& non_empty_value();

// The registry entry of the tangential model `name` given by `option` (no
// model is built: mim_table's table is not loaded); an unknown name is an
// InputError "OPTION: unknown contact model 'x' (known models: ...)".
const contact::TangentialModelEntry& tangential_model_option(const std::string& option, const std::string& name);

// InputError "--grid: model 'chopaya' does not use it (models that do: ...)"
// for each option given to a one-model command that the model does not read
// (contact::unused_model_options), instead of ignoring it silently.
void check_model_reads_options(const contact::TangentialModelEntry& model, const contact::TangentialModelOptions& o);

// InputError "--out: FILE is the input file itself (...)" when the result
// file `out` and the input file `input` are the same file (it would be
// overwritten before or while it is read).
void check_out_is_not_input(const std::string& out, const std::string& input);
// The same for every input that names an existing file (profiles, tables,
// track files: `railsim geometry --wheel w.csv --out w.csv` overwrote the
// wheel profile); a shipped name (S1002) or an empty option is no file.
void check_out_against_inputs(const std::string& out, const std::vector<std::string>& inputs);

// "run, critical-speed, ..." in registration order.
std::string subcommand_names(const CLI::App& app);

}  // namespace railsim::cli
