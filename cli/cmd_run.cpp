// `railsim run SCENARIO.yaml --out DIR`: run one scenario (engine/scenario.hpp)
// and write DIR/channels.csv (streamed row by row as the run goes: time,
// distance, speed, per wheelset lateral shift and yaw, per wheel Q, Y, Fx,
// creepages, contact position) and DIR/summary.json (max lateral shift,
// integrator statistics, wall time, real-time factor, model choices, validity
// warnings). A numerical failure still writes summary.json (status "failed",
// the message) before exiting with code 3.
#include <spdlog/spdlog.h>

#include <filesystem>

#include "cli/commands.hpp"
#include "core/errors.hpp"
#include "engine/scenario.hpp"
#include "engine/simulation.hpp"
#include "results/csv_writer.hpp"
#include "results/json_writer.hpp"

namespace railsim::cli {

namespace {
struct RunArgs {
  std::string scenario;
  std::string out = "out";
};

int run_scenario(const RunArgs& a) {
  namespace fs = std::filesystem;
  const engine::Scenario sc = engine::load_scenario(a.scenario);
  std::error_code ec;
  fs::create_directories(a.out, ec);
  if (ec) throw InputError("--out " + a.out + ": cannot create the folder (" + ec.message() + ")");
  const auto& m = sc.model;
  spdlog::info("scenario '{}': vehicle '{}', {} states, {} wheelset model, {}", sc.name, m.vehicle_name,
               m.n_states, engine::wheelset_model_name(m.wheelset_model), sc.integrator.method);

  results::CsvWriter csv(a.out + "/channels.csv", engine::channel_names(m), false, 50);
  std::vector<double> row;
  results::Json summary = results::Json::object();
  summary.set("scenario", sc.name);
  summary.set("scenario_file", sc.file);
  summary.set("vehicle", m.vehicle_name);
  results::Json choices = results::Json::object();
  choices.set("wheelset_model", engine::wheelset_model_name(m.wheelset_model));
  choices.set("geometry", sc.geometry_description);
  choices.set("tangential", m.coupling.describe());
  choices.set("track", m.track->describe());
  choices.set("integrator", sc.integrator.method);
  choices.set("rtol", sc.integrator.rtol);
  choices.set("atol", sc.integrator.atol);
  choices.set("max_step", sc.integrator.max_step);
  choices.set("jacobian", sc.integrator.jacobian);
  choices.set("linear_solver", sc.integrator.linear_solver);
  summary.set("model_choices", choices);
  summary.set("speed_initial", m.speed.v0);
  summary.set("duration", sc.duration);
  summary.set("output_interval", sc.output_interval);
  summary.set("states", m.n_states);

  engine::RunSummary rs;
  try {
    rs = engine::simulate(m, sc.integrator, sc.x0, sc.duration, sc.output_interval,
                          [&](double t, const Eigen::VectorXd& x, const engine::Data& d) {
                            engine::channel_row(m, t, x, d, row);
                            csv.row(row);
                          });
  } catch (const NumericalError& e) {
    csv.flush();
    summary.set("status", "failed");
    summary.set("error", e.what());
    summary.write_file(a.out + "/summary.json");
    throw;
  }
  csv.flush();
  summary.set("status", "ok");
  summary.set("integrator", rs.integrator);
  results::Json st = results::Json::object();
  st.set("steps", rs.stats.steps);
  st.set("rhs_calls", rs.stats.rhs_calls);
  st.set("failed_steps", rs.stats.failed_steps);
  st.set("jacobian_evaluations", rs.stats.jacobian_evals);
  st.set("last_step", rs.stats.last_step);
  summary.set("integrator_statistics", st);
  summary.set("wall_time", rs.wall_time);
  summary.set("real_time_factor", rs.real_time_factor);
  summary.set("cpu_time", rs.cpu_time);
  summary.set("real_time_factor_cpu", rs.real_time_factor_cpu);
  results::Json maxy = results::Json::object();
  double overall = 0;
  for (std::size_t w = 0; w < m.wheelsets.size(); ++w) {
    maxy.set(m.wheelsets[w].name, rs.max_abs_lateral[w]);
    overall = std::max(overall, rs.max_abs_lateral[w]);
  }
  summary.set("max_lateral_shift", overall);
  summary.set("max_lateral_shift_per_wheelset", maxy);
  results::Json warn = results::Json::array();
  if (rs.invalid_contact_calls > 0)
    warn.push("contact model used outside its validity domain in " + std::to_string(rs.invalid_contact_calls) +
              " evaluations (first: " + rs.first_invalid_reason + ")");
  if (m.wheelset_model == engine::WheelsetModel::lateral && overall > 0.006)
    warn.push("lateral wheelset model with lateral shifts above 6 mm: flange contact with quasi-static loads");
  summary.set("warnings", warn);
  summary.write_file(a.out + "/summary.json");
  spdlog::info("done: {:.3g} s simulated in {:.3g} s wall ({:.3g}x real time; {:.3g}x on CPU time), {} steps, {} rhs calls, max |y| {:.3g} mm",
               sc.duration, rs.wall_time, rs.real_time_factor, rs.real_time_factor_cpu, rs.stats.steps, rs.stats.rhs_calls, overall * 1e3);
  return kExitSuccess;
}
}  // namespace

void register_run(CLI::App& app, CommandRunner& run) {
  auto args = std::make_shared<RunArgs>();
  auto* cmd = app.add_subcommand("run", "Run a scenario (vehicle, track, speed, contact, integrator) and write channels");
  cmd->add_option("scenario", args->scenario, "Scenario YAML file")->required();
  cmd->add_option("--out", args->out, "Output folder (channels.csv, summary.json)")->capture_default_str();
  cmd->callback([args, &run] { run = [args] { return run_scenario(*args); }; });
}

}  // namespace railsim::cli
