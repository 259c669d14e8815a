// One run of a scenario with its report: the time simulation
// (engine/simulation.hpp), the channels (engine::channel_names: time,
// distance, speed, per wheelset lateral shift and yaw, per wheel Q, Y, Fx,
// creepages, contact position, Y/Q, wear number T-gamma), and the summary
// document (summary.json: max lateral shift, integrator statistics, wall time,
// real-time factor, model choices, validity warnings, `running_safety`: Nadal
// and EN 14363 evaluation of the run, run_safety.hpp; `curving`: quasi-static
// curving results per circular curve, curving.hpp). What `railsim run` and the
// Python module's railsim.run() call.
//
// With an output folder: DIR/channels.csv (streamed row by row as the run
// goes), DIR/summary.json and DIR/yq.png (Y/Q of the leading wheelset's wheels
// against distance with the Nadal and (Y/Q)_2m limits). A numerical failure
// still writes summary.json (status "failed", the message; the running safety
// up to the failure) and then throws the NumericalError on.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "engine/scenario.hpp"
#include "engine/simulation.hpp"
#include "results/json_writer.hpp"

namespace railsim::engine {

struct ScenarioRunOptions {
  std::string out_dir;         // empty: no files
  bool keep_channels = false;  // keep every channel row in memory (ScenarioRunResult::channels)
};

struct ScenarioRunResult {
  std::vector<std::string> channel_names;
  std::vector<double> channels;  // rows x channel_names.size(), row-major (keep_channels)
  std::size_t rows = 0;
  results::Json summary;         // the document of summary.json
  RunSummary run;
};

ScenarioRunResult run_scenario(const Scenario& scenario, const ScenarioRunOptions& options);

}  // namespace railsim::engine
