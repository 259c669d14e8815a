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
}  // namespace

Fastrip::Fastrip(const FastripOptions& options)
    : options_(options), grid_(StripGrid::make(options.nx, options.ny, options.spacing_x, options.spacing_y)) {
  const auto nx = static_cast<std::size_t>(grid_.nx);
  sqc_.resize(nx);
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
  const double* Xc = grid_.Xc.data();
  const double* step = grid_.step.data();
  const double* step_mid = grid_.step_mid.data();
  const double* dX = grid_.dX.data();
  const double* sqc = sqc_.data();
  // One strip's constants and march state.
  struct March {
    double aj, gj, spy, d, ar2, qs, sgx, pgx, xs;
    double sx = 0.0, sy = 0.0, qprev = 0.0, fx = 0.0, fy = 0.0, mz = 0.0, adh = 0.0;
    bool slides = false;  // the strip slides from here on (bound reached, or Carter slip zone)
  };
  const auto start = [&](std::size_t j) {
    const double y = b * grid_.Y[j], aj = a * grid_.t[j];
    const double gj = mu * p0 * grid_.t[j];  // mu p0_j: peak of the strip's bound
    // Carter solution of the strip (step 2): adhesion centre d, half-length ar.
    const double S = (gj > 0.0) ? W / gj : 1.0;  // Carter's slip measure |w| / (mu p0_j)
    const double d = W > 0.0 ? aj * std::min(S, 1.0) : 0.0;
    const double ar = aj - d;
    // The strip slides behind x_s (step 4): Carter's slip point d - a' when
    // spin matters on this strip, nowhere (the trailing edge) without spin,
    // blended by chi = |phi| |(a_j, y_j)| / (0.25 |(xi, eta)|) in [0, 1];
    // and from the leading edge once the strip's creepage alone saturates it
    // (Carter's full slip, S = |w| / (mu p0_j) >= 1), reached at S = 2.
    const double full = std::clamp(S - 1.0, 0.0, 1.0) * spin_weight;
    const double chi = std::max(creep_norm > 0.0 ? std::min(1.0, chi_rate * std::sqrt(aj * aj + y * y)) : 1.0, full);
    const double xs = W > 0.0 ? chi * (d - ar) - (1.0 - chi) * aj : -aj;
    return March{aj,
                 gj,
                 spy_tau / grid_.t[j],            // phi / L3_j
                 d,
                 ar * ar,
                 W > 0.0 ? gj / aj : 0.0,         // mu p0_j / a_j (no strip-theory traction without creepage)
                 spx * y,                          // longitudinal spin slip rate on this strip (adhesion, L3)
                 ux - upxw * y,                    // (xi - phi y_j) / Lu: uniform pull of a sliding strip
                 xs};
  };
  // One element of a strip, in three parts so that a group's sliding strips
  // take their substeps side by side (the square-root/division chains of
  // different strips interleaved): the traction at the element's start and
  // the sliding substeps' increments (or the adhering strip's spin step),
  // one substep, and the element's end (bound, sums).
  struct Step {
    double x, q, tx, ty, hx, hy, hs;
  };
  const auto begin_element = [&](March& m, std::size_t e, Step& st) {
    const double aj = m.aj;
    st.x = aj * Xc[e];
    const double dx = aj * step[e];  // from the previous point
    // Carter's strip traction at the element centre (zero without creepage).
    const double v = st.x - m.d;
    st.q = m.qs * (aj * sqc[e] - std::sqrt(std::max(0.0, m.ar2 - v * v)));
    // Carter's slip zone of the strip's creepage: the strip slides from here
    // on even if spin keeps the total traction below the bound (step 4).
    if (st.x < m.xs) m.slides = true;
    if (m.slides) {
      // Sliding strip: no more strip-theory increments (cancelled in s); the
      // total traction is marched as in FASTSIM (step 4), in kSub substeps,
      // each returned onto the bound at its end (step 4c).
      st.tx = m.qprev * ex + m.sx;
      st.ty = m.qprev * ey + m.sy;
      const double h = dx * (1.0 / kSub);
      st.hx = m.pgx * h;
      st.hy = uy * h;
      st.hs = m.spy * aj * h;
    } else {
      // Spin, FASTSIM-like (step 4), on top of the strip traction.
      m.sx += m.sgx * dx;
      m.sy -= m.spy * (aj * aj * step_mid[e]);  // the step times its midpoint
    }
  };
  const auto substep = [&](const March& m, std::size_t e, int i, Step& st) {
    st.tx -= st.hx;
    st.ty -= st.hy + st.hs * sub_xm_[e * kSub + i];
    const double gi = m.gj * sub_sq_[e * kSub + i];
    const double t2 = st.tx * st.tx + st.ty * st.ty;
    if (t2 > gi * gi) {
      const double sc = gi / std::sqrt(t2);
      st.tx *= sc;
      st.ty *= sc;
    }
  };
  const auto end_element = [&](March& m, std::size_t e, const Step& st) {
    const double q = st.q, x = st.x;
    if (m.slides) {
      m.sx = st.tx - q * ex;
      m.sy = st.ty - q * ey;
    }
    m.qprev = q;
    double tx = q * ex + m.sx, ty = q * ey + m.sy;
    const double g = m.gj * sqc[e];
    const double t2 = tx * tx + ty * ty;
    const double w = m.aj * dX[e];
    if (t2 > g * g * (1.0 + 1e-12)) {
      const double s = g / std::sqrt(t2);
      tx *= s;
      ty *= s;
      m.sx = tx - q * ex;
      m.sy = ty - q * ey;
      m.slides = true;
    } else if (x >= m.d - (m.aj - m.d)) {  // behind the adhesion zone's trailing end d - a'
      m.adh += w;
    }
    m.fx += m.sx * w;
    m.fy += m.sy * w;
    m.mz += x * m.sy * w;
  };
  // Step 5: the strip-theory traction's part of the strip force and moment,
  // integrated exactly over the strip (the sum of its exact integrals over
  // the elements telescopes): Carter's q = (mu p0_j / a_j)(sqrt(a_j^2 - x^2)
  // - sqrt(a'^2 - (x - d)^2)) gives (pi/2) mu p0_j / a_j (a_j^2 - a'^2) along
  // e and the moment -(pi/2) mu p0_j / a_j d a'^2 (a_j^2 - a'^2 = d (2 a_j - d)
  // without cancellation at small creepage).
  StripSums sums;
  const auto finish = [&](std::size_t j, const March& m) {
    const double force = 0.5 * kPi * m.qs * m.d * (2.0 * m.aj - m.d);
    const double moment = -0.5 * kPi * m.qs * m.d * m.ar2;
    sums.add(force * ex + m.fx, force * ey + m.fy, moment * ey + m.mz, b * grid_.Y[j], m.aj, m.adh, b * grid_.dY[j]);
  };
  // Strips in groups (for_strip_groups): their marches overlap; summed in strip order.
  const auto group = [&]<std::size_t N>(std::size_t j0, std::integral_constant<std::size_t, N>) {
    March m[N];
    for (std::size_t i = 0; i < N; ++i) m[i] = start(j0 + i);
    Step st[N];
    for (std::size_t e = 0; e < nx; ++e) {
      bool any = false;
      for (std::size_t i = 0; i < N; ++i) {
        begin_element(m[i], e, st[i]);
        any = any || m[i].slides;
      }
      if (any)
        for (int k2 = 0; k2 < kSub; ++k2)
          for (std::size_t i = 0; i < N; ++i)
            if (m[i].slides) substep(m[i], e, k2, st[i]);
      for (std::size_t i = 0; i < N; ++i) end_element(m[i], e, st[i]);
    }
    for (std::size_t i = 0; i < N; ++i) finish(j0 + i, m[i]);
  };
  for_strip_groups(grid_.Y.size(), group);
  return strip_model_result("fastrip", in, sums);
}

std::unique_ptr<TangentialModel> make_fastrip(const TangentialModelOptions& options) {
  FastripOptions o;
  o.nx = o.ny = StripGrid::size_option(options, "fastrip", o.nx);
  return std::make_unique<Fastrip>(o);
}

}  // namespace railsim::contact
