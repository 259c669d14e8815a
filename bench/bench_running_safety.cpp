// Cost of the EN 14363 running-safety evaluation (engine/analysis/run_safety.hpp)
// of a 10 km run against the run itself. The run is simulated once, outside
// the timing: the Manchester coach at 200 km/h on 10.5 km of straight track
// with ERRI B176 low-level irregularities (scenarios/manchester_coach_200_erri.yaml
// with a longer track), 180 s simulated, outputs every 10 ms (18,001 samples,
// 4 wheelsets, 8 acceleration points). Counters: "run_wall_s" / "run_cpu_s" of
// the simulation, "share_wall" = evaluation wall time / run wall time and
// "share_cpu" = evaluation CPU time / run CPU time (thread CPU clocks; the
// fair figure on a shared machine; goal: < 5 %, issue 17), "quantities" evaluated.
#include <benchmark/benchmark.h>

#include <time.h>

#include <chrono>
#include <string>

#include "config/yaml_input.hpp"
#include "engine/analysis/run_history.hpp"
#include "engine/analysis/run_safety.hpp"
#include "engine/analysis/track_zones.hpp"
#include "engine/io/scenario.hpp"
#include "engine/simulation.hpp"
#include "engine/track_input.hpp"

namespace {

using namespace railsim;
using namespace railsim::engine;

std::string root() { return RAILSIM_SOURCE_DIR; }

struct Recorded {
  Scenario scenario;
  RunHistory history;
  RunSummary run;
  std::vector<TrackSection> sections;
};

const Recorded& recorded_run() {
  static const Recorded r = [] {
    const std::string yaml =
        "name: erri_10km\n"
        "vehicle: vehicles/manchester_coach.yaml\n"
        "track: {name: erri_10km, rail_spacing: 1.5, gauge: 1.435, segments: [{type: straight, length: 10500}],\n"
        "        irregularities: [{type: psd, spectrum: erri_low, channels: [lateral, vertical, cross_level, gauge],\n"
        "                          seed: 1, wavelength_min: 3, wavelength_max: 150, from: 100, to: 10400, taper: 20}]}\n"
        "speed_kmh: 200\nduration: 180\noutput_interval: 0.01\nwheelset_model: lateral\n"
        "contact:\n"
        "  geometry: {type: conical, r0: 0.46, conicity: 0.15, l0: 0.75, contact_angle: 0,\n"
        "             flange_clearance: 0.009, flange_stiffness: 1.5e7}\n"
        "  tangential: chopaya\n  patch: {a: 6.0e-3, b: 4.0e-3, N_ref: 55000}\n"
        "  material: {E: 2.1e11, nu: 0.28, mu: 0.3}\n"
        "integrator: {method: odeint_dopri5, rtol: 1.0e-4, atol: 1.0e-6, max_step: 0.005}\n";
    Recorded out{load_scenario(config::InputNode::load_string(yaml, "erri_10km.yaml"), root()), {}, {}, {}};
    const Model& m = out.scenario.model;
    out.history = RunHistory(m);
    out.history.reserve(18001);
    out.run = simulate(m, out.scenario.integrator, out.scenario.x0, out.scenario.duration,
                       out.scenario.output_interval,
                       [&](double t, const Eigen::VectorXd& x, const Data& d) { out.history.record(m, t, x, d); });
    out.sections = track_sections(dynamic_cast<const TrackInput&>(*m.track).track());
    return out;
  }();
  return r;
}

void evaluate_10km(benchmark::State& state) {
  const Recorded& r = recorded_run();
  std::size_t quantities = 0;
  double cpu = 0.0, wall = 0.0;
  long n = 0;
  for (auto _ : state) {
    timespec a{}, b{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &a);
    const auto t0 = std::chrono::steady_clock::now();
    const RunSafety s = evaluate_run_safety(r.history, r.sections, 70.0 * 3.14159265358979 / 180.0, 0.3);
    wall += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &b);
    cpu += double(b.tv_sec - a.tv_sec) + 1e-9 * double(b.tv_nsec - a.tv_nsec);
    ++n;
    quantities = s.quantities.size();
    benchmark::DoNotOptimize(s.pass);
  }
  const double per_cpu = n ? cpu / double(n) : 0.0, per_wall = n ? wall / double(n) : 0.0;
  state.counters["run_wall_s"] = r.run.wall_time;
  state.counters["run_cpu_s"] = r.run.cpu_time;
  state.counters["samples"] = double(r.history.size());
  state.counters["quantities"] = double(quantities);
  state.counters["share_wall"] = r.run.wall_time > 0 ? per_wall / r.run.wall_time : 0.0;
  state.counters["share_cpu"] = r.run.cpu_time > 0 ? per_cpu / r.run.cpu_time : 0.0;
}
BENCHMARK(evaluate_10km)->Unit(benchmark::kMillisecond)->Iterations(20);

}  // namespace

BENCHMARK_MAIN();
