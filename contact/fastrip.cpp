// FaStrip-type model (strip theory + FASTSIM-like spin); see fastrip.hpp for
// the derivation, its sources and its limits.
#include "contact/fastrip.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "contact/kalker_coefficients.hpp"
#include "core/errors.hpp"

namespace railsim::contact {

namespace {
constexpr double kPi = std::numbers::pi;

// Integral of sqrt(r^2 - u^2) from 0 to u (|u| <= r) and of u sqrt(r^2 - u^2)
// from -r to u. (u / r, not u times a reciprocal: at the trailing end of a
// nearly full adhesion zone asin's slope is unbounded and a one-ulp change of
// the argument moved the small-creepage force by 1e-4.)
inline double seg_area(double u, double r) {
  const double s = std::sqrt(std::max(0.0, r * r - u * u));
  return 0.5 * (u * s + r * r * std::asin(std::clamp(u / r, -1.0, 1.0)));
}
inline double seg_moment(double u, double r) {
  const double w = std::max(0.0, r * r - u * u);
  return w * std::sqrt(w) * (-1.0 / 3.0);
}
}  // namespace

Fastrip::Fastrip(const FastripOptions& options)
    : options_(options), grid_(StripGrid::make(options.nx, options.ny, options.spacing_x, options.spacing_y)) {
  const auto nx = static_cast<std::size_t>(grid_.nx);
  sqc_.resize(nx);
  An_.resize(nx + 1);
  Bn_.resize(nx + 1);
  for (std::size_t k = 0; k <= nx; ++k) {
    An_[k] = seg_area(grid_.X[k], 1.0);
    Bn_[k] = seg_moment(grid_.X[k], 1.0);
  }
  double par = 0.0;  // midpoint rule of (1 - X^2) along a strip (continuum 4/3)
  for (std::size_t k = 0; k < nx; ++k) {
    const double X = grid_.Xc[k];
    sqc_[k] = std::sqrt(std::max(0.0, 1.0 - X * X));
    par += (1.0 - X * X) * grid_.dX[k];
  }
  double s1 = 0.0, s2 = 0.0, s3 = 0.0;
  for (std::size_t j = 0; j < grid_.t.size(); ++j) {
    const double t = grid_.t[j], dY = grid_.dY[j];
    s1 += t * dY;
    s2 += t * t * dY;
    s3 += t * t * t * dY;
  }
  load_scale_ = (4.0 / 3.0) / s2;
  k_scale_ = s1 / (kPi / 2.0);
  l3_scale_ = s3 * par / (kPi / 2.0);
  tau_ = s3 / s2;
  sub_sq_.resize(nx * kSub);
  sub_xm_.resize(nx * kSub);
  for (std::size_t k = 0; k < nx; ++k) {
    for (int i = 1; i <= kSub; ++i) {
      const double Xe = grid_.Xc[k] + grid_.step[k] * (1.0 - static_cast<double>(i) / kSub);
      sub_sq_[k * kSub + i - 1] = std::sqrt(std::max(0.0, 1.0 - Xe * Xe));
      sub_xm_[k * kSub + i - 1] = grid_.Xc[k] + grid_.step[k] * (1.0 - (i - 0.5) / kSub);
    }
  }
}

ContactForces Fastrip::compute(const ContactInput& in, TangentialWorkspace* /*ws*/) const {
  ContactForces out;
  if (!check_tangential_input(in, "fastrip")) {
    out.stick_fraction = 1.0;
    return out;
  }
  const double a = in.patch.a;
  const double b = in.patch.b;
  const double Fz = in.patch.Fz;
  const double mu = in.material.mu;
  const double G = in.material.shear_modulus();
  const KalkerCoefficients C = kalker_coefficients(a / b, in.material.nu);
  const ReductionFactors& k = in.reduction;
  const double pi2 = kPi * kPi;
  // Strip compliances (step 3) and spin flexibilities (step 4), grid-consistent.
  double Kx = pi2 / (2.0 * G * C.C11 * k.k11) * k_scale_;
  double Ky = pi2 / (2.0 * G * C.C22 * k.k22) * k_scale_;
  {
    // Saturated direction (step 2b): Kx, Ky blended toward one creepage-weighted
    // compliance Kc, by w = min(1, f / 3), f = |(xi, eta)| / |(xi*, eta*)|.
    const double xi = in.creep.xi, eta = in.creep.eta, c2 = a * b;
    const double xs = mu * Fz / (G * c2 * C.C11 * k.k11), es = mu * Fz / (G * c2 * C.C22 * k.k22);
    const double n2 = xi * xi + eta * eta;
    if (n2 > 0.0 && xs > 0.0) {
      const double w = std::min(1.0, std::sqrt(n2 / (xs * xs + es * es)) * (1.0 / 3.0));
      const double Kc = n2 / (xi * xi / Kx + eta * eta / Ky);
      Kx = (1.0 - w) * Kx + w * Kc;
      Ky = (1.0 - w) * Ky + w * Kc;
    }
  }
  const double L3 = kPi * a * std::sqrt(a / b) / (4.0 * G * C.C23 * k.k23) * l3_scale_;
  const double p0 = 3.0 * Fz / (2.0 * kPi * a * b) * load_scale_;
  const double wx = in.creep.xi / Kx;
  const double wy = in.creep.eta / Ky;
  const double W = std::sqrt(wx * wx + wy * wy);  // (not hypot: a library call, and no overflow here)
  const double ex = W > 0.0 ? -wx / W : 0.0;  // direction of the strip-theory traction
  const double ey = W > 0.0 ? -wy / W : 0.0;
  // Sliding strips (header, step 4): the rigid slip that is uniform along a
  // strip, (xi - phi y_j, eta), pulls with one flexibility Lu = sqrt(L1 L2)
  // (Kalker's L1 = 8a/(3 G C11 k11), L2 = 8a/(3 G C22 k22)), so that the
  // traction turns towards the direction of that slip; the lateral spin slip
  // phi x, which varies along the strip, keeps the spin flexibility (L3_j, step 4b).
  const double Lu = 8.0 * a / (3.0 * G * std::sqrt(C.C11 * k.k11 * C.C22 * k.k22));
  const double ux = in.creep.xi / Lu, uy = in.creep.eta / Lu, upx = in.creep.phi / Lu;
  const double creep_norm = std::sqrt(in.creep.xi * in.creep.xi + in.creep.eta * in.creep.eta);
  // Longitudinal spin slip -phi y_j of a sliding strip: with Lu when creepage
  // is present, with L3 (FASTSIM) for pure spin; blended by
  // om = |(xi, eta)| / (0.1 |phi| c) in [0, 1] so the force is continuous.
  const double om = in.creep.phi != 0.0
                        ? std::min(1.0, creep_norm / (0.1 * std::abs(in.creep.phi) * std::sqrt(a * b)))
                        : 1.0;
  const double upxw = om * upx + (1.0 - om) * in.creep.phi / L3;
  // Lateral spin slip phi x / L3 per metre of x; per strip times tau / t_j
  // (L3_j = L3 t_j / tau, step 4b).
  const double spy_tau = in.creep.phi / L3 * tau_;
  const double spx = in.creep.phi / L3;   // longitudinal spin slip / L3 per metre of y

  // Weight of the full-slip trigger (step 4): the normalised spin
  // psi' = G c^3 C23 k23 |phi| / (mu Fz), full from psi' = 0.1 (without spin
  // a strip in Carter's full slip keeps Carter's exact traction).
  const double cab = std::sqrt(a * b);
  const double spin_weight =
      std::min(1.0, G * cab * cab * cab * C.C23 * k.k23 * std::abs(in.creep.phi) / (0.1 * mu * Fz));

  // chi's rate |phi| / (0.25 |(xi, eta)|) (below), once per call.
  const double chi_rate = creep_norm > 0.0 ? std::abs(in.creep.phi) / (0.25 * creep_norm) : 0.0;

  const auto nx = static_cast<std::size_t>(grid_.nx);
  const StripSums sums = grid_.sum_strips(a, b, [&](std::size_t j, double y, double aj) {
    const double gj = mu * p0 * grid_.t[j];  // mu p0_j: peak of the strip's bound
    const double spy = spy_tau / grid_.t[j];  // phi / L3_j
    // Carter solution of the strip (step 2): adhesion centre d, half-length ar.
    const double S = (gj > 0.0) ? W / gj : 1.0;  // Carter's slip measure |w| / (mu p0_j)
    double d = 0.0, ar = aj;
    if (W > 0.0) {
      d = aj * std::min(S, 1.0);
      ar = aj - d;
    }
    const double qs = gj / aj;  // mu p0_j / a_j
    const double sgx = spx * y;        // longitudinal spin slip rate on this strip (adhesion, L3)
    const double pgx = ux - upxw * y;  // (xi - phi y_j) / Lu: uniform pull of a sliding strip
    // The strip slides behind x_s (step 4): Carter's slip point d - a' when
    // spin matters on this strip, nowhere (the trailing edge) without spin,
    // blended by chi = |phi| |(a_j, y_j)| / (0.25 |(xi, eta)|) in [0, 1];
    // and from the leading edge once the strip's creepage alone saturates it
    // (Carter's full slip, S = |w| / (mu p0_j) >= 1), reached at S = 2.
    const double full = std::clamp(S - 1.0, 0.0, 1.0) * spin_weight;
    const double chi = std::max(creep_norm > 0.0 ? std::min(1.0, chi_rate * std::sqrt(aj * aj + y * y)) : 1.0, full);
    const double xs = chi * (d - ar) - (1.0 - chi) * aj;
    double sx = 0.0, sy = 0.0, qprev = 0.0;
    bool slides = false;  // the strip slides from here on (bound reached, or Carter slip zone)
    double fx = 0.0, fy = 0.0, mz = 0.0, adh = 0.0;
    // Adhesion-ellipse integrals at the upper boundary of the current element
    // (the leading edge x = a_j sits at u = +ar); reused element to element.
    double Aup = 0.25 * kPi * ar * ar, Bup = 0.0;
    bool in_adhesion = W > 0.0 && ar > 0.0;
    for (std::size_t kk = 0; kk < nx; ++kk) {
      const double x = aj * grid_.Xc[kk];
      const double dx = aj * grid_.step[kk];             // from the previous point
      const double xmdx = aj * aj * grid_.step_mid[kk];  // the step times its midpoint
      const double w = aj * grid_.dX[kk];
      // Strip-theory traction: analytic integral and first moment over the element.
      double I = 0.0, M = 0.0, q = 0.0;
      if (W > 0.0) {
        I = aj * aj * (An_[kk] - An_[kk + 1]);
        M = aj * aj * aj * (Bn_[kk] - Bn_[kk + 1]);
        double qa = 0.0;
        if (in_adhesion) {
          const double u1 = std::max(aj * grid_.X[kk + 1] - d, -ar);
          const double Alo = seg_area(u1, ar), Blo = seg_moment(u1, ar);
          const double dA = Aup - Alo;
          I -= dA;
          M -= Bup - Blo + d * dA;
          Aup = Alo;
          Bup = Blo;
          in_adhesion = u1 > -ar;
          const double v = x - d;
          qa = std::sqrt(std::max(0.0, ar * ar - v * v));
        }
        I *= qs;
        M *= qs;
        q = qs * (aj * sqc_[kk] - qa);
      }
      // Carter's slip zone of the strip's creepage: the strip slides from here
      // on even if spin keeps the total traction below the bound (step 4).
      if (W > 0.0 && x < xs) slides = true;
      if (slides) {
        // Sliding strip: no more strip-theory increments (cancelled in s); the
        // total traction is marched as in FASTSIM (step 4), in kSub substeps,
        // each returned onto the bound at its end (step 4c).
        double tx = qprev * ex + sx, ty = qprev * ey + sy;
        const double h = dx * (1.0 / kSub), hx = pgx * h, hy = uy * h, hs = spy * aj * h;
        const double* sq = &sub_sq_[kk * kSub];
        const double* xm = &sub_xm_[kk * kSub];
        for (int i = 0; i < kSub; ++i) {
          tx -= hx;
          ty -= hy + hs * xm[i];
          const double gi = gj * sq[i];
          const double t2 = tx * tx + ty * ty;
          if (t2 > gi * gi) {
            const double sc = gi / std::sqrt(t2);
            tx *= sc;
            ty *= sc;
          }
        }
        sx = tx - q * ex;
        sy = ty - q * ey;
      } else {
        // Spin, FASTSIM-like (step 4), on top of the strip traction.
        sx += sgx * dx;
        sy -= spy * xmdx;
      }
      qprev = q;
      double tx = q * ex + sx, ty = q * ey + sy;
      const double g = gj * sqc_[kk];
      const double t2 = tx * tx + ty * ty;
      if (t2 > g * g * (1.0 + 1e-12)) {
        const double s = g / std::sqrt(t2);
        tx *= s;
        ty *= s;
        sx = tx - q * ex;
        sy = ty - q * ey;
        slides = true;
      } else if (x >= d - ar) {
        adh += w;
      }
      fx += I * ex + sx * w;
      fy += I * ey + sy * w;
      mz += M * ey + x * sy * w;
    }
    return StripForces{fx, fy, mz, adh};
  });
  return strip_model_result("fastrip", in, sums);
}

std::unique_ptr<TangentialModel> make_fastrip(const TangentialModelOptions& options) {
  FastripOptions o;
  o.nx = o.ny = StripGrid::size_option(options, "fastrip", o.nx);
  return std::make_unique<Fastrip>(o);
}

}  // namespace railsim::contact
