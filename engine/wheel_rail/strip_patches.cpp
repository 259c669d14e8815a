// Distributed normal contact of one wheel; see strip_patches.hpp.
#include "engine/wheel_rail/strip_patches.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "contact/hertz.hpp"

namespace railsim::engine {

namespace {

// cos(x): on treads and flange roots (|x| < 0.25 rad) its Taylor series to
// x^12 (truncation below 1e-19, so within an ulp or two of std::cos at a
// fraction of the cost); std::cos beyond.
inline double cos_angle(double x) {
  if (std::abs(x) >= 0.25) return std::cos(x);
  const double x2 = x * x;
  return 1.0 + x2 * (-1.0 / 2 + x2 * (1.0 / 24 + x2 * (-1.0 / 720 + x2 * (1.0 / 40320 + x2 * (-1.0 / 3628800 +
                                                                                               x2 / 479001600.0)))));
}

// Per strip: normal penetration, modulus, its load share W_j and dW_j/dw.
// Only strips that can carry load (and their neighbours, for the zero
// crossing of a loaded segment) get the exact penetration: a strip with
// (w - dphi a_j) - g_j <= 0 is unloaded whatever its angle, and its p_j is
// left at that upper bound (never read unless a neighbour is loaded, in which
// case it is made exact). `cos_cache` (optional, NaN where not yet known)
// keeps cos(delta_j) across calls on the same strips.
struct StripWork {
  double p[contact::StripSet::kMax];
  double k[contact::StripSet::kMax];
  double cd[contact::StripSet::kMax];
  double W[contact::StripSet::kMax];
  double dW[contact::StripSet::kMax];
  bool exact[contact::StripSet::kMax];
};

void shares(const contact::StripSet& s, int jb, int je, double w, double dphi_side, double Es, double* cos_cache,
            StripWork& x) {
  const int n = je;
  auto make_exact = [&](int j, double u) {
    const contact::StripPoint q = s[j];
    double c;
    if (cos_cache) {
      if (std::isnan(cos_cache[j])) cos_cache[j] = cos_angle(q.angle);
      c = cos_cache[j];
    } else {
      c = cos_angle(q.angle);
    }
    x.cd[j] = c;
    x.p[j] = u * c - q.gap;
    x.k[j] = Es * q.f;
    x.exact[j] = true;
  };
  bool any = false;
  for (int j = jb; j < n; ++j) {
    const contact::StripPoint q = s[j];
    const double u = w - dphi_side * q.lateral;
    x.W[j] = 0.0;
    x.dW[j] = 0.0;
    if (u - q.gap > 0.0) {
      make_exact(j, u);
      any = true;
    } else {
      x.p[j] = u - q.gap;  // upper bound, <= 0
      x.exact[j] = false;
    }
  }
  if (!any) return;
  for (int j = jb; j < n; ++j) {
    if (x.exact[j]) continue;
    const bool left = j > jb && x.exact[j - 1] && x.p[j - 1] > 0.0 && s.index[j] == s.index[j - 1] + 1;
    const bool right = j + 1 < n && x.exact[j + 1] && x.p[j + 1] > 0.0 && s.index[j + 1] == s.index[j] + 1;
    if (left || right) make_exact(j, w - dphi_side * s.lateral[j]);
  }
  const double d = s.width;
  for (int j = jb; j + 1 < n; ++j) {
    const double pa = x.p[j], pb = x.p[j + 1];
    if (!(pa > 0.0 || pb > 0.0)) continue;
    if (s.index[j + 1] != s.index[j] + 1) continue;  // not neighbours
    if (pa > 0.0 && pb > 0.0) {  // trapezoid, half to each end
      x.W[j] += 0.5 * d * x.k[j] * pa;
      x.W[j + 1] += 0.5 * d * x.k[j + 1] * pb;
      x.dW[j] += 0.5 * d * x.k[j] * x.cd[j];
      x.dW[j + 1] += 0.5 * d * x.k[j + 1] * x.cd[j + 1];
    } else {  // triangle up to the zero crossing, to the loaded end
      const int e = pa > 0.0 ? j : j + 1;
      const double pe = x.p[e], po = x.p[e == j ? j + 1 : j];
      const double c = pe / (pe - po);  // loaded fraction of the segment
      // load = (c d / 2) k_e p_e; d/dw: c depends on w too.
      const double ce = x.cd[e], co = x.cd[e == j ? j + 1 : j];
      const double dc = (ce * (pe - po) - pe * (ce - co)) / ((pe - po) * (pe - po));
      x.W[e] += 0.5 * c * d * x.k[e] * pe;
      x.dW[e] += 0.5 * d * x.k[e] * (dc * pe + c * ce);
    }
  }
}

// Loads, vertical load and patches from the shares of strips [jb, je).
void loads_from_shares(const contact::StripSet& s, int jb, int je, const StripWork& x, double phi_side,
                       StripLoads& out, bool with_patches, PatchShape shape);

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
  shares(s, 0, s.n, w, dphi_side, Es, nullptr, x);
  loads_from_shares(s, 0, s.n, x, phi_side, out, with_patches, shape);
}

namespace {
void loads_from_shares(const contact::StripSet& s, int jb, int je, const StripWork& x, double phi_side,
                       StripLoads& out, bool with_patches, PatchShape shape) {
  out.n = 0;
  out.vertical = 0.0;
  out.dvertical = 0.0;
  int j = jb;
  while (j < je) {
    if (!(x.W[j] > 0.0)) {
      ++j;
      continue;
    }
    // A run of neighbouring loaded strips: one patch.
    double N = 0, ang = 0, lat = 0, lead = 0, h = 0, A = 0, rw = 0, vert = 0, dvert = 0, pmax = 0;
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
      const double ct = phi_side == 0.0 ? x.cd[e] : std::cos(q.angle + phi_side);
      vert += W * ct;
      dvert += x.dW[e] * ct;
      if (e + 1 < je && s.index[e + 1] == q.index + 1 && x.W[e + 1] > 0.0) ++e;
      else break;
    }
    out.vertical += vert;
    out.dvertical += dvert;
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
      const double half = 0.5 * pmax;
      double width = 0.0;
      for (int q = j; q <= e + 1 && q < je; ++q) {  // segments [q-1, q] inside the run and its edges
        if (q == 0 || s.index[q] != s.index[q - 1] + 1) continue;
        const double pa = x.p[q - 1] - half, pb = x.p[q] - half;
        if (pa > 0 && pb > 0) width += s.width;
        else if (pa > 0 || pb > 0) width += s.width * std::max(pa, pb) / std::abs(pa - pb);
      }
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

// On x86-64 a second copy for processors with AVX2 (GCC's target_clones, as
// StripContactTable::strips): the strip loops below have no branches and run
// in groups of four strips, one instruction per group there; no FMA, so both
// copies round alike.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
__attribute__((target_clones("avx2", "default")))
#endif
double strip_approach_for_load(const contact::StripSet& s, double Q, double phi_side, double Es, StripLoads& out,
                               PatchShape shape) {
  // Z(w) is increasing and convex-ish (0 while nothing is loaded); Newton from
  // a Hertz guess, guarded by bisection on a bracket. Every evaluation fills
  // the strips' penetrations and load shares (the arithmetic of shares() with
  // dphi = 0, written per strip without branches: strip q takes from each
  // neighbouring segment the fraction f of its own end, f = 1 when the
  // neighbour is penetrated too, else the loaded fraction p_q / (p_q - p_nb)),
  // so the loads and patches at the solution come from the last evaluation.
  constexpr int L = 4;  // strips per group
  const int n = s.n;
  // Per strip, with one leading and L + 1 trailing entries of an unloaded,
  // unlinked pad (index -1 and n ... n + L): cos(delta_j), gap, penetration,
  // Winkler stiffness per half segment, vertical factor, 1 where the left /
  // right neighbour is the profile's neighbour, and the shares W, dW/dw.
  constexpr int kN = contact::StripSet::kMax + L + 2;
  alignas(32) double ccb[kN], cgb[kN], cpb[kN], ckb[kN], cvb[kN], lklb[kN], lkrb[kN], Wb[kN], dWb[kN];
  double *cc = ccb + 1, *cg = cgb + 1, *cp = cpb + 1, *ck = ckb + 1, *lkl = lklb + 1, *lkr = lkrb + 1;
  double *W = Wb + 1, *dW = dWb + 1;
  for (int q : {-1, n, n + 1, n + 2, n + 3, n + 4}) {
    cc[q] = 1.0;
    cg[q] = 1.0;
    cp[q] = -1.0;
    ck[q] = 0.0;
    lkl[q] = lkr[q] = 0.0;
  }
  for (int q = 0; q < n; ++q) {  // cos(delta) by the Taylor series of cos_angle(), fixed up beyond 0.25 rad below
    const double x2 = s.angle[q] * s.angle[q];
    cc[q] = 1.0 + x2 * (-1.0 / 2 + x2 * (1.0 / 24 + x2 * (-1.0 / 720 + x2 * (1.0 / 40320 + x2 * (-1.0 / 3628800 +
                                                                                               x2 / 479001600.0)))));
    cg[q] = s.gap[q];
    ck[q] = 0.5 * s.width * (Es * s.f[q]);
  }
  for (int q = 0; q + 1 < n; ++q) lkr[q] = s.index[q + 1] == s.index[q] + 1 ? 1.0 : 0.0;
  if (n > 0) lkr[n - 1] = 0.0;
  lkl[0] = 0.0;
  for (int q = 1; q < n; ++q) lkl[q] = lkr[q - 1];
  double vmin = 1e9;  // vertical approach at which the first strip touches (g_j / cos >= g_j)
  for (int q = 0; q < n; ++q) {
    if (std::abs(s.angle[q]) >= 0.25) cc[q] = std::cos(s.angle[q]);
    vmin = std::min(vmin, cg[q] / cc[q]);
  }
  const double* cv = cc;  // vertical factor cos(delta + phi_side)
  if (phi_side != 0.0) {
    for (int q = 0; q < n; ++q) cvb[q + 1] = std::cos(s.angle[q] + phi_side);
    for (int q : {-1, n, n + 1, n + 2, n + 3, n + 4}) cvb[q + 1] = 0.0;
    cv = cvb + 1;
  }
  // Load shares W_j, dW_j/dw over the groups of L strips from q0 (pads and
  // strips past q1 carry none: unloaded there), and the vertical load with its
  // derivative at w over strips [q0, q1).
  int q0 = 0, q1 = n;
  double w_filled = std::numeric_limits<double>::quiet_NaN();  // the w the shares hold
  auto vertical = [&](double w, double& V, double& dV) __attribute__((always_inline)) {
    const int e0 = std::max(0, q0 - 1), e1 = std::min(n, q1 + 1);
    for (int q = e0; q < e1; ++q) cp[q] = w * cc[q] - cg[q];
    double v[L] = {}, dv[L] = {};
    for (int g = q0; g < q1; g += L)
      for (int l = 0; l < L; ++l) {
        const int q = g + l;
        const double p = cp[q], c0 = cc[q];
        const bool loaded = p > 0.0;
        // One side (neighbour penetration pn, cosine cn, link flag lk): the
        // fraction f of the segment's end load and its w-derivative df. Every
        // operation is done unconditionally (and finite) and selected after,
        // so that the loop has no branch.
        auto side = [&](double pn, double cn, double lk, double& Ws, double& dWs) __attribute__((always_inline)) {
          const double D = p - std::min(pn, 0.0);  // p - pn when the neighbour is unloaded, p otherwise
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
    w_filled = w;
  };
  double lo = vmin, hi = vmin + 1e-4, Vhi = 0.0, dV = 0.0;
  for (int it = 0; it < 40; ++it) {  // grow the bracket until it carries Q
    vertical(hi, Vhi, dV);
    if (Vhi >= Q) break;
    lo = hi;
    hi = vmin + 2.0 * (hi - vmin);
  }
  // Below hi only strips penetrated at hi can be (p grows with w): the
  // iterations run on those and one neighbour on each side.
  {
    int a = n, b = -1;
    for (int q = 0; q < n; ++q)
      if (cp[q] > 0.0) {
        a = std::min(a, q);
        b = q;
      }
    if (b >= 0) {
      q0 = std::max(0, a - 1);
      q1 = std::min(n, b + 2);
    }
  }
  // First guess: Hertz's V = K (w - w0)^{3/2} through the bracket's top with
  // its slope there (w0 = hi - 1.5 V / V'; w0 = vmin without a slope).
  double w = hi;
  if (Vhi > Q && Vhi > 0.0) {
    const double w0 = dV > 0.0 ? std::max(vmin, hi - 1.5 * Vhi / dV) : vmin;
    const double guess = w0 + (hi - w0) * std::cbrt((Q / Vhi) * (Q / Vhi));
    if (guess > lo && guess < hi) w = guess;
  }
  for (int it = 0; it < 80; ++it) {
    double V;
    vertical(w, V, dV);
    const double f = V - Q;
    if (std::abs(f) <= 1e-10 * Q) break;
    (f > 0.0 ? hi : lo) = w;
    const double next = dV > 0.0 ? w - f / dV : 0.5 * (lo + hi);
    w = (next > lo && next < hi) ? next : 0.5 * (lo + hi);
    if (hi - lo < 1e-15) break;
  }
  if (!(w_filled == w)) {  // stopped on the bracket's width: the shares at the last w
    double V;
    vertical(w, V, dV);
  }
  StripWork x;
  for (int q = std::max(0, q0 - 1); q < std::min(n, q1 + 1); ++q) {
    x.p[q] = cp[q];
    x.cd[q] = cc[q];
    x.W[q] = W[q];
    x.dW[q] = dW[q];
  }
  loads_from_shares(s, q0, q1, x, phi_side, out, true, shape);
  return w;
}

}  // namespace railsim::engine
