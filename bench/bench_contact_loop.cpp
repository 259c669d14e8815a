// A tangential model on 1e5 creepage points in a plain C++ loop: the reference
// of the Python module's cost (bench/bench_python_contact.py compares
// railsim.contact() on the same points against these figures; issue 18 target:
// Python within 10 % of this loop). Same work per point as the module's loop:
// the creepages from arrays, one solve() with the model's workspace, Fx, Fy,
// Mz, valid, iterations and stick fraction stored into output arrays. The
// patch (a = 6 mm, b = 4 mm, Fz = 75 kN, steel, mu = 0.3) is solved once, as
// the module does for constant patch data. BM_ContactLoop allocates the
// outputs once outside the timed loop (the cheapest C++ caller);
// BM_ContactLoopAllocating allocates them per call, as a function returning
// its results (and the module, which returns new numpy arrays) must.
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "contact/hertz.hpp"
#include "contact/registry.hpp"

using namespace railsim::contact;

namespace {

constexpr int kPoints = 100000;

void BM_ContactLoopImpl(benchmark::State& state, const std::string& model_name, bool allocate) {
  const auto model = make_tangential_model(model_name);
  const auto ws = model->make_workspace();
  std::vector<double> xi(kPoints), Fx(kPoints), Fy(kPoints), Mz(kPoints), stick(kPoints);
  std::vector<char> valid(kPoints);
  std::vector<int> iterations(kPoints);
  for (int i = 0; i < kPoints; ++i) xi[i] = 0.01 * i / (kPoints - 1);  // numpy.linspace(0, 0.01, 1e5)
  ContactInput in;
  in.material = {2.1e11, 0.28, 0.3};
  in.patch = hertz_from_semi_axes(6e-3, 4e-3, 75e3, in.material);
  for (auto _ : state) {
    if (allocate) {
      Fx = std::vector<double>(kPoints), Fy = std::vector<double>(kPoints), Mz = std::vector<double>(kPoints);
      stick = std::vector<double>(kPoints);
      valid = std::vector<char>(kPoints);
      iterations = std::vector<int>(kPoints);
    }
    for (int i = 0; i < kPoints; ++i) {
      in.creep = {xi[i], 0.0, 0.0};
      const ContactForces f = model->solve(in, ws.get());
      Fx[i] = f.Fx;
      Fy[i] = f.Fy;
      Mz[i] = f.Mz;
      valid[i] = f.valid;
      iterations[i] = f.iterations;
      stick[i] = f.stick_fraction;
    }
    benchmark::DoNotOptimize(Fx.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * kPoints);
}

void BM_ContactLoop(benchmark::State& state, const std::string& m) { BM_ContactLoopImpl(state, m, false); }
void BM_ContactLoopAllocating(benchmark::State& state, const std::string& m) { BM_ContactLoopImpl(state, m, true); }

}  // namespace

BENCHMARK_CAPTURE(BM_ContactLoop, linear, std::string("linear"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ContactLoop, chopaya, std::string("chopaya"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ContactLoop, polach, std::string("polach"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ContactLoop, fastsim, std::string("fastsim"))->Unit(benchmark::kMillisecond)->Iterations(3);

BENCHMARK_CAPTURE(BM_ContactLoopAllocating, linear, std::string("linear"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ContactLoopAllocating, chopaya, std::string("chopaya"))->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
