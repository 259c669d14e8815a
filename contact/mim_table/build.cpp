// Building a MIM table: one live MIM solve per node on a reference patch
// (mim_table_reference: the registered model "mim", extrapolated from grid N
// and N/2), shared among worker threads, each finished node
// appended to the resume log "<file>.partial" (record: node index, 3 values,
// FNV-1a checksum of both; the log starts with the parameter hash), so an
// interrupted build resumes from the log's valid records; see mim_table.hpp.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <exception>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "contact/hertz.hpp"
#include "contact/kalker_coefficients.hpp"
#include "contact/mim/mim_model.hpp"
#include "contact/mim_table/mim_table.hpp"
#include "contact/mim_table/axes.hpp"
#include "core/atomic_file.hpp"
#include "core/content_hash.hpp"

namespace railsim::contact {

namespace {

using mim_table_detail::s_of_u;
using mim_table_detail::s_of_v;

// FFTW's planner is not thread-safe: a MimSolver plans (and frees plans) when
// its grid changes, i.e. on the first solve for a new a/b, and when destroyed.
// Its convolution serialises those calls with the program-wide
// railsim::fftw_planner_mutex() (core/fftw_planner_lock.hpp), so the table's
// worker threads need no lock of their own (and must not hold that one: it is
// not recursive).


constexpr std::size_t kRecordSize = sizeof(std::uint64_t) + 3 * sizeof(double) + sizeof(std::uint64_t);

void reference_solve(const TangentialModel& model, TangentialWorkspace* ws, const MimTableSpec& spec, double aob,
                     double xi_n, double eta_n, double psi_n, double out[3]) {
  const double c = 6.0e-3, Fz = 75.0e3, mu = 0.3;
  const double a = c * std::sqrt(aob), b = c / std::sqrt(aob);
  ContactInput in;
  in.material = Material{210.0e9, spec.nu, mu};
  in.patch = hertz_from_semi_axes(a, b, Fz, in.material);
  const double G = in.material.shear_modulus();
  const KalkerCoefficients C = kalker_coefficients(aob, spec.nu);
  const double muN = mu * Fz;
  in.creep = {xi_n * 3.0 * muN / (G * c * c * C.C11), eta_n * 3.0 * muN / (G * c * c * C.C22),
              psi_n * muN / (G * c * c * c * C.C23)};
  const ContactForces f = model.solve(in, ws);
  out[0] = f.Fx / muN;
  out[1] = f.Fy / muN;
  out[2] = f.Mz / (muN * c);
}

// The registered model "mim" at the table's grid with Richardson extrapolation
// (contact/mim/mim_model.cpp; solver id kMimTableSolverId).
std::unique_ptr<TangentialModel> reference_model(const MimTableSpec& spec) {
  TangentialModelOptions o;
  o.grid = spec.grid;
  o.tolerance = spec.tolerance;
  o.extrapolation = GridExtrapolation::Richardson;
  return make_mim(o);
}

}  // namespace

void mim_table_reference(const MimTableSpec& spec, double aob, double xi_n, double eta_n, double psi_n,
                         double out[3]) {
  const auto model = reference_model(spec);
  const auto ws = model->make_workspace();
  reference_solve(*model, ws.get(), spec, aob, xi_n, eta_n, psi_n, out);
}

std::unique_ptr<MimTable> MimTable::build(const MimTableSpec& spec, const std::string& partial_path,
                                          const MimTableBuildOptions& options) {
  spec.check();
  auto t = std::make_unique<MimTable>();
  t->spec_ = spec;
  for (double r : spec.aob) t->lnaob_.push_back(std::log(r));
  const std::size_t total = spec.size();
  t->values_.assign(3 * total, 0.0);
  std::vector<char> done(total, 0);
  std::size_t ndone = 0;
  const std::uint64_t spec_hash = spec.hash();

  // Resume from the valid records of an earlier, interrupted build.
  AppendFile log;  // checked writes: a full disk stops the build naming the file
  if (!partial_path.empty()) {
    const std::string old = read_own_file(partial_path);
    bool keep = old.size() >= sizeof(std::uint64_t);
    std::uint64_t h = 0;
    if (keep) std::memcpy(&h, old.data(), sizeof h);
    keep = keep && h == spec_hash;
    std::size_t valid_end = sizeof(std::uint64_t);
    if (keep) {
      for (std::size_t pos = sizeof(std::uint64_t); pos + kRecordSize <= old.size(); pos += kRecordSize) {
        std::uint64_t idx = 0, sum = 0;
        double v[3];
        std::memcpy(&idx, old.data() + pos, sizeof idx);
        std::memcpy(v, old.data() + pos + sizeof idx, sizeof v);
        std::memcpy(&sum, old.data() + pos + sizeof idx + sizeof v, sizeof sum);
        if (sum != fnv1a(old.data() + pos, sizeof idx + sizeof v) || idx >= total) break;  // torn tail
        if (!done[idx]) ++ndone;
        done[idx] = 1;
        std::copy(v, v + 3, &t->values_[3 * idx]);
        valid_end = pos + kRecordSize;
      }
    }
    // Rewrite the log with only its valid part (drops a torn tail or a stale spec).
    log.open(partial_path, AppendFile::Mode::truncate);
    if (keep) {
      log.write(std::string_view(old.data(), valid_end));
    } else {
      log.write(std::string_view(reinterpret_cast<const char*>(&spec_hash), sizeof spec_hash));
      ndone = 0;
      std::fill(done.begin(), done.end(), 0);
    }
  }

  const std::size_t nj = spec.uxi.size(), nk = spec.ueta.size(), nl = spec.vpsi.size();
  std::atomic<std::size_t> next{0};
  std::atomic<bool> stop{false};
  std::mutex mtx;
  std::exception_ptr error;
  std::size_t fresh = 0;
  const auto worker = [&]() {
    std::unique_ptr<TangentialModel> model;
    std::unique_ptr<TangentialWorkspace> solver;
    try {
      model = reference_model(spec);
      solver = model->make_workspace();
      for (;;) {
        if (stop.load()) break;
        const std::size_t idx = next.fetch_add(1);
        if (idx >= total) break;
        if (done[idx]) continue;
        const std::size_t l = idx % nl, k = (idx / nl) % nk, j = (idx / (nl * nk)) % nj, i = idx / (nl * nk * nj);
        double v[3];
        // Node (xi', e', psi') with e' = eta' + psi'/3 (mim_table.hpp).
        const double psi_n = s_of_v(spec.vpsi[l]);
        reference_solve(*model, solver.get(), spec, spec.aob[i], s_of_u(spec.uxi[j]), s_of_u(spec.ueta[k]) - psi_n / 3.0,
                        psi_n, v);
        std::lock_guard<std::mutex> lock(mtx);
        std::copy(v, v + 3, &t->values_[3 * idx]);
        done[idx] = 1;
        ++ndone;
        ++fresh;
        if (log.is_open()) {
          char rec[kRecordSize];
          const std::uint64_t id = idx;
          std::memcpy(rec, &id, sizeof id);
          std::memcpy(rec + sizeof id, v, sizeof v);
          const std::uint64_t sum = fnv1a(rec, sizeof id + sizeof v);
          std::memcpy(rec + sizeof id + sizeof v, &sum, sizeof sum);
          log.write(std::string_view(rec, kRecordSize));
        }
        if (options.progress) options.progress(ndone, total);
        if (options.stop_after > 0 && fresh >= options.stop_after) stop = true;
      }
    } catch (...) {
      std::lock_guard<std::mutex> lock(mtx);
      if (!error) error = std::current_exception();
      stop = true;
    }
    solver.reset();
  };
  int nthreads = options.threads > 0 ? options.threads : static_cast<int>(std::thread::hardware_concurrency());
  nthreads = std::max(1, nthreads);
  std::vector<std::thread> pool;
  for (int n = 0; n < nthreads; ++n) pool.emplace_back(worker);
  for (auto& th : pool) th.join();
  if (!error) log.close();
  if (error) std::rethrow_exception(error);
  if (ndone < total) return nullptr;  // stopped early; the log holds the progress
  return t;
}

}  // namespace railsim::contact
