// `railsim run SCENARIO.yaml --out DIR [--speed-kmh V] [--set key=value ...]`:
// run one scenario, varied by command-line overrides
// (support_scenario_overrides.hpp), and write DIR/channels.csv,
// DIR/summary.json, DIR/yq.png and DIR/sum_y_rms.png
// (engine/analysis/scenario_run.hpp says what they hold). A numerical failure
// still writes summary.json (status "failed", the message, no running-safety
// verdict) before exiting with code 3; a derailment is a result (status
// "derailed", running safety failed), exit 0; bad input (including a bad
// --set) exits 2 naming the option.
#include <algorithm>
#include <cmath>
#include <thread>

#include "cli/commands.hpp"
#include "cli/support_interrupt.hpp"
#include "cli/support_option_checks.hpp"
#include "cli/support_scenario_overrides.hpp"
#include "core/errors.hpp"
#include "core/output_lock.hpp"
#include "engine/analysis/scenario_run.hpp"
#include "engine/io/scenario.hpp"

namespace railsim::cli {

namespace {

struct RunArgs {
  std::string scenario;
  std::string out = "out";
  double speed_kmh = -1.0;  // not given
  std::vector<std::string> sets;
  int contact_audit = 0;          // states to audit (when audit_given)
  bool audit_given = false;
  std::vector<std::string> audit_settings_given;  // --audit-tolerance, --audit-threads given
  double audit_tolerance = 2.0;   // [% of mu N]
  int audit_threads = 0;          // 0: the machine's cores
};

int run_scenario(const RunArgs& a) {
  // The audit's settings without the audit were ignored silently.
  if (!a.audit_given && !a.audit_settings_given.empty())
    throw InputError(a.audit_settings_given.front() + ": applies to the contact audit; give --contact-audit N as well");
  if (a.audit_given && (a.contact_audit < engine::kMinAuditSamples || a.contact_audit > engine::kMaxAuditSamples))
    throw InputError("--contact-audit " + std::to_string(a.contact_audit) + ": the number of contact states must "
                     "lie in [1, " + std::to_string(engine::kMaxAuditSamples) + "]");
  if (!(std::isfinite(a.audit_tolerance) && a.audit_tolerance > 0.0 && a.audit_tolerance <= 100.0))
    throw InputError("--audit-tolerance: must be a finite per cent of mu N in (0, 100]");
  if (a.audit_threads < 0 || a.audit_threads > 64) throw InputError("--audit-threads: must lie in [0, 64]");
  std::vector<ScenarioOverride> overrides;
  for (const auto& s : a.sets) overrides.push_back(parse_set_option(s));
  if (a.speed_kmh > 0.0) overrides.push_back(speed_kmh_override(a.speed_kmh));
  const OutputLock lock(a.out, "run");  // one writer per output folder
  const LoadedScenario loaded = load_scenario_with_overrides(a.scenario, overrides);
  engine::ScenarioRunOptions o;
  o.out_dir = a.out;
  o.stop = interrupt_request();  // Ctrl-C: channels.csv up to then, summary.json "interrupted"
  for (const auto& ov : overrides) o.overrides.push_back(ov.option);
  o.contact_audit.samples = a.audit_given ? a.contact_audit : 0;
  o.contact_audit.tolerance = a.audit_tolerance / 100.0;
  o.contact_audit.threads =
      a.audit_threads > 0 ? a.audit_threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  try {
    engine::run_scenario(loaded.scenario, o);
  } catch (const InputError& e) {
    rethrow_for_overrides(e, overrides);  // e.g. a bad running_safety value given by --set
  }
  return kExitSuccess;
}

}  // namespace

void register_run(CLI::App& app, CommandRunner& run) {
  auto args = std::make_shared<RunArgs>();
  auto* cmd = app.add_subcommand("run", "Run a scenario (vehicle, track, speed, contact, integrator) and write channels");
  cmd->add_option("scenario", args->scenario, "Scenario YAML file")->required();
  cmd->add_option("--out", args->out, "Output folder (channels.csv, summary.json, yq.png, sum_y_rms.png)")
      ->capture_default_str();
  cmd->add_option("--speed-kmh", args->speed_kmh, "Speed [km/h] instead of the scenario's (0 < V <= 720)")
      ->check(number_range(0.001, 720.0));
  cmd->add_option("--set", args->sets,
                  "Override a scenario key: key=value, dotted path (contact.material.mu=0.2, "
                  "track.segments[2].radius=500, initial[ws1.lateral]=0.007); repeatable");
  auto* audit = cmd->add_option("--contact-audit", args->contact_audit,
                  "Audit N of the run's own contact states (1..10000; the extremes and the rest evenly in time) "
                  "with MIM (grid 60) and every registered model: contact_audit.csv, contact_audit.png, summary.json")
      ->check(number_range(engine::kMinAuditSamples, engine::kMaxAuditSamples));
  auto* tolerance = cmd->add_option("--audit-tolerance", args->audit_tolerance,
                  "Contact audit: error a model may reach, per cent of mu N (0 < PCT <= 100)")
      ->capture_default_str();
  auto* threads = cmd->add_option("--audit-threads", args->audit_threads,
                                  "Contact audit: worker threads (0: all cores, at most 64)")
                      ->check(number_range(0, 64))
                      ->capture_default_str();
  cmd->callback([args, &run, audit, tolerance, threads] {
    args->audit_given = audit->count() > 0;
    args->audit_settings_given.clear();
    for (const CLI::Option* opt : {tolerance, threads})
      if (opt->count() > 0) args->audit_settings_given.push_back(opt->get_name());
    run = [args] { return run_scenario(*args); };
  });
}

}  // namespace railsim::cli
