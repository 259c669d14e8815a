// Cached MIM creep-force tables; see mim_table.hpp.
#include "contact/mim_table.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>
#include <thread>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include "contact/fastsim.hpp"  // check_tangential_input
#include "contact/hertz.hpp"
#include "contact/kalker_coefficients.hpp"
#include "contact/mim/mim_model.hpp"
#include "core/atomic_file.hpp"
#include "core/cache_dir.hpp"
#include "core/content_hash.hpp"
#include "core/errors.hpp"

namespace railsim::contact {

namespace {

constexpr char kMagic[8] = {'R', 'S', 'M', 'I', 'M', 'T', 'A', 'B'};

// Little byte writer/reader for the table file.
struct Bytes {
  std::string buf;
  template <class T>
  void put(const T& v) {
    buf.append(reinterpret_cast<const char*>(&v), sizeof(T));
  }
  void put_vec(const std::vector<double>& v) {
    put(static_cast<std::uint32_t>(v.size()));
    buf.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(double));
  }
};
struct Reader {
  const std::string& buf;
  std::size_t pos = 0;
  bool ok = true;
  template <class T>
  T get() {
    T v{};
    if (pos + sizeof(T) > buf.size()) {
      ok = false;
      return v;
    }
    std::memcpy(&v, buf.data() + pos, sizeof(T));
    pos += sizeof(T);
    return v;
  }
  std::vector<double> get_vec() {
    const auto n = get<std::uint32_t>();
    std::vector<double> v;
    if (!ok || n > 100000 || pos + n * sizeof(double) > buf.size()) {
      ok = false;
      return v;
    }
    v.resize(n);
    std::memcpy(v.data(), buf.data() + pos, n * sizeof(double));
    pos += n * sizeof(double);
    return v;
  }
};

std::vector<double> uniform(double lo, double hi, int n) {
  std::vector<double> v(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) v[static_cast<std::size_t>(i)] = lo + (hi - lo) * i / (n - 1);
  return v;
}

bool ascending(const std::vector<double>& v) {
  for (std::size_t i = 1; i < v.size(); ++i)
    if (!(v[i] > v[i - 1])) return false;
  return true;
}

// Cubic Hermite weights (finite-difference slopes) of up to 4 nodes around x.
struct AxisWeights {
  std::size_t idx[4] = {0, 0, 0, 0};
  double w[4] = {0, 0, 0, 0};
};
AxisWeights axis_weights(const std::vector<double>& t, double x) {
  AxisWeights a;
  const std::size_t n = t.size();
  if (n == 1) {
    a.w[1] = 1.0;
    return a;
  }
  x = std::clamp(x, t.front(), t.back());
  std::size_t i = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), x) - t.begin());
  i = std::min(std::max<std::size_t>(i, 1), n - 1) - 1;  // interval [t_i, t_i+1]
  const double h = t[i + 1] - t[i];
  const double s = (x - t[i]) / h;
  const double s2 = s * s, s3 = s2 * s;
  const double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s, h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
  // local slots: 0 -> i-1, 1 -> i, 2 -> i+1, 3 -> i+2
  a.idx[0] = i > 0 ? i - 1 : i;
  a.idx[1] = i;
  a.idx[2] = i + 1;
  a.idx[3] = i + 2 < n ? i + 2 : i + 1;
  a.w[1] += h00;
  a.w[2] += h01;
  const double c1 = h10 * h, c2 = h11 * h;
  if (i > 0) {
    const double d = t[i + 1] - t[i - 1];
    a.w[2] += c1 / d;
    a.w[0] -= c1 / d;
  } else {
    a.w[2] += c1 / h;
    a.w[1] -= c1 / h;
  }
  if (i + 2 < n) {
    const double d = t[i + 2] - t[i];
    a.w[3] += c2 / d;
    a.w[1] -= c2 / d;
  } else {
    a.w[2] += c2 / h;
    a.w[1] -= c2 / h;
  }
  return a;
}

inline double u_of(double s) { return s / (1.0 + s); }
inline double v_of(double s) { return s / (1.0 + std::abs(s)); }
inline double s_of_u(double u) { return u / (1.0 - u); }
inline double s_of_v(double v) { return v / (1.0 - std::abs(v)); }

// FFTW's planner is not thread-safe: a MimSolver plans (and frees plans) when
// its grid changes, i.e. on the first solve for a new a/b, and when destroyed.
// Its convolution serialises those calls with the program-wide
// railsim::fftw_planner_mutex() (core/fftw_planner_lock.hpp), so the table's
// worker threads need no lock of their own (and must not hold that one: it is
// not recursive).

constexpr std::size_t kRecordSize = sizeof(std::uint64_t) + 3 * sizeof(double) + sizeof(std::uint64_t);

}  // namespace

// ---------------------------------------------------------------- spec

MimTableSpec MimTableSpec::standard() {
  MimTableSpec s;
  s.aob = {0.2, 0.3, 0.45, 0.7, 1.0, 1.4, 2.2, 3.3, 5.0};
  s.uxi = uniform(0.0, 0.9, 13);  // xi' up to 9 (far into full slip)
  s.ueta = uniform(0.0, 0.9, 13);
  s.vpsi = uniform(-0.9, 0.9, 37);
  s.grid = 28;  // FFT sizes 64 x (64 ... 320): fast; MIM within about 1 % of mu N of grid 60
  return s;
}

void MimTableSpec::check() const {
  const auto bad = [](const std::string& m) { throw InputError("mim_table: " + m); };
  if (aob.empty() || uxi.empty() || ueta.empty() || vpsi.empty()) bad("every table axis needs at least one node");
  if (!ascending(aob) || !ascending(uxi) || !ascending(ueta) || !ascending(vpsi)) bad("axis nodes must ascend");
  if (aob.front() <= 0.0) bad("a/b nodes must be positive");
  if (uxi.front() != 0.0 || ueta.front() != 0.0 || uxi.back() >= 1.0 || ueta.back() >= 1.0)
    bad("u(xi'), u(eta') nodes must start at 0 and stay below 1");
  if (vpsi.front() <= -1.0 || vpsi.back() >= 1.0) bad("v(psi') nodes must lie in (-1, 1)");
  if (!(nu > 0.0 && nu <= 0.5)) bad("nu must lie in (0, 0.5]");
  if (grid < 4 || grid > 4000) bad("grid must lie in [4, 4000]");
  if (!(tolerance > 0.0 && tolerance <= 0.1)) bad("tolerance must lie in (0, 0.1]");
}

std::uint64_t MimTableSpec::hash() const {
  Bytes b;
  b.put_vec(aob);
  b.put_vec(uxi);
  b.put_vec(ueta);
  b.put_vec(vpsi);
  b.put(nu);
  b.put(grid);
  b.put(tolerance);
  b.put(kMimTableFormatVersion);
  b.buf += kMimTableSolverId;
  return fnv1a(b.buf.data(), b.buf.size());
}

// ---------------------------------------------------------------- reference solve

namespace {
void reference_solve(mim::MimSolver& solver, const MimTableSpec& spec, double aob, double xi_n, double eta_n,
                     double psi_n, double out[3]) {
  const double c = 6.0e-3, Fz = 75.0e3, mu = 0.3;
  const double a = c * std::sqrt(aob), b = c / std::sqrt(aob);
  const Material m{210.0e9, spec.nu, mu};
  const HertzPatch patch = hertz_from_semi_axes(a, b, Fz, m);
  const double G = m.shear_modulus();
  const KalkerCoefficients C = kalker_coefficients(aob, spec.nu);
  const double muN = mu * Fz;
  const Creepages cr{xi_n * 3.0 * muN / (G * c * c * C.C11), eta_n * 3.0 * muN / (G * c * c * C.C22),
                     psi_n * muN / (G * c * c * c * C.C23)};
  const mim::MimSolution& s = solver.solve_hertz(patch, cr, m);
  out[0] = s.Fx / muN;
  out[1] = s.Fy / muN;
  out[2] = s.Mz / (muN * c);
}
mim::MimOptions solver_options(const MimTableSpec& spec) {
  mim::MimOptions o;
  o.grid = spec.grid;
  o.tolerance = spec.tolerance;
  return o;
}
}  // namespace

void mim_table_reference(const MimTableSpec& spec, double aob, double xi_n, double eta_n, double psi_n,
                         double out[3]) {
  mim::MimSolver solver(solver_options(spec));
  reference_solve(solver, spec, aob, xi_n, eta_n, psi_n, out);
}

// ---------------------------------------------------------------- build

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
    std::unique_ptr<mim::MimSolver> solver;
    try {
      solver = std::make_unique<mim::MimSolver>(solver_options(spec));
      for (;;) {
        if (stop.load()) break;
        const std::size_t idx = next.fetch_add(1);
        if (idx >= total) break;
        if (done[idx]) continue;
        const std::size_t l = idx % nl, k = (idx / nl) % nk, j = (idx / (nl * nk)) % nj, i = idx / (nl * nk * nj);
        double v[3];
        // Node (xi', e', psi') with e' = eta' + psi'/3 (mim_table.hpp).
        const double psi_n = s_of_v(spec.vpsi[l]);
        reference_solve(*solver, spec, spec.aob[i], s_of_u(spec.uxi[j]), s_of_u(spec.ueta[k]) - psi_n / 3.0,
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

// ---------------------------------------------------------------- file

void MimTable::save(const std::string& path) const {
  Bytes b;
  b.buf.append(kMagic, sizeof kMagic);
  b.put(kMimTableFormatVersion);
  const std::string id = kMimTableSolverId;
  b.put(static_cast<std::uint32_t>(id.size()));
  b.buf += id;
  b.put(spec_.nu);
  b.put(static_cast<std::int32_t>(spec_.grid));
  b.put(spec_.tolerance);
  b.put_vec(spec_.aob);
  b.put_vec(spec_.uxi);
  b.put_vec(spec_.ueta);
  b.put_vec(spec_.vpsi);
  b.put(static_cast<std::uint64_t>(values_.size()));
  b.buf.append(reinterpret_cast<const char*>(values_.data()), values_.size() * sizeof(double));
  b.put(fnv1a(b.buf.data(), b.buf.size()));
  try {
    write_file_atomically(path, b.buf);
  } catch (const InputError& e) {
    throw InputError(std::string("mim_table: ") + e.what());
  }
}

std::unique_ptr<MimTable> MimTable::load(const std::string& path, const MimTableSpec& expected) {
  const auto refuse = [&](const std::string& why) -> std::unique_ptr<MimTable> {
    throw InputError("mim_table: table file '" + path + "' " + why);
  };
  if (!std::filesystem::exists(path)) return refuse("does not exist");
  const std::string buf = read_own_file(path);
  if (buf.size() < sizeof kMagic + sizeof(std::uint64_t) || std::memcmp(buf.data(), kMagic, sizeof kMagic) != 0)
    return refuse("is not a railsim MIM table (bad magic or empty)");
  std::uint64_t stored = 0;
  std::memcpy(&stored, buf.data() + buf.size() - sizeof stored, sizeof stored);
  Reader r{buf, sizeof kMagic};
  const auto version = r.get<std::uint32_t>();
  if (r.ok && version != kMimTableFormatVersion)
    return refuse("has format version " + std::to_string(version) + ", expected " +
                  std::to_string(kMimTableFormatVersion));
  if (stored != fnv1a(buf.data(), buf.size() - sizeof stored))
    return refuse("is truncated or corrupt (content hash mismatch)");
  const auto idlen = r.get<std::uint32_t>();
  std::string id;
  if (r.ok && idlen < 1000 && r.pos + idlen <= buf.size()) {
    id.assign(buf.data() + r.pos, idlen);
    r.pos += idlen;
  } else {
    r.ok = false;
  }
  auto t = std::make_unique<MimTable>();
  MimTableSpec& s = t->spec_;
  s.nu = r.get<double>();
  s.grid = r.get<std::int32_t>();
  s.tolerance = r.get<double>();
  s.aob = r.get_vec();
  s.uxi = r.get_vec();
  s.ueta = r.get_vec();
  s.vpsi = r.get_vec();
  const auto nvals = r.get<std::uint64_t>();
  if (!r.ok || nvals != 3 * s.size() || r.pos + nvals * sizeof(double) + sizeof stored != buf.size())
    return refuse("is truncated or malformed");
  if (id != kMimTableSolverId) return refuse("was built by solver '" + id + "', expected '" + kMimTableSolverId + "'");
  if (std::abs(s.nu - expected.nu) > 1e-12)
    return refuse("was built for Poisson's ratio " + std::to_string(s.nu) + ", expected " + std::to_string(expected.nu));
  if (s.grid != expected.grid || s.tolerance != expected.tolerance || s.aob != expected.aob ||
      s.uxi != expected.uxi || s.ueta != expected.ueta || s.vpsi != expected.vpsi)
    return refuse("was built with other grid, tolerance or table nodes");
  t->values_.resize(nvals);
  std::memcpy(t->values_.data(), buf.data() + r.pos, nvals * sizeof(double));
  for (double v : s.aob) t->lnaob_.push_back(std::log(v));
  return t;
}

// ---------------------------------------------------------------- lookup

const double* MimTable::node(std::size_t i, std::size_t j, std::size_t k, std::size_t l) const {
  const std::size_t nj = spec_.uxi.size(), nk = spec_.ueta.size(), nl = spec_.vpsi.size();
  return &values_[3 * (((i * nj + j) * nk + k) * nl + l)];
}

void MimTable::lookup(double aob, double xi_n, double e_n, double psi_n, double out[3]) const {
  const AxisWeights A = axis_weights(lnaob_, std::log(aob));
  const AxisWeights X = axis_weights(spec_.uxi, u_of(std::max(0.0, xi_n)));
  const AxisWeights E = axis_weights(spec_.ueta, u_of(std::max(0.0, e_n)));
  const AxisWeights P = axis_weights(spec_.vpsi, v_of(psi_n));
  double f0 = 0.0, f1 = 0.0, f2 = 0.0;
  for (int a = 0; a < 4; ++a) {
    if (A.w[a] == 0.0) continue;
    for (int x = 0; x < 4; ++x) {
      const double wax = A.w[a] * X.w[x];
      if (wax == 0.0) continue;
      for (int e = 0; e < 4; ++e) {
        const double waxe = wax * E.w[e];
        if (waxe == 0.0) continue;
        for (int p = 0; p < 4; ++p) {
          const double w = waxe * P.w[p];
          if (w == 0.0) continue;
          const double* v = node(A.idx[a], X.idx[x], E.idx[e], P.idx[p]);
          f0 += w * v[0];
          f1 += w * v[1];
          f2 += w * v[2];
        }
      }
    }
  }
  out[0] = f0;
  out[1] = f1;
  out[2] = f2;
}

ContactForces MimTableModel::compute(const ContactInput& in, TangentialWorkspace* /*ws*/) const {
  ContactForces f;
  if (!check_tangential_input(in, "mim_table") || in.material.mu == 0.0) return f;
  const MimTableSpec& s = table_->spec();
  const double a = in.patch.a, b = in.patch.b, aob = a / b;
  const double c = std::sqrt(a * b), G = in.material.shear_modulus(), muN = in.material.mu * in.patch.Fz;
  const KalkerCoefficients C = kalker_coefficients(aob, s.nu);
  const ReductionFactors& k = in.reduction;
  double xi = G * c * c * k.k11 * C.C11 * in.creep.xi / (3.0 * muN);
  const double eta = G * c * c * k.k22 * C.C22 * in.creep.eta / (3.0 * muN);
  double psi = G * c * c * c * k.k23 * C.C23 * in.creep.phi / muN;
  double e = eta + psi / 3.0;                // the table's lateral axis (mim_table.hpp)
  const double sx = xi < 0.0 ? -1.0 : 1.0;  // (-xi, eta, phi) -> (-Fx, Fy, Mz)
  const double sy = e < 0.0 ? -1.0 : 1.0;   // (xi, -eta, -phi) -> (Fx, -Fy, -Mz)
  xi *= sx;
  e *= sy;
  psi *= sy;
  double v[3];
  table_->lookup(aob, xi, e, psi, v);
  f.Fx = sx * v[0] * muN;
  f.Fy = sy * v[1] * muN;
  f.Mz = sy * v[2] * muN * c;
  if (aob < s.aob.front() * (1 - 1e-9) || aob > s.aob.back() * (1 + 1e-9)) {
    f.valid = false;
    f.reason = "mim_table: a/b outside the table (value held at the edge)";
  } else if (std::abs(in.material.nu - s.nu) > 0.02) {
    f.valid = false;
    f.reason = "mim_table: Poisson's ratio differs from the table's";
  }
  return f;
}

// ---------------------------------------------------------------- cache

std::string mim_table_cache_dir(const std::string& configured) { return cache_dir(configured, "mim_table"); }

std::string mim_table_cache_path(const MimTableSpec& spec, const std::string& configured_cache_dir) {
  char name[64];
  std::snprintf(name, sizeof name, "mim_table_%016llx.bin", static_cast<unsigned long long>(spec.hash()));
  return mim_table_cache_dir(configured_cache_dir) + "/" + name;
}

namespace {

// Exclusive advisory lock on "<table>.lock" (flock) while a table is loaded or
// built, so that concurrent processes (MPI ranks, two users of one cache) and
// threads build it once: the others wait and then load the finished file.
class TableFileLock {
 public:
  explicit TableFileLock(const std::string& path) : fd_(::open((path + ".lock").c_str(), O_RDWR | O_CREAT, 0644)) {
    if (fd_ >= 0 && ::flock(fd_, LOCK_EX) != 0) {
      ::close(fd_);
      fd_ = -1;
    }
  }
  ~TableFileLock() {
    if (fd_ >= 0) {
      ::flock(fd_, LOCK_UN);
      ::close(fd_);
    }
  }
  TableFileLock(const TableFileLock&) = delete;
  TableFileLock& operator=(const TableFileLock&) = delete;

 private:
  int fd_;  // -1: no lock (read-only cache folder): each caller builds on its own
};

}  // namespace

std::shared_ptr<const MimTable> load_or_build_mim_table(const MimTableSpec& spec, const std::string& cache_dir,
                                                        const std::function<void(const std::string&)>& log) {
  spec.check();
  const std::string path = mim_table_cache_path(spec, cache_dir);
  const TableFileLock lock(path);
  if (std::filesystem::exists(path)) {
    try {
      return MimTable::load(path, spec);
    } catch (const InputError& e) {
      if (log) log(std::string(e.what()) + "; rebuilding it");
    }
  } else if (log) {
    log("mim_table: building " + path + " (" + std::to_string(spec.size()) + " exact solves, grid " +
        std::to_string(spec.grid) + ")");
  }
  MimTableBuildOptions o;
  std::size_t last = 0;
  o.progress = [&](std::size_t done, std::size_t total) {
    if (log && (done * 20 / total != last * 20 / total || done == total))
      log("mim_table: " + std::to_string(done) + " / " + std::to_string(total) + " nodes");
    last = done;
  };
  const std::string partial = path + ".partial";
  auto t = MimTable::build(spec, partial, o);
  t->save(path);
  std::error_code ec;
  std::filesystem::remove(partial, ec);
  return t;
}

std::unique_ptr<TangentialModel> make_mim_table(const TangentialModelOptions& options) {
  MimTableSpec spec = MimTableSpec::standard();
  if (options.grid != 0) spec.grid = options.grid;
  if (options.tolerance != 0.0) spec.tolerance = options.tolerance;
  auto table = load_or_build_mim_table(spec, options.cache_dir,
                                       [](const std::string& m) { std::fprintf(stderr, "%s\n", m.c_str()); });
  return std::make_unique<MimTableModel>(std::move(table));
}

}  // namespace railsim::contact
