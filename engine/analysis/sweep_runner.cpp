// Resumable parallel sweeps; see sweep_runner.hpp.
#include "engine/analysis/sweep_runner.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <set>
#include <sstream>
#include <thread>

#include "core/atomic_file.hpp"
#include "core/errors.hpp"

#ifdef RAILSIM_HAVE_MPI
#include <mpi.h>
#endif

namespace railsim::engine {

namespace fs = std::filesystem;

MpiSession::MpiSession(int* argc, char*** argv) {
#ifdef RAILSIM_HAVE_MPI
  int initialised = 0;
  MPI_Initialized(&initialised);
  // Only a run launched by mpirun is distributed.
  const bool launched = std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMI_SIZE");
  if (launched && !initialised) {
    MPI_Init(argc, argv);
    owns_ = true;
  }
#else
  (void)argc;
  (void)argv;
#endif
}

MpiSession::~MpiSession() {
#ifdef RAILSIM_HAVE_MPI
  int finalised = 0;
  MPI_Finalized(&finalised);
  if (owns_ && !finalised) MPI_Finalize();
#endif
}

MpiContext mpi_context() {
  MpiContext ctx;
#ifdef RAILSIM_HAVE_MPI
  int initialised = 0, finalised = 0;
  MPI_Initialized(&initialised);
  MPI_Finalized(&finalised);
  if (!initialised || finalised) return ctx;
  MPI_Comm_rank(MPI_COMM_WORLD, &ctx.rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ctx.size);
  ctx.active = ctx.size > 1;
#endif
  return ctx;
}

namespace {

std::string format_value(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string result_line(const SweepResult& r) {
  std::string line = std::to_string(r.index) + "," + r.key;
  for (double v : r.values) line += "," + format_value(v);
  return line;
}

// Parse "index,key,v1,...,vn"; false for torn or foreign lines.
bool parse_line(const std::string& line, std::size_t n_values, SweepResult& out) {
  std::vector<std::string> cells;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ',')) cells.push_back(cell);
  if (cells.size() != n_values + 2) return false;
  try {
    std::size_t used = 0;
    out.index = std::stol(cells[0], &used);
    if (used != cells[0].size()) return false;
    out.key = cells[1];
    out.values.clear();
    for (std::size_t i = 0; i < n_values; ++i) {
      const std::string& c = cells[i + 2];
      if (c == "nan") {
        out.values.push_back(std::nan(""));
        continue;
      }
      out.values.push_back(std::stod(c, &used));
      if (used != c.size()) return false;
    }
  } catch (const std::exception&) {
    return false;
  }
  return true;
}

std::string header_of(const std::vector<std::string>& columns) {
  std::string h = "index,key";
  for (const auto& c : columns) h += "," + c;
  return h;
}

void read_file_into(const std::string& path, std::size_t n_values, std::map<long, SweepResult>& found,
                    const std::vector<std::string>* columns) {
  const std::string content = read_own_file(path);
  std::size_t start = 0;
  while (start < content.size()) {
    const std::size_t nl = content.find('\n', start);
    if (nl == std::string::npos) break;  // torn last line: no newline, ignore
    const std::string line = content.substr(start, nl - start);
    start = nl + 1;
    if (columns && line.rfind("index,key", 0) == 0 && line != header_of(*columns))
      throw InputError(path + ": its columns (" + line + ") are not this sweep's (" + header_of(*columns) +
                       "): written by another version of railsim or another kind of sweep; delete it and its "
                       ".part files, or give another output folder");
    SweepResult r;
    if (parse_line(line, n_values, r)) found[r.index] = std::move(r);
  }
}

std::string header_line(const SweepOptions& o) { return header_of(o.result_columns); }

}  // namespace

std::vector<SweepResult> read_finished_points(const std::string& output, std::size_t n_values,
                                              const std::vector<std::string>* columns) {
  std::map<long, SweepResult> found;
  read_file_into(output, n_values, found, columns);
  const fs::path out(output);
  const fs::path dir = out.has_parent_path() ? out.parent_path() : fs::path(".");
  std::error_code ec;
  if (fs::exists(dir, ec)) {
    for (const auto& entry : fs::directory_iterator(dir, ec)) {
      const std::string name = entry.path().filename().string();
      const std::string prefix = out.filename().string() + ".part";
      if (name.rfind(prefix, 0) == 0) read_file_into(entry.path().string(), n_values, found, columns);
    }
  }
  std::vector<SweepResult> v;
  for (auto& kv : found) v.push_back(std::move(kv.second));
  return v;
}

std::vector<SweepResult> run_sweep(const std::vector<SweepPoint>& points, const SweepFunction& fn,
                                   const SweepOptions& o) {
  const MpiContext mpi = o.use_mpi ? mpi_context() : MpiContext{};
  const std::size_t nv = o.result_columns.size();
  {
    std::set<long> seen;
    for (const auto& p : points) {
      if (!seen.insert(p.index).second) throw std::logic_error("run_sweep: duplicate point index");
      if (p.key.find_first_of(",\n") != std::string::npos) throw std::logic_error("run_sweep: key with comma");
    }
  }
  const fs::path out(o.output);
  if (out.has_parent_path()) fs::create_directories(out.parent_path());

  // What is already done (from any earlier run, any rank count).
  std::map<long, SweepResult> done;
  for (auto& r : read_finished_points(o.output, nv, &o.result_columns)) done[r.index] = r;
  std::vector<const SweepPoint*> todo;
  for (const auto& p : points) {
    auto it = done.find(p.index);
    if (it != done.end() && it->second.key == p.key) continue;
    todo.push_back(&p);
  }
#ifdef RAILSIM_HAVE_MPI
  // Every rank must see the same finished set before any rank writes new points.
  if (mpi.active) MPI_Barrier(MPI_COMM_WORLD);
#endif
  // Static round-robin assignment of the remaining points to ranks.
  std::vector<const SweepPoint*> mine;
  for (std::size_t i = 0; i < todo.size(); ++i)
    if (static_cast<int>(i % static_cast<std::size_t>(mpi.size)) == mpi.rank) mine.push_back(todo[i]);
  if (mpi.rank == 0 && done.size() > 0)
    spdlog::info("{}: resuming, {} of {} points already finished", o.label, points.size() - todo.size(),
                 points.size());

  const std::string part = o.output + ".part" + std::to_string(mpi.rank);
  AppendFile part_file(part);
  {
    // A torn last line (killed mid-write) is closed off so that it stays a
    // single unreadable line instead of swallowing the next result.
    const std::string old = read_own_file(part);
    if (!old.empty() && old.back() != '\n') part_file.write("\n");
  }
  std::mutex write_mutex;
  std::atomic<std::size_t> next{0}, finished{0}, running{0};
  std::exception_ptr first_error;
  const auto t0 = std::chrono::steady_clock::now();
  auto last_report = t0;

  auto worker = [&] {
    for (;;) {
      const std::size_t i = next.fetch_add(1);
      if (i >= mine.size()) return;
      {
        std::lock_guard<std::mutex> lock(write_mutex);
        if (first_error) return;
      }
      ++running;
      SweepResult r;
      r.index = mine[i]->index;
      r.key = mine[i]->key;
      try {
        r.values = fn(*mine[i]);
        if (r.values.size() != nv) throw std::logic_error("sweep point returned the wrong number of values");
      } catch (...) {
        --running;
        std::lock_guard<std::mutex> lock(write_mutex);
        if (!first_error) first_error = std::current_exception();
        return;
      }
      --running;
      std::lock_guard<std::mutex> lock(write_mutex);
      try {
        part_file.write(result_line(r) + "\n");  // a full disk stops the sweep naming the file
      } catch (...) {
        if (!first_error) first_error = std::current_exception();
        return;
      }
      const std::size_t n_done = ++finished;
      const auto now = std::chrono::steady_clock::now();
      if (std::chrono::duration<double>(now - last_report).count() >= o.progress_interval_s ||
          n_done == mine.size()) {
        last_report = now;
        const double elapsed = std::chrono::duration<double>(now - t0).count();
        const double eta = elapsed / static_cast<double>(n_done) * static_cast<double>(mine.size() - n_done);
        spdlog::info("{}{}: {}/{} points done, {} running, about {:.0f} s left", o.label,
                     mpi.size > 1 ? " (rank " + std::to_string(mpi.rank) + ")" : std::string(), n_done,
                     mine.size(), running.load(), eta);
      }
    }
  };

  int n_threads = o.threads > 0 ? o.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  if (mpi.size > 1 && o.threads <= 0) n_threads = 1;
  n_threads = std::max(1, std::min<int>(n_threads, static_cast<int>(std::max<std::size_t>(1, mine.size()))));
  std::vector<std::thread> pool;
  for (int t = 1; t < n_threads; ++t) pool.emplace_back(worker);
  worker();
  for (auto& th : pool) th.join();
  try {
    part_file.close();
  } catch (...) {
    if (!first_error) first_error = std::current_exception();
  }

#ifdef RAILSIM_HAVE_MPI
  if (mpi.active) MPI_Barrier(MPI_COMM_WORLD);
#endif
  if (first_error) {
    try {
      std::rethrow_exception(first_error);
    } catch (const InterruptedError& e) {
      // Stopped by the user: say what is kept and how to go on.
      throw InterruptedError(o.label + ": " + e.what() + "; " + std::to_string(finished.load()) + " of " +
                             std::to_string(mine.size()) + " points of this run are kept in " + part +
                             " (with those finished before): the same command in the same folder resumes");
    }
  }

  // Gather everything finished (all ranks' parts) and write the merged file on rank 0.
  std::vector<SweepResult> all;
  std::map<long, SweepResult> merged;
  for (auto& r : read_finished_points(o.output, nv)) merged[r.index] = r;
  for (const auto& p : points) {
    auto it = merged.find(p.index);
    if (it == merged.end() || it->second.key != p.key)
      throw NumericalError(o.label + ": point " + p.key + " has no result after the sweep");
    all.push_back(it->second);
  }
  if (mpi.rank == 0) write_sweep_file(o.output, o.result_columns, all);
#ifdef RAILSIM_HAVE_MPI
  if (mpi.active) MPI_Barrier(MPI_COMM_WORLD);
#endif
  // The merged file now holds every point: the part files are no longer needed.
  if (mpi.rank == 0)
    for (int r = 0; r < std::max(mpi.size, 1); ++r) fs::remove(o.output + ".part" + std::to_string(r));
  return all;
}

void write_sweep_file(const std::string& output, const std::vector<std::string>& columns,
                      const std::vector<SweepResult>& rows) {
  SweepOptions o;
  o.result_columns = columns;
  write_file_atomically(output, [&](std::ostream& f) {
    f << header_line(o) << "\n";
    for (const auto& r : rows) f << result_line(r) << "\n";
  });
}

}  // namespace railsim::engine
