// Resumable sweeps: identical results for any worker count, nothing lost or
// duplicated after an interruption, torn lines recomputed, MPI == threads.
#include <catch2/catch.hpp>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "core/errors.hpp"
#include "engine/analysis/sweep_runner.hpp"
#include "test_support.hpp"

using namespace railsim::engine;

namespace {

std::vector<SweepPoint> make_points(int n) {
  std::vector<SweepPoint> pts;
  for (int i = 0; i < n; ++i) pts.push_back({i, "v" + std::to_string(100 + 10 * i), {100.0 + 10.0 * i}});
  return pts;
}

// A deterministic "expensive" point: values that depend on the parameter only.
std::vector<double> point_value(const SweepPoint& p) {
  double acc = 0.0;
  for (int k = 1; k < 2000; ++k) acc += std::sin(p.params[0] * k) / k;
  return {acc, p.params[0] * p.params[0]};
}

struct Interrupted : std::runtime_error {
  Interrupted() : std::runtime_error("interrupted") {}
};

}  // namespace

TEST_CASE("one and two worker threads write identical sweep files", "[sweep]") {
  const std::string dir = railsim::test::temp_dir("sweep_threads");
  const auto pts = make_points(12);
  SweepOptions o{dir + "/one.csv", {"a", "b"}, 1};
  const auto r1 = run_sweep(pts, point_value, o);
  o.output = dir + "/two.csv";
  o.threads = 2;
  const auto r2 = run_sweep(pts, point_value, o);
  REQUIRE(r1.size() == 12);
  CHECK(railsim::test::read_text(dir + "/one.csv") == railsim::test::read_text(dir + "/two.csv"));
  CHECK_FALSE(std::filesystem::exists(dir + "/two.csv.part0"));
}

TEST_CASE("an interrupted sweep resumes with all points and no duplicates", "[sweep]") {
  const std::string dir = railsim::test::temp_dir("sweep_resume");
  const auto pts = make_points(10);
  SweepOptions o{dir + "/points.csv", {"a", "b"}, 1};
  std::atomic<int> calls{0};
  auto interrupted_after_4 = [&](const SweepPoint& p) {
    if (calls++ == 4) throw Interrupted();
    return point_value(p);
  };
  CHECK_THROWS_AS(run_sweep(pts, interrupted_after_4, o), Interrupted);
  // The four finished points are on disk already.
  CHECK(read_finished_points(o.output, 2).size() == 4);
  // Simulate a kill in the middle of writing a line: a torn last line.
  {
    std::ofstream f(o.output + ".part0", std::ios::app);
    f << "7,v170,0.12";
  }
  std::atomic<int> resumed_calls{0};
  auto counting = [&](const SweepPoint& p) {
    ++resumed_calls;
    return point_value(p);
  };
  const auto all = run_sweep(pts, counting, o);
  CHECK(resumed_calls == 6);
  REQUIRE(all.size() == 10);
  for (std::size_t i = 0; i < all.size(); ++i) {
    CHECK(all[i].index == static_cast<long>(i));
    CHECK(all[i].values == point_value(pts[i]));
  }
  // The merged file has a header and exactly one line per point.
  const std::string text = railsim::test::read_text(o.output);
  CHECK(std::count(text.begin(), text.end(), '\n') == 11);
  // A clean run gives the same file.
  SweepOptions clean{dir + "/clean.csv", {"a", "b"}, 2};
  run_sweep(pts, point_value, clean);
  CHECK(railsim::test::read_text(clean.output) == text);
}

#ifdef RAILSIM_HAVE_MPI
TEST_CASE("MPI with two ranks writes the same sweep file as threads", "[sweep][mpi]") {
  const std::string dir = railsim::test::temp_dir("sweep_mpi");
  const std::string probe = std::string(RAILSIM_SWEEP_PROBE);
  const std::string mpi = railsim::test::mpirun_prefix() + "mpirun --allow-run-as-root --oversubscribe -np 2 \"" + probe + "\" " + dir + "/mpi.csv";
  const std::string thr = "\"" + probe + "\" " + dir + "/threads.csv";
  REQUIRE(std::system((mpi + " > " + dir + "/mpi.log 2>&1").c_str()) == 0);
  REQUIRE(std::system((thr + " > " + dir + "/thr.log 2>&1").c_str()) == 0);
  const std::string a = railsim::test::read_text(dir + "/mpi.csv"), b = railsim::test::read_text(dir + "/threads.csv");
  CHECK(!a.empty());
  CHECK(a == b);
}
#endif

// A point stopped by the user (InterruptedError from a stop request): the
// sweep ends saying how many points are kept and where, and that the same
// command resumes; the resume computes only the rest.
TEST_CASE("a sweep stopped by the user says what it kept, and resumes", "[sweep][interrupt]") {
  const std::string dir = railsim::test::temp_dir("sweep_user_stop");
  const auto pts = make_points(8);
  for (const int threads : {1, 2}) {
    SweepOptions o{dir + "/points" + std::to_string(threads) + ".csv", {"a", "b"}, threads};
    o.label = "test sweep";
    std::atomic<int> calls{0};
    auto stopped_at_3 = [&](const SweepPoint& p) {
      if (calls++ >= 3) throw railsim::InterruptedError("interrupted at t = 1 s of 6 s");
      return point_value(p);
    };
    std::string msg;
    try {
      run_sweep(pts, stopped_at_3, o);
    } catch (const railsim::InterruptedError& e) {
      msg = e.what();
    }
    INFO(msg);
    CHECK(msg.find("test sweep: interrupted at t = 1 s of 6 s; 3 of 8 points of this run are kept in " + o.output +
                   ".part0") != std::string::npos);
    CHECK(msg.find("the same command in the same folder resumes") != std::string::npos);
    CHECK(read_finished_points(o.output, 2).size() == 3);
    std::atomic<int> resumed{0};
    const auto all = run_sweep(pts, [&](const SweepPoint& p) { ++resumed; return point_value(p); }, o);
    CHECK(resumed == 5);
    REQUIRE(all.size() == 8);
    for (std::size_t i = 0; i < all.size(); ++i) CHECK(all[i].values == point_value(pts[i]));
  }
}
