// Speed of the track evaluation the engine calls every right-hand-side
// evaluation (Track::at), for the shipped track files, and of the one-off PSD
// synthesis at load time.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>

#include "track/psd_synthesis.hpp"
#include "track/track_file.hpp"

namespace {

// tracks/ folder of this source tree (this file is bench/bench_track.cpp).
std::string track_path(const char* file) {
  return (std::filesystem::path(RAILSIM_SOURCE_DIR) / "tracks" / file).string();
}

void track_at(benchmark::State& state, const char* file) {
  const railsim::track::Track t = railsim::track::load_track(track_path(file));
  double s = 0.0;
  const double step = 0.0937;
  for (auto _ : state) {
    const railsim::track::TrackState st = t.at(s);
    benchmark::DoNotOptimize(st);
    s += step;
    if (s > t.length()) s = 0.0;
  }
}
BENCHMARK_CAPTURE(track_at, straight_lateral_defect, "straight_lateral_defect.yaml");
BENCHMARK_CAPTURE(track_at, curve_twist, "curve_twist.yaml");
BENCHMARK_CAPTURE(track_at, curve_R300, "curve_R300.yaml");
BENCHMARK_CAPTURE(track_at, straight_erri_low, "straight_erri_low.yaml");

// Synthesis of one channel over `range(0)` km, ERRI low, 3-150 m.
void psd_synthesis(benchmark::State& state) {
  const auto sp = railsim::track::TrackSpectrum::named("erri_low");
  railsim::track::SynthesisOptions o;
  o.s_end = 1000.0 * static_cast<double>(state.range(0));
  for (auto _ : state) {
    auto x = railsim::track::synthesise_channel(sp, railsim::track::Channel::vertical, o);
    benchmark::DoNotOptimize(x.value.data());
  }
}
BENCHMARK(psd_synthesis)->Arg(3)->Arg(30)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
