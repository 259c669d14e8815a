// Wheel-rail geometry speed: contact-table build (S1002 / UIC60 1:40, +-12 mm,
// 0.1 mm step), per-lookup cost (goal < 100 ns per wheel, i.e. < 200 ns per
// wheelset lookup), single-position contact search, STRIPES semi-Hertz solve.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "contact/geometry/contact_table.hpp"
#include "contact/geometry/semi_hertz.hpp"
#include "engine/wheel_rail/geometry_table.hpp"
#include "engine/wheel_rail/profile_geometry.hpp"
#include "engine/wheel_rail/strip_patches.hpp"

using namespace railsim::contact;

namespace {
struct Setup {
  Profile w = read_profile("S1002", ProfileKind::wheel);
  Profile r = read_profile("UIC60", ProfileKind::rail);
  TrackSetup ts = [] {
    TrackSetup t;
    t.inclination = std::atan(1.0 / 40.0);
    return t;
  }();
  WheelRailGeometry g{w, r, ts};
};
const Setup& setup() {
  static const Setup s;
  return s;
}
}  // namespace

static void BM_GeometryBuild(benchmark::State& state) {
  for (auto _ : state) {
    WheelRailGeometry g(setup().w, setup().r, setup().ts);
    benchmark::DoNotOptimize(g.rail_offset());
  }
}
BENCHMARK(BM_GeometryBuild)->Unit(benchmark::kMillisecond);

static void BM_TableBuild(benchmark::State& state) {
  const TableGrid grid;  // -12 .. 12 mm, 0.1 mm: 241 rows
  for (auto _ : state) {
    const ContactTable t = ContactTable::build(setup().g, grid);
    benchmark::DoNotOptimize(t.rows());
  }
  state.counters["rows"] = 241;
}
BENCHMARK(BM_TableBuild)->Unit(benchmark::kMillisecond);

static void BM_TableLookup(benchmark::State& state) {
  static const ContactTable t = ContactTable::build(setup().g, TableGrid{});
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(-0.0119, 0.0119);
  std::vector<double> ys(4096);
  for (auto& y : ys) y = u(rng);
  TableSample s;
  std::size_t i = 0;
  for (auto _ : state) {
    t.lookup(ys[i++ & 4095], s);
    benchmark::DoNotOptimize(s.wheel[0].p[0].radius);
    benchmark::DoNotOptimize(s.wheel[1].p[0].radius);
  }
  state.SetLabel("both wheels per lookup");
}
BENCHMARK(BM_TableLookup);

static void BM_SolveSinglePosition(benchmark::State& state) {
  double y = -0.01;
  for (auto _ : state) {
    const auto c = setup().g.solve(y, 0.0);
    benchmark::DoNotOptimize(c.roll);
    y += 1e-4;
    if (y > 0.01) y = -0.01;
  }
}
BENCHMARK(BM_SolveSinglePosition)->Unit(benchmark::kMicrosecond);

static void BM_SemiHertzS1002(benchmark::State& state) {
  const auto c = setup().g.solve(0.0);
  const auto gp = setup().g.gap_profile(Side::left, c.wheel[0].p[0], 0.0, c.z[0], c.roll, 0.0, 0.014, 561);
  SemiHertzWorkspace ws;
  const Material m;
  for (auto _ : state) {
    const auto r = semi_hertz_from_load(gp, 1e4, m, ws);
    benchmark::DoNotOptimize(r.area);
  }
}
BENCHMARK(BM_SemiHertzS1002)->Unit(benchmark::kMillisecond);

// The engine's geometry per right-hand side with yaw (issue 13: target under
// 200 ns per wheel from a table). Profiles: the strips of one wheel
// near the contact at a shift and yaw, from the cached strip table
// (built on first use, about 25 s); RSGEO: one table evaluation of one wheel.
// Shifts and yaws cycle through 256 random poses in +-8 mm, +-10 mrad.
static void BM_StripsWithYaw(benchmark::State& state) {
  static const railsim::engine::ProfileGeometry g = [] {
    railsim::engine::ProfileGeometryParams p;
    p.setup.inclination = std::atan(1.0 / 40.0);
    return railsim::engine::ProfileGeometry(p, Material{});
  }();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> dy(-8e-3, 8e-3), dpsi(-10e-3, 10e-3);
  std::vector<std::pair<double, double>> poses(256);
  for (auto& q : poses) q = {dy(rng), dpsi(rng)};
  StripSet s;
  std::size_t i = 0;
  for (auto _ : state) {
    const auto& q = poses[i++ & 255];
    g.strips(q.first, q.second, railsim::engine::ProfileGeometry::kGapCutoff, s);
    benchmark::DoNotOptimize(s.n);
  }
  state.SetLabel("per wheel");
}
BENCHMARK(BM_StripsWithYaw);

// The engine's whole normal-contact job per wheel and right-hand side on the
// profiles geometry (engine/wheel_rail/wheelset_contact.cpp): the strips that can carry
// load and the wheel's loads and patches. Lateral model: strips up to a
// 0.2 mm gap (the engine's first fetch), then the approach that carries the wheel load (40 kN, the
// coach's static wheel load); full model: strips up to the approach (0.05 mm
// plus what a 0.1 mrad roll beyond the rigid pose adds) and the loads there.
static const railsim::engine::ProfileGeometry& coach_geometry() {
  static const railsim::engine::ProfileGeometry g = [] {
    railsim::engine::ProfileGeometryParams p;
    p.setup.inclination = std::atan(1.0 / 40.0);
    return railsim::engine::ProfileGeometry(p, Material{});
  }();
  return g;
}
// Poses along a hunting-like path (shift 5 mm, yaw 4 mrad amplitude, 4096
// evaluations per cycle): consecutive evaluations are close, as within an
// integration; tread contact only (flange contact starts at 6.25 mm).
static std::vector<std::pair<double, double>> path_poses() {
  std::vector<std::pair<double, double>> poses(4096);
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const double a = 2.0 * M_PI * double(i) / double(poses.size());
    poses[i] = {5e-3 * std::sin(a), 4e-3 * std::cos(a)};
  }
  return poses;
}
static void BM_WheelNormalContactLateral(benchmark::State& state) {
  const auto& g = coach_geometry();
  const auto poses = path_poses();
  StripSet s;
  railsim::engine::StripLoads L;
  std::size_t i = 0;
  for (auto _ : state) {
    const auto& q = poses[i++ & 4095];
    g.strips(q.first, q.second, 0.2e-3, s);
    const double w = railsim::engine::strip_approach_for_load(s, 4.0e4, 0.0, g.contact_modulus(), L);
    benchmark::DoNotOptimize(w);
  }
  state.SetLabel("per wheel");
}
BENCHMARK(BM_WheelNormalContactLateral);

static void BM_WheelNormalContactFull(benchmark::State& state) {
  const auto& g = coach_geometry();
  const auto poses = path_poses();
  StripSet s;
  railsim::engine::StripLoads L;
  std::size_t i = 0;
  const double w = 5e-5, dphi = 1e-4, reach = w + dphi * 0.95;
  for (auto _ : state) {
    const auto& q = poses[i++ & 4095];
    g.strips(q.first, q.second, reach, s);
    railsim::engine::strip_loads(s, w, -dphi, 0.0, g.contact_modulus(), L);
    benchmark::DoNotOptimize(L.vertical);
  }
  state.SetLabel("per wheel");
}
BENCHMARK(BM_WheelNormalContactFull);


// The strips alone at the engine's cutoffs along the hunting-like path:
// the lateral model's first fetch (0.2 mm) and the full model's reach
// (0.15 mm); counter "strips" = strips returned per call.
static void strips_on_path(benchmark::State& state, double cutoff) {
  const auto& g = coach_geometry();
  const auto poses = path_poses();
  StripSet s;
  std::size_t i = 0;
  double n = 0.0;
  for (auto _ : state) {
    const auto& q = poses[i++ & 4095];
    g.strips(q.first, q.second, cutoff, s);
    n += s.n;
    benchmark::DoNotOptimize(s.n);
  }
  state.counters["strips"] = n / double(state.iterations());
  state.SetLabel("per wheel");
}
static void BM_StripsWithYawLateralCutoff(benchmark::State& state) { strips_on_path(state, 0.2e-3); }
BENCHMARK(BM_StripsWithYawLateralCutoff);
static void BM_StripsWithYawFullReach(benchmark::State& state) { strips_on_path(state, 0.15e-3); }
BENCHMARK(BM_StripsWithYawFullReach);

static void BM_RsgeoEvaluate(benchmark::State& state) {
  static const railsim::engine::GeometryTable g(std::string(RAILSIM_SOURCE_DIR) +
                                                "/vehicles/contact_tables/RSGEO_S1002_UIC60_1in40.dat");
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> dy(-8e-3, 8e-3);
  std::vector<double> ys(256);
  for (auto& y : ys) y = dy(rng);
  railsim::engine::WheelGeometry out;
  std::size_t i = 0;
  for (auto _ : state) {
    g.evaluate(ys[i++ & 255], 0.0, out);
    benchmark::DoNotOptimize(out.n);
  }
  state.SetLabel("per wheel");
}
BENCHMARK(BM_RsgeoEvaluate);

BENCHMARK_MAIN();
