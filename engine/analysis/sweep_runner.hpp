// Resumable parallel sweeps: run independent points (speeds of a bifurcation
// sweep, reduction-factor entries of a study, ...) on a thread pool or over MPI
// ranks (options.use_mpi, when the program started MPI: MpiSession below),
// writing every finished point at once.
//
// Files, for an output path OUT (e.g. DIR/bifurcation_points.csv):
//   OUT.part<r>   one per process (MPI rank r, or 0 for threads): a CSV line is
//                 appended and flushed as soon as a point finishes;
//   OUT           written at the end: all points sorted by index.
// A sweep that is interrupted and started again reads every part file (and OUT
// if present), skips the finished points and computes only the rest, so nothing
// is lost and nothing is duplicated. A torn last line (killed mid-write) is
// ignored and recomputed. Results do not depend on the number of threads or
// ranks: each point is computed by the same deterministic function; values are
// written with 17 significant digits so reading them back is exact.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace railsim::engine {

struct SweepPoint {
  long index = 0;             // position in the sweep (unique)
  std::string key;            // unique text key, e.g. "down:210" (no commas)
  std::vector<double> params; // whatever the point function needs
};

struct SweepResult {
  long index = 0;
  std::string key;
  std::vector<double> values;  // one per result column
};

struct SweepOptions {
  std::string output;                       // OUT path
  std::vector<std::string> result_columns;  // names of the values
  int threads = 0;                          // 0 = hardware concurrency (per process)
  bool use_mpi = false;                     // spread points over MPI ranks when built with MPI
  double progress_interval_s = 5.0;         // progress log period
  std::string label = "sweep";              // for progress messages
};

using SweepFunction = std::function<std::vector<double>(const SweepPoint&)>;

// Run (or resume) the sweep and return all results sorted by index, on every
// rank. Exceptions thrown by the point function propagate after the other
// running points have finished and been written.
std::vector<SweepResult> run_sweep(const std::vector<SweepPoint>& points, const SweepFunction& fn,
                                   const SweepOptions& options);

// Finished results found in OUT and OUT.part* (for inspection and tests).
// With `columns`, a file whose header names other result columns (written by
// another version or another kind of sweep) is refused with an InputError
// naming it, rather than read as this sweep's points.
std::vector<SweepResult> read_finished_points(const std::string& output, std::size_t n_values,
                                              const std::vector<std::string>* columns = nullptr);

// Write a finished sweep file (header "index,key,<columns>", one line per row,
// values with 17 digits) atomically (temporary file + rename).
void write_sweep_file(const std::string& output, const std::vector<std::string>& columns,
                      const std::vector<SweepResult>& rows);

// MPI for the life of a program, started explicitly: construct one MpiSession
// first thing in main() (cli/main.cpp, the sweep probe of the tests). Launched
// by mpirun (OMPI_COMM_WORLD_SIZE or PMI_SIZE in the environment) it calls
// MPI_Init, and MPI_Finalize when it goes out of scope; otherwise, or built
// without MPI, it does nothing. Nothing else initialises MPI.
class MpiSession {
 public:
  MpiSession(int* argc, char*** argv);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

 private:
  bool owns_ = false;  // this session called MPI_Init
};

// The rank and size of the running MPI job: rank 0 of 1 (not active) unless MPI
// was initialised (by an MpiSession). A plain query: it never starts MPI.
struct MpiContext {
  int rank = 0;
  int size = 1;
  bool active = false;  // size > 1
};
MpiContext mpi_context();

}  // namespace railsim::engine
