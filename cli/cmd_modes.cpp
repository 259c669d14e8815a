// `railsim modes SCENARIO.yaml --out DIR [--v-min 20 --v-max 400 --v-step 10] [--count 6]`:
// linear stability of the scenario's vehicle versus speed (engine/linearisation.hpp):
// the eigenvalues of the linearised equations about centred running on
// perfect track at each speed, s = sigma + i omega, frequency f = omega/2pi and
// damping ratio zeta = -sigma/|s|. Writes DIR/modes.csv (speed, rank of the
// mode by decreasing real part, f, zeta, sigma, omega for the `count` least
// damped oscillatory modes), DIR/modes.png (zeta against speed; the
// linear critical speed is where the least damped mode reaches zeta = 0),
// DIR/modes_frequency.png and
// prints the linear critical speed. Modes are ranked per speed, not tracked
// across speeds: where two modes cross, their ranks swap.
#include <spdlog/spdlog.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "cli/commands.hpp"
#include "engine/analysis/sweep_limits.hpp"
#include "core/errors.hpp"
#include "core/output_lock.hpp"
#include "engine/analysis/mode_sweep.hpp"
#include "engine/linearisation.hpp"
#include "engine/io/scenario.hpp"
#include "results/chart.hpp"
#include "results/csv_writer.hpp"
#include "results/json_writer.hpp"

namespace railsim::cli {

namespace {

struct ModesArgs {
  std::string scenario;
  std::string out = "modes";
  double v_min_kmh = 20, v_max_kmh = 400, v_step_kmh = 10;
  int count = 6;
};

int run_modes(const ModesArgs& a) {
  const int n = engine::check_speed_range(a.v_min_kmh, a.v_max_kmh, a.v_step_kmh);
  const OutputLock lock(a.out, "modes");  // one writer per output folder
  const engine::Scenario sc = engine::load_scenario(a.scenario);
  std::error_code ec;
  std::filesystem::create_directories(a.out, ec);
  if (ec) throw InputError("--out " + a.out + ": cannot create the folder (" + ec.message() + ")");

  results::CsvWriter csv(a.out + "/modes.csv",
                         {"speed_kmh", "rank", "frequency_hz", "damping_ratio", "real_1_s", "imag_rad_s"});
  results::Chart chart;
  chart.title = "Modes versus speed: " + sc.name;
  chart.xlabel = "speed [km/h]";
  chart.ylabel = "damping ratio [-]";
  results::Chart fchart = chart;
  fchart.title = "Mode frequencies versus speed: " + sc.name;
  fchart.ylabel = "frequency [Hz]";
  std::vector<results::ChartSeries> zeta(static_cast<std::size_t>(a.count)), freq(zeta.size());
  for (int k = 0; k < a.count; ++k) {
    const std::string label = k == 0 ? "least damped" : "rank " + std::to_string(k + 1);
    zeta[k] = {label, {}, {}, "markers", "", 0};
    freq[k] = {label, {}, {}, "markers", "", 0};
  }
  std::vector<double> speeds;
  for (int i = 0; i < n; ++i) speeds.push_back((a.v_min_kmh + i * a.v_step_kmh) / 3.6);
  const engine::ModeSweep sweep = engine::mode_sweep(sc, speeds, a.count, a.v_min_kmh / 3.6, a.v_max_kmh / 3.6);
  const auto& all = sweep.modes;
  for (int i = 0; i < n; ++i) {
    const double v_kmh = a.v_min_kmh + i * a.v_step_kmh;
    const auto& md = all[static_cast<std::size_t>(i)];
    for (int k = 0; k < a.count && k < static_cast<int>(md.size()); ++k) {
      const auto& mode = md[static_cast<std::size_t>(k)];
      csv.cell(v_kmh).cell(k + 1).cell(mode.frequency).cell(mode.damping_ratio).cell(mode.eigenvalue.real())
          .cell(mode.eigenvalue.imag()).end_row();
      zeta[k].x.push_back(v_kmh), zeta[k].y.push_back(mode.damping_ratio);
      freq[k].x.push_back(v_kmh), freq[k].y.push_back(mode.frequency);
    }
  }
  csv.close();
  const double v_lin = sweep.linear_critical_speed;
  for (int k = 0; k < a.count; ++k) chart.series.push_back(zeta[k]), fchart.series.push_back(freq[k]);
  if (!std::isnan(v_lin) && !sweep.unstable_at_v_lo) {
    chart.lines.push_back({v_lin * 3.6, "linear critical speed", "r", true});
    fchart.lines.push_back({v_lin * 3.6, "linear critical speed", "r", true});
  }
  chart.lines.push_back({0.0, "zero damping", "0.5", false});
  results::draw(chart, a.out + "/modes.png");
  results::draw(fchart, a.out + "/modes_frequency.png");
  results::Json summary = results::Json::object();
  summary.set("scenario", sc.name);
  summary.set("vehicle", sc.model.vehicle_name);
  summary.set("wheelset_model", engine::wheelset_model_name(sc.model.wheelset_model));
  summary.set("geometry", sc.geometry_description);
  summary.set("equivalent_conicity_3mm", sc.equivalent_conicity_3mm);
  summary.set("contact", sc.model.coupling.describe());
  summary.set("mu", sc.model.coupling.options().material.mu);
  summary.set("speed_range_kmh", results::Json::array().push(a.v_min_kmh).push(a.v_max_kmh));
  summary.set("speed_step_kmh", a.v_step_kmh);
  // Unstable already at --v-min: no critical speed in the range, only a bound.
  const bool below = sweep.unstable_at_v_lo;
  summary.set("linear_critical_speed_kmh",
              std::isnan(v_lin) || below ? results::Json(nullptr) : results::Json(v_lin * 3.6));
  summary.set("unstable_at_v_min", below);
  summary.write_file(a.out + "/summary.json");
  if (below)
    std::printf("linear critical speed: at or below %.1f km/h (unstable already at --v-min; lower --v-min to find "
                "it)\n",
                a.v_min_kmh);
  else if (std::isnan(v_lin))
    std::printf("linear critical speed: none in %.0f..%.0f km/h (stable throughout)\n", a.v_min_kmh, a.v_max_kmh);
  else
    std::printf("linear critical speed: %.1f km/h\n", v_lin * 3.6);
  std::printf("wrote %s/modes.csv, summary.json, modes.png, modes_frequency.png (%d speeds)\n", a.out.c_str(), n);
  return kExitSuccess;
}

}  // namespace

void register_modes(CLI::App& app, CommandRunner& run) {
  auto a = std::make_shared<ModesArgs>();
  auto* cmd = app.add_subcommand("modes", "Eigenvalues of the linearised vehicle versus speed (damping, frequency)");
  cmd->add_option("scenario", a->scenario, "Scenario YAML file")->required();
  cmd->add_option("--out", a->out, "Output folder")->capture_default_str();
  cmd->add_option("--v-min", a->v_min_kmh, "Lowest speed [km/h]")->capture_default_str();
  cmd->add_option("--v-max", a->v_max_kmh, "Highest speed [km/h]")->capture_default_str();
  cmd->add_option("--v-step", a->v_step_kmh, "Speed step [km/h]")->capture_default_str();
  cmd->add_option("--count", a->count, "Least damped oscillatory modes reported per speed")
      ->check(CLI::Range(1, 50))
      ->capture_default_str();
  cmd->callback([a, &run] { run = [a] { return run_modes(*a); }; });
}

}  // namespace railsim::cli
