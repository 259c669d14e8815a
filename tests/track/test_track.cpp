// Track::at, the engine's entry point: does not allocate (counted with a
// replaced global operator new in this test program), gives bit-identical
// results from several threads at once, and sums alignment and irregularities.
#include <catch2/catch.hpp>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <new>
#include <string>
#include <thread>
#include <vector>

#include "core/errors.hpp"
#include "test_support.hpp"
#include "track/track_file.hpp"

namespace {
std::atomic<long> g_allocations{0};
}

void* operator new(std::size_t n) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t n) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
// The nothrow forms too, so that every new pairs with the free() below (Catch
// allocates with new(std::nothrow); under AddressSanitizer a mix of its own
// nothrow new and our delete is an alloc-dealloc mismatch).
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  return std::malloc(n ? n : 1);
}
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  return std::malloc(n ? n : 1);
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

using namespace railsim::track;
using railsim::test::source_path;

namespace {
// A track with every kind of segment and irregularity component.
const char* kAll = R"(segments:
  - {type: straight, length: 50}
  - {type: clothoid, length: 30, shape: bloss}
  - {type: circular, length: 60, radius: 250, direction: left, cant_mm: 100}
  - {type: clothoid, length: 30}
  - {type: straight, length: 300}
irregularities:
  - {type: defect, channel: lateral, start: 20, wavelength: 20, amplitude_mm: 10}
  - {type: twist, start: 150, base_length: 3, amplitude_mm: -18, rail: right}
  - {type: psd, spectrum: erri_low, seed: 5, wavelength_min: 2, wavelength_max: 100}
  - {type: measured, file: measured_good.csv, offset: 200}
)";
}  // namespace

TEST_CASE("Track::at does not allocate", "[tracks][track]") {
  const Track t = load_track(railsim::config::InputNode::load_string(kAll, "all.yaml"),
                             railsim::test::data_path("tracks"), "all");
  double sink = 0;
  const long before = g_allocations.load();
  for (double s = -20.0; s < 500.0; s += 0.0937) {
    const TrackState st = t.at(s);
    sink += st.x + st.curvature + st.cant_angle + st.irregularity.left_lateral() + st.irregularity.right_vertical_slope();
  }
  const long after = g_allocations.load();
  CHECK(after - before == 0);
  CHECK(std::isfinite(sink));
}

TEST_CASE("Track::at is thread-safe and deterministic", "[tracks][track]") {
  const Track t = load_track(railsim::config::InputNode::load_string(kAll, "all.yaml"),
                             railsim::test::data_path("tracks"), "all");
  std::vector<double> pts;
  for (double s = 0.0; s < 470.0; s += 0.31) pts.push_back(s);
  std::vector<TrackState> serial(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) serial[i] = t.at(pts[i]);
  std::vector<std::vector<TrackState>> par(4, std::vector<TrackState>(pts.size()));
  std::vector<std::thread> threads;
  for (std::size_t k = 0; k < par.size(); ++k)
    threads.emplace_back([&, k] {
      for (std::size_t i = 0; i < pts.size(); ++i) par[k][i] = t.at(pts[i]);
    });
  for (auto& th : threads) th.join();
  for (const auto& p : par) CHECK(std::memcmp(p.data(), serial.data(), serial.size() * sizeof(TrackState)) == 0);
}

TEST_CASE("embedded track: errors carry the key path of the embedding file", "[tracks][track]") {
  const auto root = railsim::config::InputNode::load_string(
      "track:\n  segments:\n    - {type: straight, length: 50}\n    - {type: clothoid, length: 0}\n", "scn.yaml");
  try {
    load_track(root.at("track"), ".", "track");
    FAIL("no error");
  } catch (const railsim::InputError& e) {
    CHECK(std::string(e.what()) ==
          "scn.yaml:4: track.segments[1] (clothoid): key 'length': expected a positive number (got 0)");
  }
}
