// `railsim run SCENARIO.yaml --out DIR`: run one scenario and write
// DIR/channels.csv, DIR/summary.json and DIR/yq.png
// (engine/analysis/scenario_run.hpp says what they hold). A numerical failure
// still writes summary.json (status "failed", the message) before exiting
// with code 3.
#include "cli/commands.hpp"
#include "core/errors.hpp"
#include "engine/analysis/scenario_run.hpp"
#include "engine/scenario.hpp"

namespace railsim::cli {

namespace {

struct RunArgs {
  std::string scenario;
  std::string out = "out";
};

int run_scenario(const RunArgs& a) {
  const engine::Scenario sc = engine::load_scenario(a.scenario);
  engine::ScenarioRunOptions o;
  o.out_dir = a.out;
  engine::run_scenario(sc, o);
  return kExitSuccess;
}

}  // namespace

void register_run(CLI::App& app, CommandRunner& run) {
  auto args = std::make_shared<RunArgs>();
  auto* cmd = app.add_subcommand("run", "Run a scenario (vehicle, track, speed, contact, integrator) and write channels");
  cmd->add_option("scenario", args->scenario, "Scenario YAML file")->required();
  cmd->add_option("--out", args->out, "Output folder (channels.csv, summary.json, yq.png)")->capture_default_str();
  cmd->callback([args, &run] { run = [args] { return run_scenario(*args); }; });
}

}  // namespace railsim::cli
