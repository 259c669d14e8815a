// Strip-wise contact table; see strip_contact_table.hpp.
#include "contact/geometry/strip_contact_table.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>
#include <thread>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>

#include <boost/math/interpolators/cardinal_cubic_b_spline.hpp>
#include <boost/math/interpolators/cubic_hermite.hpp>

#include "contact/hertz.hpp"
#include "core/atomic_file.hpp"
#include "core/cache_dir.hpp"
#include "core/content_hash.hpp"
#include "core/errors.hpp"

namespace railsim::contact {

namespace {
constexpr char kMagic[8] = {'R', 'S', 'S', 'T', 'R', 'P', '0', '4'};

// Cubic Hermite basis on a cell of width h at t in [0, 1]: values
// (h00 f_a + h10 f'_a + h01 f_b + h11 f'_b) and derivatives d/dy
// (d00 f_a + d10 f'_a - d00 f_b + d11 f'_b).
struct HermiteBasis {
  double h00, h10, h01, h11, d00, d10, d11;
  HermiteBasis(double t, double h) {
    const double t2 = t * t, t3 = t2 * t;
    h00 = 2 * t3 - 3 * t2 + 1;
    h10 = (t3 - 2 * t2 + t) * h;
    h01 = -2 * t3 + 3 * t2;
    h11 = (t3 - t2) * h;
    d00 = (6 * t2 - 6 * t) / h;
    d10 = 3 * t2 - 4 * t + 1;
    d11 = 3 * t2 - 2 * t;
  }
};

std::string num(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}


// Hertz's constant K = N / delta^{3/2} = E* A^{-1/2} g(B/A) and the Winkler
// factor f(B/A) = (3/4) K sqrt(B) / E* = (3/4) g sqrt(B/A), tabulated in
// ln(B/A) on [ln 0.01, ln 100] from the exact Hertz solution (contact/hertz.hpp;
// E* = E / (2 (1 - nu^2)); both are material-free).
class HertzRatioTable {
 public:
  HertzRatioTable() {
    const Material m;
    const double Es = m.E / (2.0 * (1.0 - m.nu * m.nu));
    constexpr int n = 201;
    lo_ = std::log(0.01);
    h_ = (std::log(100.0) - lo_) / (n - 1);
    hi_ = lo_ + (n - 1) * h_;
    std::vector<double> lg(n), al(n), be(n);
    for (int i = 0; i < n; ++i) {
      const double B = std::exp(lo_ + i * h_);
      const HertzPatch p = hertz_from_load(1.0, B, 1e4, m);
      lg[std::size_t(i)] = std::log(1e4 / std::pow(p.approach, 1.5) / Es);
      al[std::size_t(i)] = p.a / std::sqrt(p.approach);
      be[std::size_t(i)] = p.b / std::sqrt(p.approach / B);
    }
    lng_ = lg;
    spline_ = boost::math::interpolators::cardinal_cubic_b_spline<double>(lg.begin(), lg.end(), lo_, h_);
    // The semi-axis factors are evaluated per patch and right-hand side: the
    // same cubic splines (interpolating, so cubic per cell with the spline's
    // node values and slopes) held in Hermite form, a few dozen instructions
    // per evaluation instead of Boost's B-spline basis sums.
    const boost::math::interpolators::cardinal_cubic_b_spline<double> alpha(al.begin(), al.end(), lo_, h_),
        beta(be.begin(), be.end(), lo_, h_);
    std::vector<double> dal(n), dbe(n);
    for (int i = 0; i < n; ++i) {
      dal[std::size_t(i)] = alpha.prime(lo_ + i * h_);
      dbe[std::size_t(i)] = beta.prime(lo_ + i * h_);
    }
    alpha_ = std::make_unique<Hermite>(std::move(al), std::move(dal), lo_, h_);
    beta_ = std::make_unique<Hermite>(std::move(be), std::move(dbe), lo_, h_);
    axes_hi_ = std::min(alpha_->domain().second, beta_->domain().second);  // hi_ within Boost's rounding
  }
  double g(double ratio) const { return std::exp(spline_(std::clamp(std::log(ratio), lo_, hi_))); }
  double ratio(double g) const {
    const double x = std::log(g);
    if (x <= lng_.front()) return std::exp(lo_);
    if (x >= lng_.back()) return std::exp(hi_);
    const auto it = std::upper_bound(lng_.begin(), lng_.end(), x);
    const auto i = std::size_t(it - lng_.begin()) - 1;
    // Linear in the table, then one Newton step on the spline.
    double u = lo_ + (double(i) + (x - lng_[i]) / (lng_[i + 1] - lng_[i])) * h_;
    const double d = spline_.prime(u);
    if (d > 0) u = std::clamp(u - (spline_(u) - x) / d, lo_, hi_);
    return std::exp(u);
  }

  void axes(double ratio, double& a, double& b) const {
    const double u = std::clamp(std::log(ratio), lo_, axes_hi_);
    a = (*alpha_)(u);
    b = (*beta_)(u);
  }

 private:
  using Hermite = boost::math::interpolators::cardinal_cubic_hermite<std::vector<double>>;
  boost::math::interpolators::cardinal_cubic_b_spline<double> spline_;
  std::unique_ptr<Hermite> alpha_, beta_;
  double axes_hi_ = 0.0;
  std::vector<double> lng_;
  double lo_ = 0.0, hi_ = 0.0, h_ = 1.0;
};
const HertzRatioTable& hertz_ratio_table() {
  static const HertzRatioTable table;
  return table;
}
}  // namespace

double StripContactTable::hertz_stiffness_factor(double B_over_A) {
  return hertz_ratio_table().g(std::clamp(B_over_A, 0.01, 100.0));
}
double StripContactTable::ratio_for_stiffness_factor(double g) { return hertz_ratio_table().ratio(g); }
void StripContactTable::hertz_axis_factors(double r, double& alpha, double& beta) {
  hertz_ratio_table().axes(std::clamp(r, 0.01, 100.0), alpha, beta);
}
double StripContactTable::winkler_factor(double B_over_A) {
  const double r = std::clamp(B_over_A, 0.01, 100.0);
  return 0.75 * hertz_ratio_table().g(r) * std::sqrt(r);
}

void StripTableGrid::validate() const {
  auto check = [](bool ok, const std::string& what) {
    if (!ok) throw InputError("strip contact table: " + what);
  };
  check(std::isfinite(y_min) && std::isfinite(y_max) && y_min >= -0.05 && y_max <= 0.05 && y_min < 0 && y_max > 0,
        "y range [" + num(y_min) + ", " + num(y_max) + "] m: expected -0.05 <= y_min < 0 < y_max <= 0.05 m");
  check(std::isfinite(y_step) && y_step >= 1e-5 && y_step <= 1e-3,
        "y step " + num(y_step) + " m: expected a value in [1e-5, 1e-3] m");
  check((y_max - y_min) / y_step <= 20000, "more than 20000 rows requested");
  check(std::isfinite(yaw_max) && yaw_max >= 0 && yaw_max <= 0.1,
        "yaw_max " + num(yaw_max) + " rad: expected a value in [0, 0.1] rad");
  check(std::isfinite(yaw_step) && yaw_step >= 1e-4 && yaw_step <= 0.05,
        "yaw_step " + num(yaw_step) + " rad: expected a value in [1e-4, 0.05] rad");
  check(std::isfinite(strip) && strip >= 1e-4 && strip <= 5e-3,
        "strip width " + num(strip) + " m: expected a value in [1e-4, 5e-3] m");
  check(std::isfinite(gap_store) && gap_store >= 2e-4 && gap_store <= 1e-2,
        "gap_store " + num(gap_store) + " m: expected a value in [2e-4, 1e-2] m");
}

StripContactTable StripContactTable::build(const WheelRailGeometry& g, const StripTableGrid& grid) {
  grid.validate();
  StripContactTable t;
  t.grid_ = grid;
  t.ny_ = int(std::floor((grid.y_max - grid.y_min) / grid.y_step + 1e-9)) + 1;
  t.nk_ = grid.yaw_max > 0 ? int(std::floor(grid.yaw_max / grid.yaw_step + 1e-9)) + 1 : 1;
  t.grid_.y_max = grid.y_min + (t.ny_ - 1) * grid.y_step;
  t.grid_.yaw_max = (t.nk_ - 1) * grid.yaw_step;
  t.t0_ = g.wheel_t_min();
  t.strips_total_ = int(std::floor((g.wheel_t_max() - t.t0_) / grid.strip)) + 1;
  const int ns = t.strips_total_;
  t.y_wheel_.resize(std::size_t(ns));
  for (int j = 0; j < ns; ++j) t.y_wheel_[std::size_t(j)] = g.wheel_profile().spline().eval(t.t0_ + j * grid.strip).y;
  // Full raw data per node: roll, z and per strip (v, angle, lateral, lead, height, A, f).
  struct Raw {
    double roll = 0, z = 0;
    std::vector<double> v, angle, lateral, lead, height, A, f;
  };
  std::vector<Raw> raw(std::size_t(t.nk_) * std::size_t(t.ny_));
  // Nodes are independent: solved on all cores (the search is const and
  // allocation-local); the first error is reported.
  std::atomic<std::size_t> next{0};
  std::mutex error_mutex;
  std::string error;
  auto worker = [&]() {
    for (;;) {
      const std::size_t node = next++;
      if (node >= raw.size()) return;
      const int k = int(node / std::size_t(t.ny_)), i = int(node % std::size_t(t.ny_));
      const double psi = k * grid.yaw_step;
      const double y = grid.y_min + i * grid.y_step;
      WheelsetContact c;
      try {
        c = g.solve(y, psi);
      } catch (const InputError& e) {
        std::lock_guard<std::mutex> lock(error_mutex);
        if (error.empty())
          error = std::string(e.what()) + " (strip contact table node y = " + num(y * 1e3) + " mm, yaw = " +
                  num(psi * 1e3) + " mrad: narrow the table's y range (max_shift) or its yaw range (max_yaw))";
        next = raw.size();
        return;
      }
      Raw& r = raw[node];
      r.roll = c.roll;
      r.z = c.z[0];
      for (auto* vec : {&r.v, &r.angle, &r.lateral, &r.lead, &r.height, &r.A, &r.f}) vec->resize(std::size_t(ns));
      for (int j = 0; j < ns; ++j) {
        const ContactPoint p = g.point_at(Side::left, t.t0_ + j * grid.strip, y, c.z[0], c.roll, psi);
        const double cd = std::cos(p.angle);
        const std::size_t jj = std::size_t(j);
        // Normal gap; off the rail (no rail below the point): far away.
        r.v[jj] = std::isfinite(p.gap) && cd > 0 ? std::clamp(p.gap, 0.0, 2.0 * grid.gap_store) : 2.0 * grid.gap_store;
        r.angle[jj] = p.angle;
        r.lateral[jj] = p.y - y;
        // Lead in the wheelset's frame (ahead of the axle's vertical plane), not
        // the track-frame x, which also holds the yaw rotation of the lateral
        // position (-psi a): the creepages' spin term -x Omega needs the former.
        r.lead[jj] = p.x * std::cos(psi) + (p.y - y) * std::sin(psi);
        r.height[jj] = p.height;
        r.A[jj] = p.A;
        r.f[jj] = winkler_factor(p.B / p.A);
      }
    }
  };
  const unsigned nthreads = std::max(1u, std::min(8u, std::thread::hardware_concurrency()));
  std::vector<std::thread> pool;
  for (unsigned n = 1; n < nthreads; ++n) pool.emplace_back(worker);
  worker();
  for (auto& th : pool) th.join();
  if (!error.empty()) throw InputError(error);
  // The centred wheelset's axle height is the reference of the pose.
  const Raw& centre = raw[std::size_t(std::lround(-grid.y_min / grid.y_step))];
  const double z0 = centre.z;
  // Stored ranges: strips with v < gap_store at this node or its neighbours in y and yaw.
  auto idx = [&](int k, int i) { return std::size_t(k) * std::size_t(t.ny_) + std::size_t(i); };
  t.rows_.resize(raw.size());
  std::vector<Entry> entries;
  for (int k = 0; k < t.nk_; ++k)
    for (int i = 0; i < t.ny_; ++i) {
      int j0 = ns, j1 = -1;
      for (int kk = std::max(0, k - 1); kk <= std::min(t.nk_ - 1, k + 1); ++kk)
        for (int ii = std::max(0, i - 1); ii <= std::min(t.ny_ - 1, i + 1); ++ii) {
          const Raw& r = raw[idx(kk, ii)];
          for (int j = 0; j < ns; ++j)
            if (r.v[std::size_t(j)] < grid.gap_store) {
              j0 = std::min(j0, j);
              j1 = std::max(j1, j);
            }
        }
      Row& row = t.rows_[idx(k, i)];
      row.j0 = std::max(0, j0 - 1);
      row.j1 = std::min(ns - 1, j1 + 1);
      const Raw& r = raw[idx(k, i)];
      const Raw& rl = raw[idx(k, std::max(0, i - 1))];
      const Raw& rr = raw[idx(k, std::min(t.ny_ - 1, i + 1))];
      const double span = (std::min(t.ny_ - 1, i + 1) - std::max(0, i - 1)) * grid.y_step;
      row.roll = r.roll;
      row.z = r.z - z0;
      row.droll = (rr.roll - rl.roll) / span;
      row.dz = (rr.z - rl.z) / span;
      row.offset = entries.size();
      // Centred slope limited as Fritsch & Carlson: zero at a local extremum
      // of the rows, at most three times either secant.
      auto limited = [&](double fl, double f0, double fr) {
        const double m = (fr - fl) / span;
        if (i == 0 || i == t.ny_ - 1) return m;
        const double dl = (f0 - fl) / grid.y_step, dr = (fr - f0) / grid.y_step;
        if (dl * dr <= 0.0) return 0.0;
        return std::copysign(std::min({std::abs(m), 3.0 * std::abs(dl), 3.0 * std::abs(dr)}), dl);
      };
      for (int j = row.j0; j <= row.j1; ++j) {
        const std::size_t jj = std::size_t(j);
        Entry e;
        e.gap = r.v[jj];
        e.dgap = limited(rl.v[jj], r.v[jj], rr.v[jj]);
        e.angle = r.angle[jj];
        e.dangle = limited(rl.angle[jj], r.angle[jj], rr.angle[jj]);
        e.lateral = r.lateral[jj];
        e.dlateral = limited(rl.lateral[jj], r.lateral[jj], rr.lateral[jj]);
        e.lead = r.lead[jj];
        e.dlead = limited(rl.lead[jj], r.lead[jj], rr.lead[jj]);
        e.height = r.height[jj];
        e.dheight = limited(rl.height[jj], r.height[jj], rr.height[jj]);
        e.A = r.A[jj];
        e.dA = limited(rl.A[jj], r.A[jj], rr.A[jj]);
        e.f = r.f[jj];
        e.df = limited(rl.f[jj], r.f[jj], rr.f[jj]);
        entries.push_back(e);
      }
    }
  t.unpack(entries);
  return t;
}

void StripContactTable::unpack(const std::vector<Entry>& entries) {
  static_assert(sizeof(Entry) == kColumns * sizeof(double), "Entry is kColumns doubles");
  entries_ = entries.size();
  cols_.assign(entries_ * kColumns + kLanes, 0.0);  // + kLanes: strips() reads whole lane groups
  for (std::size_t n = 0; n < entries_; ++n) {
    const double* e = &entries[n].gap;
    for (int c = 0; c < kColumns; ++c) cols_[std::size_t(c) * entries_ + n] = e[c];
  }
  index_near_ranges();
}

std::vector<StripContactTable::Entry> StripContactTable::pack() const {
  std::vector<Entry> entries(entries_);
  for (std::size_t n = 0; n < entries_; ++n) {
    double* e = &entries[n].gap;
    for (int c = 0; c < kColumns; ++c) e[c] = cols_[std::size_t(c) * entries_ + n];
  }
  return entries;
}

void StripContactTable::index_near_ranges() {
  near_.assign(rows_.size() * kNearLevels, NearRange{});
  for (std::size_t r = 0; r < rows_.size(); ++r) {
    const Row& row = rows_[r];
    for (int L = 0; L < kNearLevels; ++L) {
      NearRange& nr = near_[r * kNearLevels + std::size_t(L)];
      for (int j = row.j0; j <= row.j1; ++j)
        if (column(2 * kGap)[row.offset + std::size_t(j - row.j0)] <= kNearGap[L]) {
          if (nr.j1 < nr.j0) nr.j0 = j;
          nr.j1 = j;
        }
    }
  }
}

void StripContactTable::locate(double y, double psi, int& i, double& t, int& k, double& wpsi, double& apsi) const {
  const double u = std::clamp((y - grid_.y_min) / grid_.y_step, 0.0, double(ny_ - 1));
  i = std::min(int(u), ny_ - 2);
  t = u - i;
  apsi = std::min(std::abs(psi), grid_.yaw_max);
  if (nk_ == 1) {
    k = 0;
    wpsi = 0.0;
    return;
  }
  const double q = apsi / grid_.yaw_step;
  k = std::min(int(q), nk_ - 2);
  const double p0 = k * grid_.yaw_step, p1 = (k + 1) * grid_.yaw_step;
  wpsi = (apsi * apsi - p0 * p0) / (p1 * p1 - p0 * p0);  // linear in psi^2
}

bool StripContactTable::in_range(double y, double psi) const {
  return y >= grid_.y_min && y <= grid_.y_max && std::abs(psi) <= grid_.yaw_max + 1e-12;
}

void StripContactTable::pose(double y, double psi, StripPose& out) const {
  int i, k;
  double t, w, apsi;
  locate(y, psi, i, t, k, w, apsi);
  const HermiteBasis H(t, grid_.y_step);
  const double h00 = H.h00, h10 = H.h10, h01 = H.h01, h11 = H.h11, d00 = H.d00, d10 = H.d10, d11 = H.d11;
  auto at = [&](int kk, double& roll, double& droll, double& z, double& dz) {
    const Row& a = row(kk, i);
    const Row& b = row(kk, i + 1);
    roll = h00 * a.roll + h10 * a.droll + h01 * b.roll + h11 * b.droll;
    droll = d00 * a.roll + d10 * a.droll - d00 * b.roll + d11 * b.droll;
    z = h00 * a.z + h10 * a.dz + h01 * b.z + h11 * b.dz;
    dz = d00 * a.z + d10 * a.dz - d00 * b.z + d11 * b.dz;
  };
  double r0, dr0, z0, dz0;
  at(k, r0, dr0, z0, dz0);
  if (nk_ > 1 && w > 0.0) {
    double r1, dr1, z1, dz1;
    at(k + 1, r1, dr1, z1, dz1);
    r0 += w * (r1 - r0);
    dr0 += w * (dr1 - dr0);
    z0 += w * (z1 - z0);
    dz0 += w * (dz1 - dz0);
  }
  out.roll = r0;
  out.droll_dy = dr0;
  out.height = z0;
  out.dheight_dy = dz0;
}

// On x86-64 a second copy for processors with AVX2 (chosen at load time, GCC's
// target_clones): the column loops run four strips per instruction; no FMA,
// so both copies round alike and give the same results.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
__attribute__((target_clones("avx2", "default")))
#endif
void StripContactTable::strips(double y, double psi, double cutoff, StripSet& out) const {
  int i, k;
  double t, w, apsi;
  locate(y, psi, i, t, k, w, apsi);
  const HermiteBasis H(t, grid_.y_step);
  const double h00 = H.h00, h10 = H.h10, h01 = H.h01, h11 = H.h11;
  const bool two = nk_ > 1 && w > 0.0;
  const int kb = two ? k + 1 : k;
  // Common strip range of the (up to) four rows involved.
  int j0 = 0, j1 = strips_total_ - 1;
  for (int kk = k; kk <= kb; ++kk)
    for (int ii = i; ii <= i + 1; ++ii) {
      j0 = std::max(j0, row(kk, ii).j0);
      j1 = std::min(j1, row(kk, ii).j1);
    }
  // A cutoff within a kNearGap level: only the hull of the nodes' near strips can
  // pass it, plus one neighbour on each side (index_near_ranges). Not in the
  // end cells in y, whose slopes are not limited.
  int level = 0;
  while (level < kNearLevels && cutoff > kNearGap[level]) ++level;
  if (level < kNearLevels && i > 0 && i + 1 < ny_ - 1) {
    int n0 = strips_total_, n1 = -1;
    for (int kk = k; kk <= kb; ++kk)
      for (int ii = i; ii <= i + 1; ++ii) {
        const NearRange& nr =
            near_[(std::size_t(kk) * std::size_t(ny_) + std::size_t(ii)) * kNearLevels + std::size_t(level)];
        if (nr.j1 < nr.j0) continue;
        n0 = std::min(n0, nr.j0);
        n1 = std::max(n1, nr.j1);
      }
    if (n1 < n0) {  // nothing within reach
      out.n = 0;
      out.width = grid_.strip;
      return;
    }
    j0 = std::max(j0, n0 - 1);
    j1 = std::min(j1, n1 + 1);
  }
  out.n = 0;
  out.width = grid_.strip;
  const int m = std::min(j1 - j0 + 1, StripSet::kMax);
  if (m <= 0) return;
  auto at = [&](int kk, int ii) { return row(kk, ii).offset + std::size_t(j0 - row(kk, ii).j0); };
  const std::size_t ia0 = at(k, i), ib0 = at(k, i + 1);
  const std::size_t ia1 = two ? at(k + 1, i) : ia0, ib1 = two ? at(k + 1, i + 1) : ib0;
  // Every quantity is a weighted sum of eight entries of strip j0 + q: value
  // and y-slope at rows i and i + 1 (Hermite in y), at yaw nodes k and k + 1
  // (linear in psi^2 between them): weights c[0..3] at node k, c[4..7] at
  // node k + 1. interpolate() sums them over strips [q0, q0 + cnt) into
  // dst[0, cnt), one quantity at a time (columns: vectorised over the strips).
  // (Inlined always, so that it is compiled for each target_clones copy.)
  auto interpolate = [&](int quantity, const double* c, int q0, int cnt, double* __restrict dst)
                         __attribute__((always_inline)) {
    const double* __restrict v = column(2 * quantity) + q0;
    const double* __restrict d = column(2 * quantity + 1) + q0;
    const double c0 = c[0], c1 = c[1], c2 = c[2], c3 = c[3];
    if (!two) {
      for (int n = 0; n < cnt; ++n) dst[n] = c0 * v[ia0 + n] + c1 * d[ia0 + n] + c2 * v[ib0 + n] + c3 * d[ib0 + n];
      return;
    }
    const double c4 = c[4], c5 = c[5], c6 = c[6], c7 = c[7];
    for (int n = 0; n < cnt; ++n)
      dst[n] = (c0 * v[ia0 + n] + c1 * d[ia0 + n] + c2 * v[ib0 + n] + c3 * d[ib0 + n]) +
               (c4 * v[ia1 + n] + c5 * d[ia1 + n] + c6 * v[ib1 + n] + c7 * d[ib1 + n]);
  };
  const double u0 = two ? 1.0 - w : 1.0, u1 = two ? w : 0.0;
  const double even[8] = {u0 * h00, u0 * h10, u0 * h01, u0 * h11, u1 * h00, u1 * h10, u1 * h01, u1 * h11};
  // Lead: odd in psi, interpolated as psi * (lead/psi) linear in psi^2 (node 0
  // takes node 1's lead/psi; at psi = 0 the lead is 0).
  const double p0 = k * grid_.yaw_step, p1 = (k + 1) * grid_.yaw_step;
  const double inv_p0 = k > 0 ? 1.0 / p0 : 0.0, inv_p1 = nk_ > 1 ? 1.0 / p1 : 0.0;
  const double odd = (psi < 0 ? -1.0 : 1.0) * apsi;
  const double l0 = two ? (k > 0 ? odd * (1.0 - w) * inv_p0 : 0.0) : odd * inv_p0;
  const double l1 = two ? (k > 0 ? odd * w * inv_p1 : odd * inv_p1) : 0.0;
  const double lead[8] = {l0 * h00, l0 * h10, l0 * h01, l0 * h11, l1 * h00, l1 * h10, l1 * h01, l1 * h11};
  // Pass 1: gaps of all m strips; pass 2 the other quantities over the run
  // [qa, qb] from the first to the last strip near a loaded one, written
  // straight into the output's columns.
  double vgap[StripSet::kMax];
  // Loops run over whole groups of kLanes strips (the columns and the output
  // have room for the overrun; values past the range are never read), so no
  // loop takes a scalar remainder.
  auto lanes = [](int c) { return (c + kLanes - 1) / kLanes * kLanes; };
  interpolate(kGap, even, 0, lanes(m), vgap);
  for (int q = 0; q < m; ++q) vgap[q] = std::max(0.0, vgap[q]);
  // The first and last strips within the cutoff; the run [qa, qb] adds one
  // neighbour on each side. Strips between them that are not within one strip
  // of a passing one (two separate runs: tread and flange) are dropped below.
  int first = 0, last = m - 1;
  while (first < m && !(vgap[first] <= cutoff)) ++first;
  if (first == m) return;
  while (!(vgap[last] <= cutoff)) --last;
  int passing = 0;
  for (int q = first; q <= last; ++q) passing += vgap[q] <= cutoff ? 1 : 0;
  bool split = false;
  if (passing < last - first + 1)
    for (int q = first + 1; q < last && !split; ++q)
      split = !(vgap[q - 1] <= cutoff) && !(vgap[q] <= cutoff) && !(vgap[q + 1] <= cutoff);
  const int qa = std::max(0, first - 1), qb = std::min(m - 1, last + 1);
  const int cnt = qb - qa + 1, cnt_lanes = lanes(cnt);
  interpolate(kAngle, even, qa, cnt_lanes, out.angle);
  interpolate(kLateral, even, qa, cnt_lanes, out.lateral);
  interpolate(kLead, lead, qa, cnt_lanes, out.lead);
  interpolate(kHeight, even, qa, cnt_lanes, out.height);
  interpolate(kA, even, qa, cnt_lanes, out.A);
  interpolate(kF, even, qa, cnt_lanes, out.f);
  for (int n = 0; n < cnt; ++n) {
    out.index[n] = j0 + qa + n;
    out.gap[n] = vgap[qa + n];
    out.y_wheel[n] = y_wheel_[std::size_t(j0 + qa + n)];
  }
  out.n = cnt;
  if (!split) return;
  // Between two separate runs (tread and flange) strips far from both are
  // dropped: keep those near a strip within the cutoff (in place).
  auto near = [&](int q) {
    return vgap[q] <= cutoff || (q > 0 && vgap[q - 1] <= cutoff) || (q + 1 < m && vgap[q + 1] <= cutoff);
  };
  int kept = 0;
  for (int n = 0; n < cnt; ++n) {
    if (!near(qa + n)) continue;
    if (kept != n) out.set(kept, out[n]);
    ++kept;
  }
  out.n = kept;
}

StripContactTable StripContactTable::cached(const WheelRailGeometry& geometry, const Profile& wheel, const Profile& rail,
                                            const StripTableGrid& grid, const std::string& cache_dir,
                                            bool* loaded_from_cache) {
  grid.validate();
  if (loaded_from_cache) *loaded_from_cache = false;
  const std::string dir = resolve_cache_dir(cache_dir);
  ContentHash f = geometry_cache_hash(kMagic, sizeof kMagic, wheel, rail, geometry);
  const SearchOptions& o = geometry.options();
  for (double v : {grid.y_min, grid.y_max, grid.y_step, grid.yaw_max, grid.yaw_step, grid.strip, grid.gap_store,
                   o.wheel_step, o.rail_step})
    f.value(v);
  const unsigned long long key = f.value();
  char name[64];
  std::snprintf(name, sizeof name, "strip_table_%016llx.bin", key);
  const std::string path = dir + "/" + name;
  {
    std::ifstream in(path, std::ios::binary);
    if (in) {
      char magic[8];
      unsigned long long k = 0;
      long long hdr[5] = {};
      in.read(magic, 8);
      in.read(reinterpret_cast<char*>(&k), sizeof k);
      in.read(reinterpret_cast<char*>(hdr), sizeof hdr);
      if (in && std::memcmp(magic, kMagic, 8) == 0 && k == key && hdr[0] > 1 && hdr[0] < 100000 && hdr[1] >= 1 &&
          hdr[1] < 1000 && hdr[2] > 0 && hdr[2] < 100000 && hdr[3] >= 0 && hdr[3] < 100000000 && hdr[0] * hdr[1] < 10000000) {
        StripContactTable t;
        t.grid_ = grid;
        t.ny_ = int(hdr[0]);
        t.nk_ = int(hdr[1]);
        t.strips_total_ = int(hdr[2]);
        t.grid_.y_max = grid.y_min + (t.ny_ - 1) * grid.y_step;
        t.grid_.yaw_max = (t.nk_ - 1) * grid.yaw_step;
        in.read(reinterpret_cast<char*>(&t.t0_), sizeof t.t0_);
        t.y_wheel_.resize(std::size_t(t.strips_total_));
        in.read(reinterpret_cast<char*>(t.y_wheel_.data()), std::streamsize(t.y_wheel_.size() * sizeof(double)));
        t.rows_.resize(std::size_t(t.ny_) * std::size_t(t.nk_));
        in.read(reinterpret_cast<char*>(t.rows_.data()), std::streamsize(t.rows_.size() * sizeof(Row)));
        std::vector<Entry> entries(static_cast<std::size_t>(hdr[3]));
        in.read(reinterpret_cast<char*>(entries.data()), std::streamsize(entries.size() * sizeof(Entry)));
        bool ok = bool(in) && in.peek() == std::char_traits<char>::eof();
        for (const Row& r : t.rows_)
          ok = ok && r.j0 >= 0 && r.j1 < t.strips_total_ && r.j1 >= r.j0 - 1 &&
               r.offset + std::size_t(r.j1 - r.j0 + 1) <= entries.size();
        if (ok) {
          if (loaded_from_cache) *loaded_from_cache = true;
          t.unpack(entries);
          return t;
        }
      }
    }
  }
  StripContactTable t = build(geometry, grid);
  // Best effort: an unwritable cache costs a rebuild next time, not a failure.
  try {
    const std::string folder = railsim::cache_dir(dir, "strip contact table");
    const std::vector<Entry> entries = t.pack();
    write_file_atomically(folder + "/" + name, [&](std::ostream& out) {
      const long long hdr[5] = {t.ny_, t.nk_, t.strips_total_, static_cast<long long>(entries.size()), 0};
      out.write(kMagic, 8);
      out.write(reinterpret_cast<const char*>(&key), sizeof key);
      out.write(reinterpret_cast<const char*>(hdr), sizeof hdr);
      out.write(reinterpret_cast<const char*>(&t.t0_), sizeof t.t0_);
      out.write(reinterpret_cast<const char*>(t.y_wheel_.data()), std::streamsize(t.y_wheel_.size() * sizeof(double)));
      out.write(reinterpret_cast<const char*>(t.rows_.data()), std::streamsize(t.rows_.size() * sizeof(Row)));
      out.write(reinterpret_cast<const char*>(entries.data()), std::streamsize(entries.size() * sizeof(Entry)));
    });
  } catch (const InputError&) {
  }
  return t;
}

}  // namespace railsim::contact
