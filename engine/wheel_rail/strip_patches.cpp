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

double strip_approach_for_load(const contact::StripSet& s, double Q, double phi_side, double Es, StripLoads& out,
                               PatchShape shape) {
  // Z(w) is increasing and convex-ish (0 while nothing is loaded); Newton from
  // a Hertz guess, guarded by bisection on a bracket. The bracket and the
  // iterations need only the vertical load and its derivative: they run on
  // compact copies of the strips (the same arithmetic as shares() and
  // loads_from_shares() with dphi = 0); the loads and patches are evaluated
  // once, at the solution, on the strips that can be loaded there.
  const int n = s.n;
  double cos_cache[contact::StripSet::kMax];
  double cg[contact::StripSet::kMax], ck[contact::StripSet::kMax], cv[contact::StripSet::kMax],
      cp[contact::StripSet::kMax];
  bool linked[contact::StripSet::kMax];  // strips q and q+1 are neighbours
  double vmin = 1e9;  // vertical approach at which the first strip touches (g_j / cos >= g_j)
  for (int q = 0; q < n; ++q) {
    const contact::StripPoint sp = s[q];
    const double c = cos_angle(sp.angle);
    cos_cache[q] = c;
    cg[q] = sp.gap;
    ck[q] = 0.5 * s.width * Es * sp.f;
    cv[q] = phi_side == 0.0 ? c : std::cos(sp.angle + phi_side);
    linked[q] = q + 1 < n && s.index[q + 1] == sp.index + 1;
    if (sp.gap < vmin) vmin = std::min(vmin, sp.gap / c);  // gap / c >= gap
  }
  const double* cc = cos_cache;
  // Vertical load and its derivative at w over strips [q0, q1) (segments
  // whose both ends lie in the range).
  int q0 = 0, q1 = n;
  auto vertical = [&](double w, double& V, double& dV) {
    for (int q = q0; q < q1; ++q) cp[q] = w * cc[q] - cg[q];
    V = 0.0;
    dV = 0.0;
    for (int q = q0; q + 1 < q1; ++q) {
      const double pa = cp[q], pb = cp[q + 1];
      if (!linked[q] || !(pa > 0.0 || pb > 0.0)) continue;
      if (pa > 0.0 && pb > 0.0) {
        V += ck[q] * pa * cv[q] + ck[q + 1] * pb * cv[q + 1];
        dV += ck[q] * cc[q] * cv[q] + ck[q + 1] * cc[q + 1] * cv[q + 1];
      } else {
        const int e = pa > 0.0 ? q : q + 1, o = pa > 0.0 ? q + 1 : q;
        const double pe = cp[e], po = cp[o], ce = cc[e], co = cc[o];
        const double c = pe / (pe - po);
        const double dc = (ce * (pe - po) - pe * (ce - co)) / ((pe - po) * (pe - po));
        V += c * ck[e] * pe * cv[e];
        dV += ck[e] * (dc * pe + c * ce) * cv[e];
      }
    }
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
  // Loads and patches at w: only strips with gap < w can be loaded (p <= w -
  // g); those and one neighbour on each side (the zero crossings).
  int jb = 0, je = n;
  {
    int a = n, b = -1;
    for (int j = 0; j < n; ++j)
      if (s.gap[j] < w) {
        a = std::min(a, j);
        b = j;
      }
    if (b >= 0) {
      jb = std::max(0, a - 1);
      je = std::min(n, b + 2);
    }
  }
  StripWork x;
  shares(s, jb, je, w, 0.0, Es, cos_cache, x);
  loads_from_shares(s, jb, je, x, phi_side, out, true, shape);
  return w;
}

}  // namespace railsim::engine
