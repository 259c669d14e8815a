// FASTSIM (Kalker 1982); see fastsim.hpp for equations, units and signs.
#include "contact/fastsim.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "contact/kalker_coefficients.hpp"
#include "core/errors.hpp"

namespace railsim::contact {

namespace {
constexpr double kPi = std::numbers::pi;

// Node positions on [-1, 1] from +1 down to -1.
std::vector<double> nodes_descending(int n, GridSpacing s) {
  std::vector<double> x(static_cast<std::size_t>(n) + 1);
  for (int k = 0; k <= n; ++k)
    x[static_cast<std::size_t>(k)] = (s == GridSpacing::uniform) ? 1.0 - 2.0 * k / n : std::cos(kPi * k / n);
  x.front() = 1.0;
  x.back() = -1.0;
  return x;
}
}  // namespace

int StripGrid::size_option(const TangentialModelOptions& options, const char* model, int fallback) {
  if (options.grid == 0) return fallback;
  if (options.grid < 2 || options.grid > 1000)
    throw InputError(std::string(model) + ": grid must be in [2, 1000] elements (got " +
                     std::to_string(options.grid) + ")");
  return options.grid;
}

void throw_non_finite_strip_force(const char* model, const ContactInput& in) {
  throw NumericalError(std::string(model) + ": non-finite creep force (a = " + std::to_string(in.patch.a) +
                       " m, b = " + std::to_string(in.patch.b) + " m, Fz = " + std::to_string(in.patch.Fz) + " N)");
}

StripGrid StripGrid::make(int nx, int ny, GridSpacing spacing_x, GridSpacing spacing_y) {
  if (nx < 2 || ny < 2 || nx > 100000 || ny > 100000)
    throw InputError("strip grid: expected at least 2 elements per strip and 2 strips (got " +
                     std::to_string(nx) + " x " + std::to_string(ny) + ")");
  StripGrid g;
  g.nx = nx;
  g.ny = ny;
  g.X = nodes_descending(nx, spacing_x);
  g.Xc.resize(static_cast<std::size_t>(nx));
  g.dX.resize(static_cast<std::size_t>(nx));
  for (std::size_t k = 0; k < g.Xc.size(); ++k) {
    g.Xc[k] = 0.5 * (g.X[k] + g.X[k + 1]);
    g.dX[k] = g.X[k] - g.X[k + 1];
  }
  g.step.resize(g.Xc.size());
  g.step_mid.resize(g.Xc.size());
  g.centre_dX.resize(g.Xc.size());
  for (std::size_t k = 0; k < g.Xc.size(); ++k) {
    const double prev = k == 0 ? 1.0 : g.Xc[k - 1];
    g.step[k] = prev - g.Xc[k];
    g.step_mid[k] = g.step[k] * 0.5 * (prev + g.Xc[k]);
    g.centre_dX[k] = g.Xc[k] * g.dX[k];
  }
  const std::vector<double> yb = nodes_descending(ny, spacing_y);  // strip boundaries
  g.Y.resize(static_cast<std::size_t>(ny));
  g.dY.resize(static_cast<std::size_t>(ny));
  g.t.resize(static_cast<std::size_t>(ny));
  for (std::size_t j = 0; j < g.Y.size(); ++j) {
    g.Y[j] = 0.5 * (yb[j] + yb[j + 1]);
    g.dY[j] = yb[j] - yb[j + 1];
    g.t[j] = std::sqrt(std::max(0.0, 1.0 - g.Y[j] * g.Y[j]));
  }
  return g;
}

namespace {
// blend_flexibilities, inlined into Fastsim::compute (its divisions and
// square root then overlap the caller's).
inline void blend(const ContactInput& in, double& L1, double& L2, double& L3) {
  const double a = in.patch.a, b = in.patch.b;
  const double xi = in.creep.xi, eta = in.creep.eta, phi = in.creep.phi;
  // Combined flexibility: creepage-weighted harmonic mean, spin as the
  // equivalent creepage phi (3 pi a / 32) (the ratio of the spin and creepage
  // moments of FASTSIM's no-slip traction, pi a^2/4 over 8 a/3).
  const double ph = phi * (3.0 * kPi / 32.0) * a;
  const double x2 = xi * xi, e2 = eta * eta, p2 = ph * ph;
  const double num = x2 + e2 + p2;
  const double L12 = L1 * L2;
  const double den = x2 * L2 * L3 + e2 * L1 * L3 + p2 * L12;  // (x2/L1 + e2/L2 + p2/L3) L1 L2 L3
  if (!(num > 0.0) || !(den > 0.0)) return;
  const double L = num * L12 * L3 / den;
  // Blending weight: creepage over the saturation creepage, 0 -> 1 at 3 times it.
  // The saturation creepages are mu Fz / (G c^2 C11), mu Fz / (G c^2 C22),
  // mu Fz / (G c^3 C23) (c^2 = ab); CONTACT adds spin to xi and eta in rad/mm,
  // so spin enters with the length unit 1 mm here too. From the flexibilities
  // (G C11 = 8a / (3 L1), G c^3 C23 = 4 a^3 b / (pi L3)), times a^3 b:
  // 3 mu Fz L1 a / 8, 3 mu Fz L2 a / 8, 1e-3 x 4 mu Fz L3 / pi (no division:
  // the weight is the square root of one ratio).
  const double M = in.material.mu * in.patch.Fz, a3b = a * a * a * b;
  const double sx = 0.375 * M * L1 * a, sy = 0.375 * M * L2 * a, sp = (4e-3 / kPi) * M * L3;
  const double r2 = (x2 + e2 + 1e-6 * phi * phi) * a3b * a3b, s2 = sx * sx + sy * sy + sp * sp;
  const double w = r2 >= 9.0 * s2 ? 1.0 : std::sqrt(r2 / s2) * (1.0 / 3.0);
  L1 = (1.0 - w) * L1 + w * L;
  L2 = (1.0 - w) * L2 + w * L;
  L3 = (1.0 - w) * L3 + w * L;
}
}  // namespace

void blend_flexibilities(const ContactInput& in, double& L1, double& L2, double& L3) { blend(in, L1, L2, L3); }

bool check_tangential_input(const ContactInput& in, const char* model) {
  const HertzPatch& p = in.patch;
  const auto bad = [&](const std::string& what) {
    throw InputError(std::string(model) + ": " + what);
  };
  if (!std::isfinite(p.Fz)) bad("normal load Fz is not finite");
  if (p.Fz <= 0.0) return false;
  if (!(std::isfinite(p.a) && p.a > 0.0) || !(std::isfinite(p.b) && p.b > 0.0))
    bad("semi-axes a, b must be positive and finite (got a = " + std::to_string(p.a) +
        " m, b = " + std::to_string(p.b) + " m)");
  if (!(std::isfinite(in.material.mu) && in.material.mu >= 0.0))
    bad("friction coefficient mu must be >= 0 (got " + std::to_string(in.material.mu) + ")");
  if (!(std::isfinite(in.material.E) && in.material.E > 0.0) ||
      !(in.material.nu > 0.0 && in.material.nu <= 0.5))
    bad("material needs E > 0 and nu in (0, 0.5]");
  const ReductionFactors& k = in.reduction;
  if (!(k.k11 > 0.0 && k.k22 > 0.0 && k.k23 > 0.0))
    bad("reduction factors k11, k22, k23 must be positive");
  if (!std::isfinite(in.creep.xi) || !std::isfinite(in.creep.eta) || !std::isfinite(in.creep.phi))
    bad("creepages must be finite");
  return true;
}

Fastsim::Fastsim(const FastsimOptions& options, const char* name)
    : options_(options), name_(name), grid_(StripGrid::make(options.nx, options.ny, options.spacing_x, options.spacing_y)) {
  const auto nx = static_cast<std::size_t>(grid_.nx);
  const auto ny = static_cast<std::size_t>(grid_.ny);
  bound_shape_.resize(ny * nx);
  // Discretised load of the pressure shape (midpoint rule), in units of
  // a b p0: continuum 2 pi / 3 (elliptic), pi / 2 (parabolic).
  double load = 0.0;
  for (std::size_t j = 0; j < ny; ++j) {
    const double tj = grid_.t[j];
    double strip = 0.0;
    for (std::size_t k = 0; k < nx; ++k) {
      const double X = grid_.Xc[k];
      const double w = std::max(0.0, 1.0 - X * X);
      const double s = (options_.bound == TractionBound::elliptic) ? tj * std::sqrt(w) : tj * tj * w;
      bound_shape_[j * nx + k] = s;
      strip += s * grid_.dX[k];
    }
    load += strip * tj * grid_.dY[j];  // dx = a t_j dX
  }
  const double exact = (options_.bound == TractionBound::elliptic) ? 2.0 * kPi / 3.0 : kPi / 2.0;
  load_scale_ = exact / load;
}

ContactForces Fastsim::compute(const ContactInput& in, TangentialWorkspace* /*ws*/) const {
  ContactForces out;
  if (!check_tangential_input(in, name_)) {
    out.stick_fraction = 1.0;
    return out;
  }
  const double a = in.patch.a;
  const double b = in.patch.b;
  const double Fz = in.patch.Fz;
  const double G = in.material.shear_modulus();
  const KalkerCoefficients C = kalker_coefficients(a / b, in.material.nu);
  // Traction gradients from xi [Pa/m], from eta, and from spin per metre of
  // lever arm [Pa/m^2]: xi / L1, eta / L2, phi / L3.
  double sx, sy, sp;
  if (options_.flexibility == FastsimFlexibility::blended) {
    double L1 = 8.0 * a / (3.0 * G * C.C11 * in.reduction.k11);
    double L2 = 8.0 * a / (3.0 * G * C.C22 * in.reduction.k22);
    double L3 = kPi * a * std::sqrt(a / b) / (4.0 * G * C.C23 * in.reduction.k23);
    blend(in, L1, L2, L3);
    sx = in.creep.xi / L1;
    sy = in.creep.eta / L2;
    sp = in.creep.phi / L3;
  } else {
    // Kalker's flexibilities: xi / L1 = xi (3 G k11 / 8a) C11 and alike, the
    // factors before C computed while kalker_coefficients runs, so that its
    // result meets one multiplication instead of two chained divisions (the
    // chain from a/b to the march is the call's critical path; equal to rounding).
    const double f12 = 3.0 * G / (8.0 * a), f3 = 4.0 * G / (kPi * a * std::sqrt(a / b));
    sx = in.creep.xi * (f12 * in.reduction.k11) * C.C11;
    sy = in.creep.eta * (f12 * in.reduction.k22) * C.C22;
    sp = in.creep.phi * (f3 * in.reduction.k23) * C.C23;
  }
  const double p0 = ((options_.bound == TractionBound::elliptic) ? 3.0 * Fz / (2.0 * kPi * a * b)
                                                                 : 2.0 * Fz / (kPi * a * b)) *
                    load_scale_;
  const double gmax = in.material.mu * p0;

  const auto nx = static_cast<std::size_t>(grid_.nx);
  const auto ny = static_cast<std::size_t>(grid_.ny);
  const double* step = grid_.step.data();
  const double* step_mid = grid_.step_mid.data();
  const double* dX = grid_.dX.data();
  const double* centre_dX = grid_.centre_dX.data();
  // One strip's march state. Per step (normalised by a_j): px -= (xi - phi
  // y)/L1 dx, py -= (eta/L2 + phi x/L3) dx, then the traction bound.
  struct March {
    double cx, cy, cp;  // per-step increments
    const double* bnd;  // the strip's normalised bound
    double px = 0.0, py = 0.0, fx = 0.0, fy = 0.0, mz = 0.0, adh = 0.0;  // per a_j (mz per a_j^2)
  };
  const auto start = [&](std::size_t j) {
    const double y = b * grid_.Y[j], aj = a * grid_.t[j];
    return March{(sx - sp * y) * aj, sy * aj, sp * aj * aj, &bound_shape_[j * nx]};
  };
  const auto advance = [&](March& m, std::size_t k) {
    m.px -= m.cx * step[k];
    m.py -= m.cy * step[k] + m.cp * step_mid[k];
    const double g = gmax * m.bnd[k];
    const double q2 = m.px * m.px + m.py * m.py;
    if (q2 > g * g) {
      const double s = g / std::sqrt(q2);
      m.px *= s;
      m.py *= s;
    } else {
      m.adh += dX[k];
    }
    m.fx += m.px * dX[k];
    m.fy += m.py * dX[k];
    m.mz += m.py * centre_dX[k];
  };
  StripSums sums;
  const auto finish = [&](std::size_t j, const March& m) {
    const double y = b * grid_.Y[j], aj = a * grid_.t[j];
    sums.add(m.fx * aj, m.fy * aj, m.mz * aj * aj, y, aj, m.adh * aj, b * grid_.dY[j]);
  };
  // Strips in groups (for_strip_groups): their marches overlap; summed in strip order.
  const auto group = [&]<std::size_t N>(std::size_t j0, std::integral_constant<std::size_t, N>) {
    March m[N];
    for (std::size_t i = 0; i < N; ++i) m[i] = start(j0 + i);
    for (std::size_t k = 0; k < nx; ++k)
      for (std::size_t i = 0; i < N; ++i) advance(m[i], k);
    for (std::size_t i = 0; i < N; ++i) finish(j0 + i, m[i]);
  };
  // Up to 7 strips (a 5 x 5 grid) one at a time: a strip's short march fits
  // the processor's window on its own, and five marches side by side spill
  // registers (callgrind, 5 x 5: 2,068 -> 1,890 instructions a call for
  // fastsim_kalker, 2,148 -> 1,971 blended; 8ae1583's per-strip loop 1,920).
  if (ny <= 7) {
    for (std::size_t j = 0; j < ny; ++j) group(j, std::integral_constant<std::size_t, 1>{});
  } else {
    for_strip_groups(ny, group);
  }
  return strip_model_result(name_, in, sums);
}

std::unique_ptr<TangentialModel> make_fastsim(const TangentialModelOptions& options) {
  FastsimOptions o;  // 20 x 20, blended flexibilities, elliptic bound
  o.nx = o.ny = StripGrid::size_option(options, "fastsim", o.nx);
  return std::make_unique<Fastsim>(o);
}

std::unique_ptr<TangentialModel> make_fastsim_kalker(const TangentialModelOptions& options) {
  FastsimOptions o;
  o.flexibility = FastsimFlexibility::three;
  o.nx = o.ny = StripGrid::size_option(options, "fastsim_kalker", o.nx);
  return std::make_unique<Fastsim>(o, "fastsim_kalker");
}

std::unique_ptr<TangentialModel> make_fastsim_parabolic(const TangentialModelOptions& options) {
  FastsimOptions o;
  o.flexibility = FastsimFlexibility::three;
  o.bound = TractionBound::parabolic;
  o.nx = o.ny = StripGrid::size_option(options, "fastsim_parabolic", o.nx);
  return std::make_unique<Fastsim>(o, "fastsim_parabolic");
}

}  // namespace railsim::contact
