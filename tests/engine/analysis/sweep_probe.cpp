// Small program for the MPI sweep test: runs a deterministic 16-point sweep
// with MPI when launched by mpirun, with threads otherwise, into argv[1].
#include <cmath>
#include <cstdio>

#include "engine/analysis/sweep_runner.hpp"

using namespace railsim::engine;

int main(int argc, char** argv) {
  const MpiSession mpi(&argc, &argv);
  if (argc < 2) return 2;
  std::vector<SweepPoint> pts;
  for (int i = 0; i < 16; ++i) pts.push_back({i, "p" + std::to_string(i), {0.1 * i}});
  SweepOptions o;
  o.output = argv[1];
  o.result_columns = {"f"};
  o.use_mpi = true;
  o.threads = 0;
  run_sweep(pts, [](const SweepPoint& p) { return std::vector<double>{std::exp(-p.params[0]) * std::cos(p.params[0])}; }, o);
  return 0;
}
