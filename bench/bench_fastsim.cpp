// Per-call cost of FASTSIM and the FaStrip-type model (contact/fastsim.cpp,
// contact/fastrip.cpp) on a typical wheel-rail patch (a = 6 mm, b = 4 mm,
// Fz = 75 kN, mu = 0.3), in partial slip with creepage and spin.
// Target (issue 5): FASTSIM on 10 x 10 elements under 5 microseconds per call;
// MIM table lookup (contact/mim_table.cpp) under 1 microsecond per call.
#include <benchmark/benchmark.h>

#include "contact/fastrip.hpp"
#include "contact/fastsim.hpp"
#include "contact/mim_table/mim_table.hpp"

using namespace railsim::contact;

namespace {
ContactInput typical_input() {
  ContactInput in;
  in.patch.a = 6e-3;
  in.patch.b = 4e-3;
  in.patch.Fz = 75000.0;
  in.material = Material{210.0e9, 0.28, 0.3};
  in.creep = {1.0e-3, -0.8e-3, 0.6};  // partial slip, with spin [1/m]
  return in;
}

template <class Model, class Options>
void run(benchmark::State& state, Options o = {}) {
  o.nx = o.ny = static_cast<int>(state.range(0));
  const Model model(o);
  ContactInput in = typical_input();
  double sink = 0.0;
  for (auto _ : state) {
    in.creep.xi += 1e-12;  // defeat caching of a constant input
    const ContactForces f = model.solve(in, nullptr);
    sink += f.Fx;
    benchmark::DoNotOptimize(sink);
  }
  state.counters["elements"] = static_cast<double>(o.nx * o.ny);
}

void BM_Fastsim(benchmark::State& s) { run<Fastsim, FastsimOptions>(s); }
void BM_Fastrip(benchmark::State& s) { run<Fastrip, FastripOptions>(s); }
// Kalker's three flexibilities (fastsim_kalker): FASTSIM without the blending.
void BM_FastsimKalker(benchmark::State& s) {
  FastsimOptions o;
  o.flexibility = FastsimFlexibility::three;
  run<Fastsim, FastsimOptions>(s, o);
}

// Lookup cost does not depend on how accurate the table is, so a small table
// on a coarse MIM grid (built in well under a second) stands in for the standard one.
void BM_MimTableLookup(benchmark::State& state) {
  MimTableSpec spec;
  spec.aob = {0.45, 0.7, 1.0, 1.4, 2.2};
  spec.uxi = MimTableSpec::standard().uxi;
  spec.ueta = MimTableSpec::standard().ueta;
  spec.vpsi = {-0.9, -0.6, -0.3, 0.0, 0.3, 0.6, 0.9};
  spec.grid = 8;  // the smallest grid the table's extrapolation (8 and 4) takes
  const MimTableModel model(std::shared_ptr<const MimTable>(MimTable::build(spec, "", {}).release()));
  ContactInput in = typical_input();
  double sink = 0.0;
  for (auto _ : state) {
    in.creep.xi += 1e-12;
    sink += model.solve(in, nullptr).Fx;
    benchmark::DoNotOptimize(sink);
  }
}
}  // namespace

BENCHMARK(BM_Fastsim)->Arg(5)->Arg(10)->Arg(20)->Arg(40)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_FastsimKalker)->Arg(5)->Arg(10)->Arg(20)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Fastrip)->Arg(5)->Arg(10)->Arg(20)->Arg(40)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_MimTableLookup)->Unit(benchmark::kMicrosecond);

BENCHMARK_MAIN();
