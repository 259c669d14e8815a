// One run of a scenario with its report: the time simulation
// (engine/simulation.hpp), the channels (engine::channel_names: time,
// distance, speed, per wheelset lateral shift (absolute) and yaw, per wheel Q,
// Y, Fx, creepages, contact position, Y/Q, wear number T-gamma; then
// RunHistory::channel_names: per wheelset the shift relative to the rails
// <ws>.y_rel, per measuring point <body>.ay@<where> and .az@<where>,
// run_history.hpp), and the summary document (summary.json: max lateral
// shift relative to the rails and absolute, integrator statistics, wall time,
// real-time factor, model choices, the overrides, validity warnings,
// `running_safety`: the EN 14363 evaluation of the run (run_safety.hpp) with
// every quantity's processing, limit, margin, where, when and zone, per track
// zone (track_zones.hpp), and Nadal; `curving`: quasi-static curving results
// per circular curve, curving.hpp; `post_processing`: the evaluation's own
// wall and CPU time and its share of the run's). The scenario's
// `running_safety:` section sets the evaluation (safety_settings.hpp). What
// `railsim run` and the Python module's railsim.run() call.
//
// With an output folder: DIR/channels.csv (streamed row by row as the run
// goes), DIR/summary.json, DIR/yq.png ((Y/Q)_2m of both wheels of the worst
// wheelset, the envelope of all wheelsets, the limits; curves, transitions and
// defects shaded) and DIR/sum_y_rms.png (the instability rms of every
// wheelset with its limit). A numerical failure still writes summary.json
// (status "failed", the message, no running-safety verdict: numerics are not
// physics) and then throws the NumericalError on. A derailment
// (DerailmentError: a wheelset past its flange) is a result: status
// "derailed", the running safety up to it, failed, and `derailed` set.
//
// With ScenarioRunOptions::contact_audit.samples > 0 (`railsim run
// --contact-audit N`): the contact audit of the run (run_contact_audit.hpp) on
// N of its own contact states, after a complete run or up to a derailment:
// summary.json `contact_audit`, DIR/contact_audit.csv and DIR/contact_audit.png.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "engine/analysis/run_contact_audit.hpp"
#include "engine/io/scenario.hpp"
#include "engine/simulation.hpp"
#include "results/json_writer.hpp"

namespace railsim::engine {

struct ScenarioRunOptions {
  std::string out_dir;         // empty: no files
  bool keep_channels = false;  // keep every channel row in memory (ScenarioRunResult::channels)
  std::vector<std::string> overrides;  // how the scenario was varied (e.g. "--set contact.material.mu=0.2"), recorded
  RunContactAuditOptions contact_audit;  // samples = 0 (the default): no contact audit
  StopRequest stop;  // polled between output points: InterruptedError after writing what was run
};

struct ScenarioRunResult {
  std::vector<std::string> channel_names;
  std::vector<double> channels;  // rows x channel_names.size(), row-major (keep_channels)
  std::size_t rows = 0;
  results::Json summary;         // the document of summary.json
  RunSummary run;
  bool derailed = false;         // the run ended in a derailment (physics)
  std::string derailment;        // its message
  bool audited = false;          // the contact audit ran (options.contact_audit.samples > 0)
  RunContactAudit contact_audit;
};

// Throws InputError for a bad running_safety section or contact-audit options
// (before running) or an output folder that cannot be made, NumericalError
// when the run fails, InterruptedError when `stop` was requested (channels.csv
// then holds every row up to that time and summary.json says "interrupted",
// with no running-safety verdict).
ScenarioRunResult run_scenario(const Scenario& scenario, const ScenarioRunOptions& options);

}  // namespace railsim::engine
