// Speed and memory of the exact contact solver (contact/mim): one normal +
// steady-rolling tangential solve, circular Hertzian case (A = B = 1/0.92 1/m,
// a = b = 6.10 mm, Fz = 75 kN, steel, mu = 0.3), partial slip (xi = 5e-4,
// eta = 2e-4, phi = 0.2 1/m: about 3/4 of the patch adheres), on grids of
// 20x20, 50x50, 100x100 and 200x200 elements (N = 16, 46, 96, 196 across the
// patch plus 4). The workspace (FFT plans, kernels) is built once before the
// timed loop, as in a simulation; BM_mim_setup times building it.
// BM_mim_solve alternates the load by 1e-9 between calls so that every call
// solves the normal problem (a vehicle run's patch changes every call);
// BM_mim_creepage_sweep keeps the patch and varies the creepage (tables,
// creep curves, reference sets: the normal solution is reused).
// BM_mim_model: the registered model "mim" on a changing patch, arg 1 = its
// default Richardson extrapolation (grid N and N/2), 0 = none.
// Targets (issue 4): 100x100 < 0.5 s, 200x200 < 3 s; memory ~ N log N.
// Counters: iterations of the normal and tangential solvers, adhesion
// fraction, rss_MB (resident set after the solve), peak_rss_MB (process peak).
#include <benchmark/benchmark.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cstdio>

#include "contact/mim/mim_model.hpp"

using namespace railsim::contact;
using namespace railsim::contact::mim;

namespace {

HertzPatch circular() {
  HertzPatch p;
  p.A = p.B = 1.0 / 0.92;
  p.a = p.b = 6.10114259e-3;
  p.Fz = 75000.0;
  return p;
}

double rss_mb() {
  long pages = 0, resident = 0;
  if (FILE* f = std::fopen("/proc/self/statm", "r")) {
    if (std::fscanf(f, "%ld %ld", &pages, &resident) != 2) resident = 0;
    std::fclose(f);
  }
  return resident * static_cast<double>(sysconf(_SC_PAGESIZE)) / 1048576.0;
}

double peak_rss_mb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024.0;
}

void BM_mim_solve(benchmark::State& state) {
  const int elements = static_cast<int>(state.range(0));
  MimOptions o;
  o.grid = elements - 4;
  MimSolver solver(o);
  const Material m{210e9, 0.28, 0.3};
  const Creepages c{5e-4, 2e-4, 0.2};
  const double rss0 = rss_mb();
  solver.solve_hertz(circular(), c, m);  // builds the workspace
  HertzPatch p = circular();
  int k = 0;
  for (auto _ : state) {
    p.Fz = 75000.0 * (1.0 + 1e-9 * (++k % 2));  // a new normal problem each call
    const MimSolution& s = solver.solve_hertz(p, c, m);
    benchmark::DoNotOptimize(s.Fx);
  }
  const MimSolution& s = solver.solution();
  state.counters["normal_it"] = s.normal.iterations;
  state.counters["tang_it"] = s.tangential.iterations;
  state.counters["adhesion"] = static_cast<double>(s.n_adhesion) / s.n_contact;
  state.counters["Fx_N"] = s.Fx;
  state.counters["ws_MB"] = rss_mb() - rss0;
  state.counters["rss_MB"] = rss_mb();
  state.counters["peak_rss_MB"] = peak_rss_mb();
  state.SetLabel(std::to_string(s.grid.mx) + "x" + std::to_string(s.grid.my));
}
BENCHMARK(BM_mim_solve)->Arg(20)->Arg(50)->Arg(100)->Arg(200)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();

void BM_mim_creepage_sweep(benchmark::State& state) {
  MimOptions o;
  o.grid = static_cast<int>(state.range(0)) - 4;
  MimSolver solver(o);
  const Material m{210e9, 0.28, 0.3};
  solver.solve_hertz(circular(), {5e-4, 2e-4, 0.2}, m);
  int k = 0;
  for (auto _ : state) {
    const double f = 1.0 + 0.01 * (++k % 7);  // the same patch, another creepage
    const MimSolution& s = solver.solve_hertz(circular(), {5e-4 * f, 2e-4 * f, 0.2 * f}, m);
    benchmark::DoNotOptimize(s.Fx);
  }
  state.counters["tang_it"] = solver.solution().tangential.iterations;
}
BENCHMARK(BM_mim_creepage_sweep)->Arg(20)->Arg(50)->Arg(100)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();

void BM_mim_model(benchmark::State& state) {
  TangentialModelOptions mo;
  mo.grid = static_cast<int>(state.range(0));
  mo.extrapolation = state.range(1) ? GridExtrapolation::Richardson : GridExtrapolation::None;
  const auto model = make_mim(mo);
  const auto ws = model->make_workspace();
  ContactInput in;
  in.material = Material{210e9, 0.28, 0.3};
  in.patch = circular();
  in.creep = {5e-4, 2e-4, 0.2};
  model->solve(in, ws.get());
  int k = 0;
  for (auto _ : state) {
    in.patch.Fz = 75000.0 * (1.0 + 1e-9 * (++k % 2));
    benchmark::DoNotOptimize(model->solve(in, ws.get()).Fx);
  }
  state.SetLabel(state.range(1) ? "richardson" : "none");
}
BENCHMARK(BM_mim_model)->Args({40, 0})->Args({40, 1})->Args({60, 0})->Args({60, 1})->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();

void BM_mim_setup(benchmark::State& state) {
  const int elements = static_cast<int>(state.range(0));
  const ContactGrid g = grid_for_patch(6.1e-3, 6.1e-3, elements - 4);
  for (auto _ : state) {
    InfluenceOperator op(g, ElasticPair{}, 0.0, 64u);
    benchmark::DoNotOptimize(op.self_xx());
  }
}
BENCHMARK(BM_mim_setup)->Arg(100)->Arg(200)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
