// Options checks shared by all subcommands; see support_option_checks.hpp.
#include "cli/support_option_checks.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>

#include "core/errors.hpp"

namespace railsim::cli {

namespace {

// CLI11 prefixes a validator's message with the option's name:
// "--v-min: expected a finite number (got 'nan')".
const CLI::Validator kFinite(
    [](std::string& s) -> std::string {
      const char* b = s.c_str();
      char* e = nullptr;
      const double v = std::strtod(b, &e);
      if (e != b && !std::isfinite(v)) return "expected a finite number (got '" + s + "')";
      return {};  // not a number at all: CLI11's own conversion reports it
    },
    "FINITE", "finite");

// A whole-number option: CLI11's own conversion said only "Could not convert"
// for 1.5 or for a value past the type's range (99999999999 for an int).
const CLI::Validator kWholeNumber(
    [](std::string& s) -> std::string {
      const char* b = s.c_str();
      char* e = nullptr;
      errno = 0;
      const long long v = std::strtoll(b, &e, 10);
      if (e == b || *e != '\0') return "expected a whole number (got '" + s + "')";
      if (errno == ERANGE || v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max())
        return "expected a whole number in the option's range, see --help (got " + s + ")";
      return {};
    },
    "WHOLE", "whole number");

const CLI::Validator kNotEmpty(
    [](std::string& s) -> std::string { return s.empty() ? "expected a file or folder name (got '')" : std::string(); },
    "NONEMPTY", "not empty");

void add_checks(CLI::App& cmd) {
  for (CLI::Option* o : cmd.get_options()) {
    const std::string type = o->get_type_name();
    if (type.find("FLOAT") != std::string::npos) o->check(kFinite);
    if ((type.rfind("INT", 0) == 0 || type.rfind("UINT", 0) == 0) && o->get_items_expected_max() == 1)
      o->check(kWholeNumber);
    if (o->check_lname("out") || o->check_sname("o")) o->check(kNotEmpty);
  }
  for (CLI::App* sub : cmd.get_subcommands([](CLI::App*) { return true; })) add_checks(*sub);
}

}  // namespace

void add_common_checks(CLI::App& app) { add_checks(app); }

const CLI::Validator& non_empty_value() {
  static const CLI::Validator v(
      [](std::string& s) -> std::string {
        return s.find_first_not_of(" ,;") == std::string::npos ? "expected a value (got '" + s + "')" : std::string();
      },
      "NONEMPTY", "non-empty value");
  return v;
}

CLI::Validator number_range(double lo, double hi) {
  char range[80];
  std::snprintf(range, sizeof range, "[%.6g, %.6g]", lo, hi);
  const std::string text = range;
  return CLI::Validator(
      [lo, hi, text](std::string& s) -> std::string {
        const char* b = s.c_str();
        char* e = nullptr;
        const double v = std::strtod(b, &e);
        if (e == b || *e != '\0') return "expected a number in " + text + " (got '" + s + "')";
        if (!std::isfinite(v)) return "expected a finite number (got '" + s + "')";
        if (!(v >= lo && v <= hi)) return "expected a number in " + text + " (got " + s + ")";
        return {};
      },
      "NUMBER in " + text, "range");
}

std::string subcommand_names(const CLI::App& app) {
  std::string out;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    out += (out.empty() ? "" : ", ") + sub->get_name();
  return out;
}

std::string unknown_subcommand(const CLI::App& app, int argc, const char* const* argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a.empty()) return "";
    if (a[0] == '-') {
      // A top-level option taking a value (--log-level X): skip the value.
      if (a.find('=') == std::string::npos) {
        const CLI::Option* o = nullptr;
        try {
          o = app.get_option_no_throw(a);
        } catch (...) {
          o = nullptr;
        }
        if (o && o->get_type_size() > 0 && i + 1 < argc) ++i;
      }
      continue;
    }
    try {
      (void)app.get_subcommand(a);
      return "";
    } catch (const CLI::OptionNotFound&) {
      return a;
    }
  }
  return "";
}

const contact::TangentialModelEntry& tangential_model_option(const std::string& option, const std::string& name) {
  try {
    return contact::find_tangential_model(name);
  } catch (const InputError& e) {
    throw InputError(option + ": " + e.what());
  }
}

void check_model_reads_options(const contact::TangentialModelEntry& model, const contact::TangentialModelOptions& o) {
  for (const contact::TangentialOption flag : contact::unused_model_options(model, o)) {
    std::string option = std::string("--") + contact::option_field_name(flag);
    std::replace(option.begin(), option.end(), '_', '-');
    throw InputError(option + ": model '" + model.name + "' does not use it (models that do: " +
                     contact::models_reading(flag) + ")");
  }
}

void check_out_is_not_input(const std::string& out, const std::string& input) {
  namespace fs = std::filesystem;
  std::error_code e1, e2;
  const fs::path a = fs::weakly_canonical(out, e1), b = fs::weakly_canonical(input, e2);
  if (!e1 && !e2 && a == b)
    throw InputError("--out: " + out + " is the input file " + input +
                     " itself; writing the results would overwrite it: give another result file");
}

void check_out_against_inputs(const std::string& out, const std::vector<std::string>& inputs) {
  std::error_code ec;
  if (out.empty()) return;
  for (const std::string& input : inputs)
    if (!input.empty() && std::filesystem::is_regular_file(input, ec)) check_out_is_not_input(out, input);
}

}  // namespace railsim::cli
