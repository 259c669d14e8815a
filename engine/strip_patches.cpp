// Distributed normal contact of one wheel; see strip_patches.hpp.
#include "engine/strip_patches.hpp"

#include <algorithm>
#include <cmath>

#include "contact/hertz.hpp"

namespace railsim::engine {

namespace {

// Per strip: normal penetration, modulus, its load share W_j and dW_j/dw.
struct StripWork {
  double p[contact::StripSet::kMax];
  double k[contact::StripSet::kMax];
  double cd[contact::StripSet::kMax];
  double W[contact::StripSet::kMax];
  double dW[contact::StripSet::kMax];
};

void shares(const contact::StripSet& s, double w, double dphi_side, double Es, StripWork& x) {
  const int n = s.n;
  for (int j = 0; j < n; ++j) {
    const contact::StripPoint& q = s.s[j];
    x.cd[j] = std::cos(q.angle);
    x.p[j] = (w - dphi_side * q.lateral) * x.cd[j] - q.gap;
    x.k[j] = Es * q.f;
    x.W[j] = 0.0;
    x.dW[j] = 0.0;
  }
  const double d = s.width;
  for (int j = 0; j + 1 < n; ++j) {
    if (s.s[j + 1].index != s.s[j].index + 1) continue;  // not neighbours
    const double pa = x.p[j], pb = x.p[j + 1];
    if (pa > 0.0 && pb > 0.0) {  // trapezoid, half to each end
      x.W[j] += 0.5 * d * x.k[j] * pa;
      x.W[j + 1] += 0.5 * d * x.k[j + 1] * pb;
      x.dW[j] += 0.5 * d * x.k[j] * x.cd[j];
      x.dW[j + 1] += 0.5 * d * x.k[j + 1] * x.cd[j + 1];
    } else if (pa > 0.0 || pb > 0.0) {  // triangle up to the zero crossing, to the loaded end
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

}  // namespace

void strip_loads(const contact::StripSet& s, double w, double dphi_side, double phi_side, double Es, StripLoads& out,
                 bool with_patches) {
  StripWork x;
  shares(s, w, dphi_side, Es, x);
  out.n = 0;
  out.vertical = 0.0;
  out.dvertical = 0.0;
  int j = 0;
  while (j < s.n) {
    if (!(x.W[j] > 0.0)) {
      ++j;
      continue;
    }
    // A run of neighbouring loaded strips: one patch.
    double N = 0, ang = 0, lat = 0, lead = 0, h = 0, A = 0, rw = 0, vert = 0, dvert = 0, pmax = 0;
    int e = j;
    for (;;) {
      const contact::StripPoint& q = s.s[e];
      const double W = x.W[e];
      N += W;
      ang += W * q.angle;
      lat += W * q.lateral;
      lead += W * q.lead;
      h += W * q.height;
      A += W * q.A;
      pmax = std::max(pmax, x.p[e]);
      rw += W * x.cd[e];
      const double ct = std::cos(q.angle + phi_side);
      vert += W * ct;
      dvert += x.dW[e] * ct;
      if (e + 1 < s.n && s.s[e + 1].index == q.index + 1 && x.W[e + 1] > 0.0) ++e;
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
      for (int q = j; q <= e + 1 && q < s.n; ++q) {  // segments [q-1, q] inside the run and its edges
        if (q == 0 || s.s[q].index != s.s[q - 1].index + 1) continue;
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

double strip_approach_for_load(const contact::StripSet& s, double Q, double phi_side, double Es, StripLoads& out) {
  // Z(w) is increasing and convex-ish (0 while nothing is loaded); Newton from
  // the smallest gap, guarded by bisection on a bracket.
  double vmin = 1e9;  // vertical approach at which the first strip touches
  for (int j = 0; j < s.n; ++j) vmin = std::min(vmin, s.s[j].gap / std::cos(s.s[j].angle));
  double lo = vmin, hi = vmin + 1e-4;
  for (int it = 0; it < 40; ++it) {  // grow the bracket until it carries Q
    strip_loads(s, hi, 0.0, phi_side, Es, out, false);
    if (out.vertical >= Q) break;
    lo = hi;
    hi = vmin + 2.0 * (hi - vmin);
  }
  double w = hi;
  for (int it = 0; it < 80; ++it) {
    strip_loads(s, w, 0.0, phi_side, Es, out, false);
    const double f = out.vertical - Q;
    if (std::abs(f) <= 1e-10 * Q) break;
    (f > 0.0 ? hi : lo) = w;
    const double next = out.dvertical > 0.0 ? w - f / out.dvertical : 0.5 * (lo + hi);
    w = (next > lo && next < hi) ? next : 0.5 * (lo + hi);
    if (hi - lo < 1e-15) break;
  }
  strip_loads(s, w, 0.0, phi_side, Es, out, true);
  return w;
}

}  // namespace railsim::engine
