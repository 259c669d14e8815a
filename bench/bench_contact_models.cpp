// Cost per call of the analytic contact pieces: exact Hertz, Kalker coefficient
// look-up, every registered tangential model on a typical tread contact, and the
// combination Hertz + Kalker + CHOPAYA per contact (issue 2 target: < 200 ns).
// Inputs vary from call to call (16 curvature ratios / creepage sets) so that no
// result can be hoisted out of the loop.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "contact/hertz.hpp"
#include "contact/kalker_coefficients.hpp"
#include "contact/registry.hpp"

using namespace railsim::contact;

namespace {

const Material kSteel{210e9, 0.28, 0.3};

// Typical wheel-rail curvature sets: A = cos(gamma)/(2 r_w), B from rail/wheel radii.
std::array<std::pair<double, double>, 16> curvatures() {
  std::array<std::pair<double, double>, 16> c{};
  for (int i = 0; i < 16; ++i) c[i] = {1.0 / (2.0 * (0.42 + 0.005 * i)), 0.4 + 0.35 * i};
  return c;
}

std::array<Creepages, 16> creepages() {
  std::array<Creepages, 16> c{};
  for (int i = 0; i < 16; ++i) c[i] = {1e-4 * (i + 1), -5e-5 * (i % 5), 0.02 * (i % 7)};
  return c;
}

void BM_Hertz(benchmark::State& state) {
  const auto c = curvatures();
  std::size_t i = 0;
  for (auto _ : state) {
    const auto& ab = c[i++ & 15];
    benchmark::DoNotOptimize(hertz_from_load(ab.first, ab.second, 75e3, kSteel));
  }
}
BENCHMARK(BM_Hertz);

void BM_KalkerCoefficients(benchmark::State& state) {
  std::array<double, 16> ab{};
  for (int i = 0; i < 16; ++i) ab[i] = 0.3 + 0.21 * i;
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(kalker_coefficients(ab[i++ & 15], 0.28));
}
BENCHMARK(BM_KalkerCoefficients);

// One model on a fixed Hertz patch (tread contact, 75 kN, a/b ~ 1.33), creepages varying.
void BM_Model(benchmark::State& state, const TangentialModelEntry* entry) {
  const auto model = entry->make({});
  const auto ws = model->make_workspace();
  ContactInput in;
  in.material = kSteel;
  in.patch = hertz_from_load(1.0 / 0.92, 1.0 / 0.6, 75e3, kSteel);
  const auto cr = creepages();
  std::size_t i = 0;
  for (auto _ : state) {
    in.creep = cr[i++ & 15];
    benchmark::DoNotOptimize(model->solve(in, ws.get()));
  }
}

// Per contact: Hertz patch from the curvatures, then CHOPAYA (which looks up C_ij).
void BM_HertzKalkerChopaya(benchmark::State& state) {
  const auto model = make_tangential_model("chopaya");
  const auto c = curvatures();
  const auto cr = creepages();
  ContactInput in;
  in.material = kSteel;
  std::size_t i = 0;
  for (auto _ : state) {
    const std::size_t k = i++ & 15;
    in.patch = hertz_from_load(c[k].first, c[k].second, 75e3, kSteel);
    in.creep = cr[k];
    benchmark::DoNotOptimize(model->solve(in, nullptr));
  }
}
BENCHMARK(BM_HertzKalkerChopaya);

// The same with the Hertz shape cached per curvature pair (as a wheel-rail
// geometry table can store it): per contact only the load-dependent part.
void BM_HertzShapeCachedKalkerChopaya(benchmark::State& state) {
  const auto model = make_tangential_model("chopaya");
  const auto c = curvatures();
  const auto cr = creepages();
  std::array<HertzShape, 16> shapes{};
  for (int k = 0; k < 16; ++k) shapes[k] = hertz_shape(std::min(c[k].first, c[k].second) / std::max(c[k].first, c[k].second));
  ContactInput in;
  in.material = kSteel;
  std::size_t i = 0;
  for (auto _ : state) {
    const std::size_t k = i++ & 15;
    in.patch = hertz_from_shape(c[k].first, c[k].second, shapes[k], 70e3 + 100.0 * k, kSteel);
    in.creep = cr[k];
    benchmark::DoNotOptimize(model->solve(in, nullptr));
  }
}
BENCHMARK(BM_HertzShapeCachedKalkerChopaya);

const int kRegistered = [] {
  for (const auto& e : tangential_models())
    if (e.compared_by_default())  // mim_table's lookup: bench_fastsim; coefficients: as linear / she
    benchmark::RegisterBenchmark(("BM_Model/" + std::string(e.name)).c_str(), BM_Model, &e);
  return 0;
}();

}  // namespace

BENCHMARK_MAIN();
