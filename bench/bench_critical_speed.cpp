// Wall time of the main job's bifurcation sweep (scenarios/
// manchester_coach_critical_speed.yaml: the Manchester coach on the S1002/UIC60
// table, Kalker + CHOPAYA, its own sweep settings: 150..350 km/h in 10 km/h
// steps, both branches, 10 s per point = 42 runs) and its scaling from one to
// two worker threads, with the scenario's path following on the down branch
// (BM_DefaultSweep: the parallel sweep, then a short serial chain below the
// lowest hunting speed down to the fold) and with every point independent
// (BM_ParallelSweep: the sweep runner's own scaling). Counters: "points", "s_per_point" (wall),
// and on the two-thread runs "speedup" = T1/T2 and "efficiency" = T1/(2 T2)
// (target > 0.85 for the independent points).
// Each benchmark runs the whole sweep twice and keeps the faster (Iterations(1)): a few minutes.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <string>

#include "engine/analysis/critical_speed.hpp"
#include "engine/analysis/critical_speed_study.hpp"
#include "engine/io/scenario.hpp"

namespace {

std::string scenario_path(const char* file) {
  return (std::filesystem::path(RAILSIM_SOURCE_DIR) / "scenarios" / file).string();
}

// Wall time of the one-thread sweep, for the speed-up of the two-thread one
// (benchmarks run in registration order): [continuation].
double one_thread_wall[2] = {0.0, 0.0};

void sweep(benchmark::State& state, bool continuation) {
  using namespace railsim::engine;
  const Scenario sc = load_scenario(scenario_path("manchester_coach_critical_speed.yaml"));
  BifurcationOptions o = bifurcation_options(study_settings(sc.critical_speed));
  o.use_mpi = false;
  o.continuation = continuation;
  o.threads = static_cast<int>(state.range(0));
  const auto dir = std::filesystem::temp_directory_path() / "railsim_bench_sweep";
  double wall = 0.0;
  std::size_t points = 0;
  for (auto _ : state) {
    // The fastest of two sweeps: a shared virtual machine adds minutes-long
    // slow phases that would otherwise decide the speed-up.
    wall = 1e300;
    for (int rep = 0; rep < 2; ++rep) {
      std::filesystem::remove_all(dir);
      std::filesystem::create_directories(dir);
      const auto t0 = std::chrono::steady_clock::now();
      const BifurcationResult r = bifurcation_sweep(sc, o, (dir / "points.csv").string());
      wall = std::min(wall, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
      points = r.points.size();
      state.counters["critical_speed_kmh"] = r.nonlinear_critical_speed * 3.6;
    }
    state.SetIterationTime(wall);
  }
  std::filesystem::remove_all(dir);
  state.counters["points"] = static_cast<double>(points);
  state.counters["s_per_point"] = wall / static_cast<double>(points);
  double& t1 = one_thread_wall[continuation ? 1 : 0];
  if (o.threads == 1) t1 = wall;
  if (o.threads == 2 && t1 > 0) {
    state.counters["speedup"] = t1 / wall;
    state.counters["efficiency"] = t1 / (2.0 * wall);
  }
}

void BM_DefaultSweep(benchmark::State& state) { sweep(state, true); }
void BM_ParallelSweep(benchmark::State& state) { sweep(state, false); }

}  // namespace

BENCHMARK(BM_DefaultSweep)->Arg(1)->Arg(2)->ArgName("threads")->Iterations(1)->UseManualTime()->Unit(benchmark::kSecond);
BENCHMARK(BM_ParallelSweep)->Arg(1)->Arg(2)->ArgName("threads")->Iterations(1)->UseManualTime()->Unit(benchmark::kSecond);

BENCHMARK_MAIN();
