// `railsim contact CASES.yaml --model NAME --out results.csv [--reduction R]
// [--grid N] [--tolerance T] [--extrapolation none|richardson] [--no-timing]`:
// runs one tangential contact model on every case of a case file (format in
// support_contact_cases.hpp) and writes one CSV row per case with the patch,
// the forces, the validity flag (and why) and the measured cost per call
// (--no-timing: each case solved once, time_ns written as 0; for long
// reference runs such as tests/data/contact/spin_reference/).
#include <spdlog/spdlog.h>

#include <string>

#include "cli/commands.hpp"
#include "cli/support_option_checks.hpp"
#include "cli/support_contact_cases.hpp"
#include "contact/reduction.hpp"
#include "contact/registry.hpp"
#include "core/errors.hpp"

namespace railsim::cli {

namespace {

struct ContactOptions {
  std::string cases;
  std::string model;
  std::string out;
  std::string reduction;
  int grid = 0;
  double tolerance = 0.0;
  std::string extrapolation;
  std::string cache_dir;
  bool no_timing = false;
};

int run_contact(const ContactOptions& o) {
  const contact::TangentialModelEntry& entry = tangential_model_option("--model", o.model);
  const char* spin = entry.spin;
  // Inputs first: a cached-table model may take a while to build on first use.
  check_out_is_not_input(o.out, o.cases);
  ContactCaseSet set = load_contact_cases(o.cases);
  if (!o.reduction.empty()) set_reduction(set, contact::parse_reduction(o.reduction, "--reduction"));
  contact::TangentialModelOptions mo;
  mo.grid = o.grid;
  mo.tolerance = o.tolerance;
  if (!o.extrapolation.empty()) mo.extrapolation = contact::grid_extrapolation_from_name(o.extrapolation, "--extrapolation");
  mo.cache_dir = o.cache_dir;
  check_model_reads_options(entry, mo);
  const auto model = contact::make_tangential_model(o.model, mo);
  const auto ws = model->make_workspace();
  // 17 significant digits: the file holds the doubles exactly (round trip).
  results::CsvWriter csv(o.out, contact_csv_columns(), false, 1, 17);
  int invalid = 0;
  for (const auto& c : set.cases) {
    TimedForces r;
    if (o.no_timing)
      r.forces = model->solve(c.input, ws.get());
    else
      r = solve_timed(*model, c.input, ws.get());
    if (!r.forces.valid) {
      ++invalid;
      spdlog::warn("case '{}': {} outside its validity domain: {}", c.id, o.model, r.forces.reason);
    }
    write_contact_row(csv, c, model->name(), r);
  }
  spdlog::info("{} cases with model {} (reduction {}): {} flagged invalid; results in {}", set.cases.size(),
               o.model, contact::describe_reduction(set.reduction), invalid, o.out);
  spdlog::info("{} and spin: {}", o.model, spin);
  return 0;
}

}  // namespace

void register_contact(CLI::App& app, CommandRunner& run) {
  auto opts = std::make_shared<ContactOptions>();
  auto* cmd = app.add_subcommand("contact", "Run a tangential contact model on a file of contact cases");
  cmd->add_option("cases", opts->cases, "Case file (YAML: material, optional reduction, cases)")->required();
  cmd->add_option("--model", opts->model, "Tangential model: " + contact::tangential_model_names())->required();
  cmd->add_option("--out", opts->out, "Result CSV file")->required();
  cmd->add_option("--reduction", opts->reduction,
                  "Reduction of Kalker's coefficients (overrides the file): none, elastic_fe, "
                  "elastoplastic_fe, third_body, one number k, or k11,k22,k23");
  cmd->add_option("--grid", opts->grid, "Discretisation of grid-based models (0 = model default; each model "
                  "checks its own range, MIM also its memory)")
      ->check(CLI::Range(0, 4000));
  cmd->add_option("--tolerance", opts->tolerance, "Solver tolerance of iterative models (0 = model default)")
      ->check(number_range(0.0, 0.1));
  cmd->add_option("--extrapolation", opts->extrapolation,
                  "Grid extrapolation of model mim: richardson (default; from grid N and N/2) or none (the grid's "
                  "own forces, CONTACT's discretisation)")
      ->check(CLI::IsMember({"none", "richardson"}));
  cmd->add_option("--cache-dir", opts->cache_dir,
                  "Table cache folder of cached-table models (mim_table; default $RAILSIM_CACHE_DIR, "
                  "$XDG_CACHE_HOME/railsim or ~/.cache/railsim)");
  cmd->add_flag("--no-timing", opts->no_timing,
                "Solve each case once and write time_ns = 0 (no repeated calls to measure the cost)");
  cmd->callback([&run, opts] { run = [opts] { return run_contact(*opts); }; });
}

}  // namespace railsim::cli
