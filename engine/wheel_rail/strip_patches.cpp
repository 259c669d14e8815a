// Distributed normal contact of one wheel; see strip_patches.hpp.
#include "engine/wheel_rail/strip_patches.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "contact/hertz.hpp"

namespace railsim::engine {

namespace {

// One wheel's strips as padded columns (one leading and kLanes + 1 trailing
// entries of an unloaded, unlinked pad: index -1 and n ... n + kLanes):
// cos(delta_j), gap, normal penetration p_j, Winkler stiffness per half
// segment k_j = (d/2) E* f_j, 1 where the left / right strip is the profile's
// neighbour, the load shares W_j, dW_j/dw, and the vertical factor cv_j =
// cos(delta_j + phi_side) (cd itself when phi_side = 0). Not copyable (the
// column pointers point into the object).
struct StripWork {
  static constexpr int kLanes = 4;  // strips per group of the share pass
  static constexpr int kPad = contact::StripSet::kMax + kLanes + 2;
  alignas(32) double cdb[kPad], gapb[kPad], pb[kPad], kb[kPad], lklb[kPad], lkrb[kPad], Wb[kPad], dWb[kPad],
      cvb[kPad];
  double* const cd = cdb + 1;
  double* const gap = gapb + 1;
  double* const p = pb + 1;
  double* const k = kb + 1;
  double* const lkl = lklb + 1;
  double* const lkr = lkrb + 1;
  double* const W = Wb + 1;
  double* const dW = dWb + 1;
  const double* cv = cd;
  StripWork() = default;
  StripWork(const StripWork&) = delete;
  StripWork& operator=(const StripWork&) = delete;
};

// The columns of strips s (penetrations left to the caller; the pads' set).
// On x86-64 a second copy for processors with AVX2 (GCC's target_clones, as
// StripContactTable::strips); no FMA, so both copies round alike.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
__attribute__((target_clones("avx2", "default")))
#endif
void strip_columns(const contact::StripSet& s, double Es, double phi_side, StripWork& x) {
  const int n = s.n;
  for (int q : {-1, n, n + 1, n + 2, n + 3, n + 4}) {
    x.cd[q] = 1.0;
    x.gap[q] = 1.0;
    x.p[q] = -1.0;
    x.k[q] = 0.0;
    x.lkl[q] = x.lkr[q] = 0.0;
    x.cvb[q + 1] = 0.0;
  }
  // cos(delta): on treads and flange roots (|delta| < 0.25 rad) its Taylor
  // series to delta^12 (truncation below 1e-19, within an ulp or two of
  // std::cos at a fraction of the cost); std::cos beyond (fixed up below).
  int steep = 0;  // any strip beyond the series' range
  for (int q = 0; q < n; ++q) {
    const double x2 = s.angle[q] * s.angle[q];
    x.cd[q] = 1.0 + x2 * (-1.0 / 2 + x2 * (1.0 / 24 + x2 * (-1.0 / 720 + x2 * (1.0 / 40320 + x2 * (-1.0 / 3628800 +
                                                                                                   x2 / 479001600.0)))));
    x.gap[q] = s.gap[q];
    x.k[q] = 0.5 * s.width * (Es * s.f[q]);
    steep |= x2 >= 0.0625;
  }
  if (steep)
    for (int q = 0; q < n; ++q)
      if (std::abs(s.angle[q]) >= 0.25) x.cd[q] = std::cos(s.angle[q]);
  if (n > 0) x.lkl[0] = 0.0;
  if (n > 0 && s.index[n - 1] - s.index[0] == n - 1) {  // one run of consecutive strips (the rule)
    for (int q = 0; q + 1 < n; ++q) x.lkl[q + 1] = x.lkr[q] = 1.0;
  } else {
    for (int q = 0; q + 1 < n; ++q) x.lkl[q + 1] = x.lkr[q] = s.index[q + 1] == s.index[q] + 1 ? 1.0 : 0.0;
  }
  if (n > 0) x.lkr[n - 1] = 0.0;
  x.cv = x.cd;
  if (phi_side != 0.0) {
    for (int q = 0; q < n; ++q) x.cvb[q + 1] = std::cos(s.angle[q] + phi_side);
    x.cv = x.cvb + 1;
  }
}

// Load shares of the strips in groups of kLanes from q0 up to q1 (a strip's
// neighbours' penetrations are read; pads and unloaded strips past q1 carry
// none) and the vertical load sum W_j cv_j with its w-derivative over them.
// Between neighbouring strips the penetration is linear and integrated up to
// its zero crossing, half of each segment's load to each end: written per
// strip, strip q takes from each neighbouring segment the fraction f of its
// own end load k_q p_q, f = 1 when the neighbour is penetrated too, else the
// loaded fraction p_q / (p_q - p_nb) (a triangle). No branches: every
// operation is done unconditionally (and finite) and selected after, so that
// the group loop vectorises (the file is built with -fno-trapping-math; the
// columns come as separate restrict pointers, as GCC does not vectorise
// through the StripWork's own).
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
__attribute__((target_clones("avx2", "default")))
#endif
void share_pass(const double* __restrict cp, const double* __restrict cc, const double* __restrict ck,
                const double* __restrict lkl, const double* __restrict lkr, const double* __restrict cv,
                double* __restrict W, double* __restrict dW, int q0, int q1, double& V, double& dV) {
  constexpr int L = StripWork::kLanes;
  double v[L] = {}, dv[L] = {};
  for (int g = q0; g < q1; g += L)
    for (int l = 0; l < L; ++l) {
      const int q = g + l;
      const double p = cp[q], c0 = cc[q];
      const bool loaded = p > 0.0;
      // One side (neighbour penetration pn, cosine cn, link flag lk): the
      // fraction f of the segment's end load and its w-derivative df.
      auto side = [&](double pn, double cn, double lk, double& Ws, double& dWs) __attribute__((always_inline)) {
        const double D = p - std::min(pn, 0.0);      // p - pn when the neighbour is unloaded, p otherwise
        const double iD = 1.0 / std::max(D, 1e-30);  // (D >= p > 0 where used)
        const bool both = pn > 0.0;
        const double fr = p * iD;
        const double dfr = (c0 - p * (c0 - cn) * iD) * iD;
        const double f = both ? 1.0 : fr;
        const double df = both ? 0.0 : dfr;
        const double fp = f * p, dfp = df * p + f * c0;
        const bool on = loaded & (lk != 0.0);
        Ws = on ? fp : 0.0;
        dWs = on ? dfp : 0.0;
      };
      double Wl, dWl, Wr, dWr;
      side(cp[q - 1], cc[q - 1], lkl[q], Wl, dWl);
      side(cp[q + 1], cc[q + 1], lkr[q], Wr, dWr);
      W[q] = ck[q] * (Wl + Wr);
      dW[q] = ck[q] * (dWl + dWr);
      v[l] += W[q] * cv[q];
      dv[l] += dW[q] * cv[q];
    }
  V = (v[0] + v[1]) + (v[2] + v[3]);
  dV = (dv[0] + dv[1]) + (dv[2] + dv[3]);
}

// Loads, vertical load and patches from the shares of strips [jb, je).
void loads_from_shares(const contact::StripSet& s, int jb, int je, const StripWork& x, StripLoads& out,
                       bool with_patches, PatchShape shape);

// int_0^d sqrt(g(t)) dt for g linear from g0 to g1 over d, clipped at zero.
double sqrt_linear_integral(double g0, double g1, double d) {
  if (g0 <= 0.0 && g1 <= 0.0) return 0.0;
  if (g0 < 0.0 || g1 < 0.0) {  // up to the zero crossing
    const double gp = std::max(g0, g1);
    const double len = d * gp / (gp - std::min(g0, g1));
    return 2.0 / 3.0 * len * std::sqrt(gp);
  }
  const double s0 = std::sqrt(g0), s1 = std::sqrt(g1);
  // (2 d / 3) (g1^{3/2} - g0^{3/2}) / (g1 - g0), written without the cancellation
  return 2.0 / 3.0 * d * (g0 + s0 * s1 + g1) / (s0 + s1);
}

// The semi-Hertzian ellipse of the run of strips [j, e] (strip_patches.hpp):
// semi-axes (a_s, b_s) from the Hertz ellipse (a, b) of curvatures (A, Be) at
// the approach pmax. Segments to the run's unloaded neighbours are included
// (g falls below zero inside them).
void semi_hertz_axes(const contact::StripSet& s, int jb, int je, int j, int e, const StripWork& x, double pmax,
                     double A, double Be, double& a, double& b) {
  const double eps = Be * b * b / pmax;
  const double cA = Be * b * b / (A * a * a);
  const double shift = (1.0 - eps) * pmax;
  // half-length squared per strip, x_j^2 = g_j / (c_A A_j); A_j <= 0 (a strip
  // of the run with no longitudinal curvature of its own) takes the patch's A.
  auto g_over_curv = [&](int q) {
    const double Aq = s.A[q] > 0.0 ? s.A[q] : A;
    return (x.p[q] - shift) / (cA * Aq);
  };
  double area = 0.0, amax = 0.0;
  const int lo = (j > jb && s.index[j - 1] + 1 == s.index[j]) ? j - 1 : j;
  const int hi = (e + 1 < je && s.index[e + 1] == s.index[e] + 1) ? e + 1 : e;
  for (int q = lo; q <= hi; ++q) {
    const double u = g_over_curv(q);
    if (u > 0.0) amax = std::max(amax, std::sqrt(u));
    if (q < hi) area += 2.0 * sqrt_linear_integral(u, g_over_curv(q + 1), s.width);
  }
  if (amax > 0.0 && area > 0.0) {
    a = amax;
    b = area / (M_PI * amax);
  }
}

}  // namespace

void strip_loads(const contact::StripSet& s, double w, double dphi_side, double phi_side, double Es, StripLoads& out,
                 bool with_patches, PatchShape shape) {
  StripWork x;
  strip_columns(s, Es, phi_side, x);
  for (int q = 0; q < s.n; ++q) x.p[q] = (w - dphi_side * s.lateral[q]) * x.cd[q] - x.gap[q];
  double V, dV;
  share_pass(x.p, x.cd, x.k, x.lkl, x.lkr, x.cv, x.W, x.dW, 0, s.n, V, dV);
  loads_from_shares(s, 0, s.n, x, out, with_patches, shape);
}

namespace {
void loads_from_shares(const contact::StripSet& s, int jb, int je, const StripWork& x, StripLoads& out,
                       bool with_patches, PatchShape shape) {
  out.n = 0;
  out.vertical = 0.0;
  int j = jb;
  while (j < je) {
    if (!(x.W[j] > 0.0)) {
      ++j;
      continue;
    }
    // A run of neighbouring loaded strips: one patch.
    double N = 0, ang = 0, lat = 0, lead = 0, h = 0, A = 0, rw = 0, vert = 0, pmax = 0;
    int e = j;
    for (;;) {
      const contact::StripPoint q = s[e];
      const double W = x.W[e];
      N += W;
      ang += W * q.angle;
      lat += W * q.lateral;
      lead += W * q.lead;
      h += W * q.height;
      A += W * q.A;
      pmax = std::max(pmax, x.p[e]);
      rw += W * x.cd[e];
      const double ct = x.cv[e];
      vert += W * ct;
      if (e + 1 < je && x.lkr[e] != 0.0 && x.W[e + 1] > 0.0) ++e;  // (lkr: e + 1 is e's profile neighbour)
      else break;
    }
    out.vertical += vert;
    if (with_patches && out.n < WheelGeometry::kMaxPoints) {
      ContactPointGeometry& c = out.patch[out.n];
      c = ContactPointGeometry{};
      c.contact_angle = ang / N;
      c.lateral = lat / N;
      c.lead = lead / N;
      c.rolling_radius = h / N;
      c.A = A / N;
      // Equivalent ellipse: the lateral curvature B_e of the parabola with
      // the patch's largest penetration and width at half of it, w = 2
      // sqrt(p_max / (2 B_e)); then Hertz's semi-axes for (A, B_e) at the
      // approach p_max, a = alpha sqrt(p_max/A), b = beta sqrt(p_max/B_e)
      // (exact for a quadratic gap).
      // Segments [q-1, q] inside the run and at its edges, where q - 1 is q's
      // profile neighbour (lkl): the part above half, 1 where both ends are,
      // max / |difference| where one is (no branches; the last in lane 0).
      const double half = 0.5 * pmax;
      constexpr int L = StripWork::kLanes;
      double wl[L] = {};
      auto segment = [&](int q, int l) __attribute__((always_inline)) {
        const double pa = x.p[q - 1] - half, pb = x.p[q] - half;
        const double top = std::max(pa, pb), diff = std::abs(pa - pb);
        const double part = top >= diff ? 1.0 : top / std::max(diff, 1e-300);
        wl[l] += top > 0.0 ? x.lkl[q] * part : 0.0;
      };
      const int qe = std::min(e + 1, je - 1);
      int q = j;
      for (; q + L - 1 <= qe; q += L)
        for (int l = 0; l < L; ++l) segment(q + l, l);
      for (; q <= qe; ++q) segment(q, 0);
      const double width = s.width * ((wl[0] + wl[1]) + (wl[2] + wl[3]));
      if (c.A > 0.0 && width > 0.0 && pmax > 0.0) {
        const double Be = 2.0 * pmax / (width * width);
        double alpha = 0.0, beta = 0.0;
        contact::StripContactTable::hertz_axis_factors(Be / c.A, alpha, beta);
        c.semi_a = alpha * std::sqrt(pmax / c.A);
        c.semi_b = beta * std::sqrt(pmax / Be);
        if (shape == PatchShape::semi_hertz) semi_hertz_axes(s, jb, je, j, e, x, pmax, c.A, Be, c.semi_a, c.semi_b);
      }
      out.N[out.n] = N;
      out.rate_weight[out.n] = rw;
      ++out.n;
    } else if (with_patches) {  // more patches than slots: add to the last one's load
      out.N[out.n - 1] += N;
    }
    j = e + 1;
  }
}
}  // namespace

// (An AVX2 copy as well, for its penetration loop.)
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
__attribute__((target_clones("avx2", "default")))
#endif
double strip_approach_for_load(const contact::StripSet& s, double Q, double phi_side, double Es, StripLoads& out,
                               PatchShape shape, double* warm_start) {
  // V(w) is increasing and convex-ish (0 while nothing is loaded). Steps on
  // Hertz's law through the last evaluation (below), guarded by bisection once
  // a bracket is known. Every evaluation is a share pass (the loads of
  // strip_loads() with dphi = 0), so the loads and patches at the solution
  // come from the last evaluation (or its linearised last step).
  const int n = s.n;
  StripWork x;
  strip_columns(s, Es, phi_side, x);
  const double *cc = x.cd, *cg = x.gap;
  double* cp = x.p;
  // The smallest gap: nothing is loaded below it (strip j touches at the
  // approach g_j / cos(delta_j) >= g_j); the reference of the warm start.
  double vm[StripWork::kLanes] = {1e9, 1e9, 1e9, 1e9};  // (four lanes: vectorised; the pads' gaps are 1 m)
  for (int g = 0; g < n; g += StripWork::kLanes)
    for (int l = 0; l < StripWork::kLanes; ++l) vm[l] = std::min(vm[l], cg[g + l]);
  const double vmin = std::min(std::min(vm[0], vm[1]), std::min(vm[2], vm[3]));
  // Penetrations over strips [q0, q1) and one neighbour on each side; shares
  // over the penetrated ones among them, [pa, pb) (the others carry none); the
  // loads are read from these and their unloaded neighbours.
  int q0 = 0, q1 = n, pa = 0, pb = 0;
  double w_filled = std::numeric_limits<double>::quiet_NaN();  // the w the shares hold
  auto vertical = [&](double w, double& V, double& dV) {
    const int e0 = std::max(0, q0 - 1), e1 = std::min(n, q1 + 1);
    for (int q = e0; q < e1; ++q) cp[q] = w * cc[q] - cg[q];
    pa = q0;
    pb = q1;
    while (pa < pb && !(cp[pa] > 0.0)) ++pa;
    while (pb > pa && !(cp[pb - 1] > 0.0)) --pb;
    V = dV = 0.0;
    if (pa < pb) share_pass(x.p, x.cd, x.k, x.lkl, x.lkr, x.cv, x.W, x.dW, pa, pb, V, dV);
    if (pa > 0) x.W[pa - 1] = 0.0;  // the unloaded neighbours (read by the patches' edges)
    if (pb < n) x.W[pb] = 0.0;
    w_filled = w;
  };
  // Start: the caller's warm start (this wheel's approach above its smallest
  // gap at the last solve, taken within [1 nm, 1 mm]), else 0.1 mm above that
  // gap.
  const double inf = std::numeric_limits<double>::infinity();
  double lo = vmin, hi = inf, dV = 0.0;
  double w = vmin + (warm_start && *warm_start > 0.0 ? std::clamp(*warm_start, 1e-9, 1e-3) : 1e-4);
  bool solved = false;  // to the tolerance (not stopped by the bracket's width or the evaluation count)
  for (int it = 0; it < 100; ++it) {
    double V;
    vertical(w, V, dV);
    const double f = V - Q;
    if (std::abs(f) <= 1e-10 * Q) {
      solved = true;
      break;
    }
    // Near enough that the Newton step's remainder, about f^2 / (6 V) for a
    // Hertzian V ~ (w - w0)^{3/2}, lies below a third of the tolerance: the
    // last step is taken on the linearised shares (p is linear in w, the
    // shares W_j to first order) instead of a pass that would confirm it.
    if (f * f <= 2e-10 * Q * V && dV > 0.0) {
      const double d = -f / dV;
      const int e0 = std::max(0, q0 - 1), e1 = std::min(n, q1 + 1);
      for (int q = e0; q < e1; ++q) cp[q] += d * cc[q];
      for (int q = pa; q < pb; ++q) x.W[q] = cp[q] > 0.0 ? std::max(0.0, x.W[q] + d * x.dW[q]) : 0.0;
      w += d;
      w_filled = w;
      solved = true;
      break;
    }
    if (f > 0.0) {
      // The first upper bound: below it only strips penetrated there can be
      // (p grows with w), [pa, pb) of this pass over every strip; the passes
      // run on those and one neighbour each side.
      if (hi == inf && pa < pb) {
        q0 = std::max(0, pa - 1);
        q1 = std::min(n, pb + 1);
      }
      hi = w;
    } else {
      lo = w;
    }
    // Next: Hertz's V = K (w - w0)^{3/2} through (w, V) with its slope there
    // (w0 = w - 1.5 V / V'), solved for Q; bisection where that leaves the
    // bracket, doubling the approach while there is no upper bound.
    double next = lo;
    if (V > 0.0 && dV > 0.0) {
      const double w0 = w - 1.5 * V / dV;
      next = w0 + (w - w0) * std::cbrt((Q / V) * (Q / V));
    }
    if (!(next > lo && next < hi))
      next = hi < inf ? 0.5 * (lo + hi) : vmin + 2.0 * std::max(std::max(w, lo) - vmin, 1e-9);
    w = next;
    if (hi - lo < 1e-15) break;
  }
  if (!(w_filled == w)) {  // stopped on the bracket's width: the shares at the last w
    double V;
    vertical(w, V, dV);
  }
  loads_from_shares(s, std::max(0, pa - 1), std::min(n, pb + 1), x, out, true, shape);
  if (warm_start && solved) *warm_start = w - vmin;  // (an unsolved one would mislead the next start)
  return w;
}

}  // namespace railsim::engine
