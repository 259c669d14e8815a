// STRIPES semi-Hertzian normal contact (see semi_hertz.hpp for the method and sources).
#include "contact/geometry/semi_hertz.hpp"

#include <algorithm>
#include <boost/math/interpolators/cardinal_cubic_b_spline.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <cmath>
#include <cstdio>

#include "contact/hertz.hpp"
#include "core/errors.hpp"

namespace railsim::contact {

struct SemiHertzWorkspace::Impl {
  std::vector<double> g, xl, f;
};

SemiHertzWorkspace::SemiHertzWorkspace() : impl_(std::make_unique<Impl>()) {}
SemiHertzWorkspace::~SemiHertzWorkspace() = default;

namespace {
constexpr double kPi = 3.14159265358979323846;

// Strip kernel int_{d1}^{d2} int_{-L}^{L} sqrt(1 - x^2/L^2) / sqrt(x^2 + d^2) dx dd
// = L [G(d2/L) - G(d1/L)] with G(eta) = 2 int_0^{pi/2} cos^2(t) asinh(eta / sin t) dt
// (inner integral over d in closed form), G odd. G is tabulated once on a
// uniform grid in u = asinh(eta) (cubic B-spline) and continued by its
// asymptote G' = (pi/2)/eta for eta > 1e7.
class StripKernel {
 public:
  StripKernel() {
    boost::math::quadrature::tanh_sinh<double> quad(8);
    std::vector<double> g(kN);
    for (int i = 0; i < kN; ++i) {
      const double eta = std::sinh(i * kDu);
      auto f = [eta](double th) {
        const double sn = std::sin(th), c = std::cos(th);
        return sn > 0.0 ? c * c * std::asinh(eta / sn) : 0.0;
      };
      g[static_cast<std::size_t>(i)] = i == 0 ? 0.0 : 2.0 * quad.integrate(f, 0.0, kPi / 2, 1e-12);
    }
    gmax_ = g.back();
    spline_ = std::make_unique<boost::math::interpolators::cardinal_cubic_b_spline<double>>(g.begin(), g.end(), 0.0, kDu);
  }
  double G(double eta) const {
    const double a = std::abs(eta);
    const double u = std::asinh(a);
    const double v = u <= kUmax ? (*spline_)(u) : gmax_ + 0.5 * kPi * (u - kUmax);
    return eta < 0 ? -v : v;
  }
  double operator()(double L, double d1, double d2) const { return L * (G(d2 / L) - G(d1 / L)); }

 private:
  static constexpr int kN = 4001;
  static constexpr double kUmax = 16.0;  // eta up to sinh(16) ~ 4.4e6
  static constexpr double kDu = kUmax / (kN - 1);
  double gmax_ = 0.0;
  std::unique_ptr<boost::math::interpolators::cardinal_cubic_b_spline<double>> spline_;
};

const StripKernel& strip_kernel() {
  static const StripKernel k;  // immutable after construction
  return k;
}
}  // namespace

SemiHertzResult semi_hertz_from_load(const GapProfile& gap, double Fn, const Material& material,
                                     SemiHertzWorkspace& ws) {
  const std::size_t n = gap.q.size();
  if (n < 5 || gap.h.size() != n || gap.A.size() != n)
    throw InputError("semi_hertz: gap profile needs at least 5 points with h and A at each");
  if (!(Fn > 0.0 && std::isfinite(Fn))) throw InputError("semi_hertz: normal load must be positive and finite");
  const double dq = (gap.q.back() - gap.q.front()) / static_cast<double>(n - 1);
  if (!(dq > 0.0)) throw InputError("semi_hertz: gap profile q must increase");
  auto& im = ws.impl();
  const StripKernel& kernel = strip_kernel();
  im.g.assign(n, 0.0);
  im.xl.assign(n, 0.0);
  im.f.assign(n, 0.0);

  std::size_t k0 = 0;
  for (std::size_t j = 0; j < n; ++j)
    if (std::isfinite(gap.h[j]) && (gap.h[j] < gap.h[k0] || !std::isfinite(gap.h[k0]))) k0 = j;
  const double hmin = gap.h[k0];
  const double A0 = gap.A[k0];
  if (!(A0 > 0.0)) throw InputError("semi_hertz: longitudinal curvature A must be positive at the contact point");
  auto hrel = [&](std::size_t j) { return std::isfinite(gap.h[j]) ? gap.h[j] - hmin : 1e30; };
  // Equivalent lateral curvature around index kc: least squares over the
  // neighbourhood where h - h(kc) < limit.
  auto fit_B = [&](std::size_t kc, double limit) {
    double num = 0.0, den = 0.0;
    for (int dir : {-1, 1}) {
      for (std::size_t j = kc;; j = static_cast<std::size_t>(static_cast<long>(j) + dir)) {
        const double hr = hrel(j) - hrel(kc);
        if (hr >= limit) break;
        const double d2 = (gap.q[j] - gap.q[kc]) * (gap.q[j] - gap.q[kc]);
        num += hr * d2;
        den += d2 * d2;
        if ((dir < 0 && j == 0) || (dir > 0 && j + 1 == n)) break;
      }
    }
    return den > 0.0 ? num / den : 0.0;
  };
  const double Bmin = 1e-3 * A0;
  double Be = std::max(fit_B(k0, 4.0 * dq * dq * A0 + 1e-12), Bmin);
  double delta = hertz_from_load(A0, Be, Fn, material).approach;
  const double Estar = material.combined_modulus();

  SemiHertzResult r;
  double P = 0.0, I1 = 0.0, eps = 0.0;
  // N(delta) for a trial approach: fills the strips, sets eps, P, I1.
  auto evaluate = [&](double dl) {
    delta = dl;
    Be = std::max(fit_B(k0, delta), Bmin);
    {
      const HertzPatch h1 = hertz_from_load(A0, Be, 1.0, material);
      eps = Be * h1.b * h1.b / h1.approach;
    }
    const double dv = eps * delta;
    I1 = 0.0;
    double I2 = 0.0;
    std::fill(im.g.begin(), im.g.end(), 0.0);
    std::fill(im.xl.begin(), im.xl.end(), 0.0);
    std::fill(im.f.begin(), im.f.end(), 0.0);
    for (std::size_t j0 = 0; j0 < n;) {
      if (!(hrel(j0) < delta)) {
        ++j0;
        continue;
      }
      std::size_t j1 = j0, kz = j0;
      while (j1 < n && hrel(j1) < delta) {
        if (hrel(j1) < hrel(kz)) kz = j1;
        ++j1;
      }
      const double hz = hrel(kz);
      const double Az = gap.A[kz];
      if (Az > 0.0) {
        const double Bz = std::max(fit_B(kz, delta - hz), 1e-3 * Az);
        const HertzPatch hz1 = hertz_from_load(Az, Bz, 1.0, material);
        const double epsz = Bz * hz1.b * hz1.b / hz1.approach;
        const double cAz = Bz * hz1.b * hz1.b / (Az * hz1.a * hz1.a);
        const double dvz = epsz * (delta - hz);
        for (std::size_t j = j0; j < j1; ++j) {
          const double g = dvz - (hrel(j) - hz);
          if (g <= 0.0 || !(gap.A[j] > 0.0)) continue;
          im.g[j] = g;
          im.xl[j] = std::sqrt(g / (cAz * gap.A[j]));
          im.f[j] = std::sqrt(g / dv);
          I1 += im.f[j] * 0.5 * kPi * im.xl[j] * dq;
          const double d = gap.q[j] - gap.q[k0];
          I2 += im.f[j] * kernel(im.xl[j], d - 0.5 * dq, d + 0.5 * dq);
        }
      }
      j0 = j1;
    }
    if (!(I1 > 0.0 && I2 > 0.0))
      throw NumericalError("semi_hertz: empty contact patch (check the gap profile around the contact point)");
    P = kPi * Estar * delta / I2;
    return P * I1;
  };
  // Fixed point delta <- delta (Fn/N)^(2/3) (N ~ delta^1.5); when zones appear
  // or vanish N(delta) can jump, then fall back to bisection on a bracket.
  bool done = false;
  double lo = 0.0, hi = 0.0;
  for (int it = 1; it <= 30 && !done; ++it) {
    const double N = evaluate(delta);
    r.iterations = it;
    const double ratio = Fn / N;
    if (std::abs(ratio - 1.0) < 1e-9) done = true;
    else if (ratio > 1.0) lo = delta;
    else hi = delta;
    if (!done) delta *= std::pow(ratio, 2.0 / 3.0);
  }
  if (!done) {
    if (lo == 0.0) lo = delta;
    if (hi == 0.0) hi = delta;
    for (int k = 0; k < 60 && evaluate(lo) > Fn; ++k) lo *= 0.5;
    for (int k = 0; k < 60 && evaluate(hi) < Fn; ++k) hi *= 2.0;
    for (int it = 0; it < 200; ++it) {
      const double mid = 0.5 * (lo + hi);
      const double N = evaluate(mid);
      ++r.iterations;
      if (std::abs(N / Fn - 1.0) < 1e-9) break;
      (N < Fn ? lo : hi) = mid;
      if (hi - lo < 1e-12 * hi) {
        P *= Fn / N;  // N(delta) jumps here: keep the load, accept the nearest approach
        break;
      }
    }
  }
  r.Fn = Fn;
  r.approach = delta;
  r.virtual_penetration = eps * delta;
  r.B_equivalent = Be;
  double qlo = 1e30, qhi = -1e30;
  bool in_part = false;
  for (std::size_t j = 0; j < n; ++j) {
    if (im.f[j] > 0.0) {
      r.area += 2.0 * im.xl[j] * dq;
      r.p_max = std::max(r.p_max, P * im.f[j]);
      r.length = std::max(r.length, 2.0 * im.xl[j]);
      qlo = std::min(qlo, gap.q[j] - 0.5 * dq);
      qhi = std::max(qhi, gap.q[j] + 0.5 * dq);
      r.strips.push_back({gap.q[j], im.xl[j], P * im.f[j]});
      if (!in_part) ++r.parts;
      in_part = true;
    } else {
      in_part = false;
    }
  }
  r.width = qhi - qlo;
  return r;
}

}  // namespace railsim::contact
