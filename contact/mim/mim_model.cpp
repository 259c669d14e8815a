// The exact contact solver facade and the tangential model "mim"; see mim_model.hpp.
#include "contact/mim/mim_model.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "contact/hertz.hpp"
#include "contact/mim/convolution.hpp"
#include "core/errors.hpp"

namespace railsim::contact::mim {

namespace {
std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

void check_material(const Material& m) {
  if (!(m.E > 0.0) || !std::isfinite(m.E))
    throw InputError("mim: Young's modulus E must be positive (got " + num(m.E) + ")");
  if (!(m.nu > 0.0 && m.nu <= 0.5))
    throw InputError("mim: Poisson's ratio nu must lie in (0, 0.5] (got " + num(m.nu) + ")");
  if (!(m.mu >= 0.0) || !std::isfinite(m.mu))
    throw InputError("mim: friction coefficient mu must be >= 0 and finite (got " + num(m.mu) + ")");
}

// A field of grid `from` interpolated bilinearly between its element centres
// at the element centres of grid `to` (zero beyond `from`'s outer centres).
// Continuous in position, so a field with a mirror symmetry keeps it.
void sample_on_grid(const ContactGrid& from, const double* f, const ContactGrid& to, double* out) {
  const auto value = [&](int i, int j) {
    return (i >= 0 && i < from.mx && j >= 0 && j < from.my) ? f[from.index(i, j)] : 0.0;
  };
  for (int j = 0; j < to.my; ++j) {
    const double sy = (to.y(j) - from.y0) / from.dy - 0.5;
    const int j0 = static_cast<int>(std::floor(sy));
    const double wy = sy - j0;
    for (int i = 0; i < to.mx; ++i) {
      const double sx = (to.x(i) - from.x0) / from.dx - 0.5;
      const int i0 = static_cast<int>(std::floor(sx));
      const double wx = sx - i0;
      out[to.index(i, j)] = (1.0 - wy) * ((1.0 - wx) * value(i0, j0) + wx * value(i0 + 1, j0)) +
                            wy * ((1.0 - wx) * value(i0, j0 + 1) + wx * value(i0 + 1, j0 + 1));
    }
  }
}

void check_patch(const HertzPatch& p) {
  for (auto [v, name] : {std::pair{p.A, "A"}, {p.B, "B"}, {p.a, "a"}, {p.b, "b"}, {p.Fz, "Fz"}})
    if (!(v > 0.0) || !std::isfinite(v))
      throw InputError(std::string("mim: Hertz patch ") + name + " must be positive and finite (got " + num(v) + ")");
}
}  // namespace

void MimOptions::check() const {
  if (grid < 4 || grid > 4000)
    throw InputError("mim: grid (elements across the minor axis) must lie in [4, 4000] (got " +
                     std::to_string(grid) + ")");
  if (!(tolerance > 0.0 && tolerance <= 0.1))
    throw InputError("mim: tolerance must lie in (0, 0.1] (got " + num(tolerance) + ")");
  if (!(normal_tolerance > 0.0 && normal_tolerance <= 0.1))
    throw InputError("mim: normal tolerance must lie in (0, 0.1] (got " + num(normal_tolerance) + ")");
  if (max_iterations < 1) throw InputError("mim: max_iterations must be >= 1");
  layer.check();
}

MimSolver::MimSolver(const MimOptions& options) : opt_(options) { opt_.check(); }

double mim_memory_estimate(int mx, int my) {
  const double n0 = fft_friendly_size(2 * my - 1), n1 = fft_friendly_size(2 * mx - 1);
  const double nc = std::floor(n1 / 2) + 1;
  return 3 * 8 * n0 * n1 + 9 * 16 * n0 * nc + 700.0 * mx * my;
}

void MimSolver::prepare(const ContactGrid& grid, const Material& material) {
  grid.check("mim");
  check_material(material);
  // Bounded memory: refuse before allocating.
  if (const double bytes = mim_memory_estimate(grid.mx, grid.my); bytes > kMaxMimBytes) {
    char buf[256];
    std::snprintf(buf, sizeof buf,
                  "mim: a grid of %d x %d elements needs about %.3g GB of memory, more than the limit of %.3g GB; "
                  "use fewer elements across the minor axis (grid, --grid; the patch's a/b sets the other side)",
                  grid.mx, grid.my, bytes / 1e9, kMaxMimBytes / 1e9);
    throw InputError(buf);
  }
  const ElasticPair pair{material.shear_modulus(), material.nu, 0.0};
  const double layer = opt_.layer.compliance();
  if (!op_ || !op_->matches(grid, pair, layer)) {
    const bool resize = !op_ || op_->grid().size() != grid.size();
    op_ = std::make_unique<InfluenceOperator>(grid, pair, layer, opt_.fftw_flags);
    have_previous_ = false;
    have_normal_ = false;
    if (resize) {
      const int n = grid.size();
      nsolver_ = std::make_unique<NormalSolver>(n);
      tsolver_ = std::make_unique<TangentialSolver>(n);
      gap_.assign(n, 0.0);
      wx_.assign(n, 0.0);
      wy_.assign(n, 0.0);
      bound_.assign(n, 0.0);
      sol_.pn.assign(n, 0.0);
      sol_.px.assign(n, 0.0);
      sol_.py.assign(n, 0.0);
      sol_.state.assign(n, ElementState::Exterior);
    }
  }
  sol_.grid = op_->grid();
  sol_.tangential = TangentialResult{};
}

void MimSolver::normal(const std::vector<double>& gap, double Fz, const MimSolution* start) {
  if (!(Fz > 0.0) || !std::isfinite(Fz)) throw InputError("mim: normal load Fz must be positive (got " + num(Fz) + ")");
  if (static_cast<int>(gap.size()) != sol_.grid.size())
    throw InputError("mim: gap has " + std::to_string(gap.size()) + " values, grid has " +
                     std::to_string(sol_.grid.size()) + " elements");
  for (double v : gap)
    if (!std::isfinite(v)) throw InputError("mim: gap values must be finite");
  // The same normal problem as last time on this operator: its solution stands
  // (sol_.pn and sol_.normal are untouched since; the solver is deterministic).
  if (have_normal_ && Fz == normal_Fz_ && gap == normal_gap_) return;
  have_normal_ = false;
  NormalOptions no;
  no.tolerance = opt_.normal_tolerance;
  if (start != nullptr && start != &sol_ && start->grid.size() > 0) {
    sample_on_grid(start->grid, start->pn.data(), sol_.grid, sol_.pn.data());
    no.initial_guess = true;
  }
  sol_.normal = nsolver_->solve_load(*op_, gap.data(), Fz, sol_.pn.data(), no);
  sol_.Fz = sol_.normal.load;
  sol_.approach = sol_.normal.approach;
  sol_.n_contact = sol_.normal.n_contact;
  if (!sol_.normal.converged && opt_.throw_on_failure)
    throw NumericalError("mim: normal solver did not converge in " + std::to_string(sol_.normal.iterations) +
                         " iterations (Fz = " + num(Fz) + " N, residual " + num(sol_.normal.residual) + ")");
  if (sol_.normal.converged) {
    have_normal_ = true;
    normal_gap_ = gap;
    normal_Fz_ = Fz;
  }
}

void MimSolver::tangential(TangentialProblem kind, double w1, double w2, double w3, double mu) {
  const ContactGrid& g = sol_.grid;
  // Spin's rigid slip at x_i + dx/6, consistent with the rolling step (mim_model.hpp).
  const double spin_dx = g.dx / 6.0;
  for (int j = 0; j < g.my; ++j)
    for (int i = 0; i < g.mx; ++i) {
      const int q = g.index(i, j);
      if (kind == TangentialProblem::SteadyRolling) {
        wx_[q] = w1 - w3 * g.y(j);              // xi - phi y
        wy_[q] = w2 + w3 * (g.x(i) + spin_dx);  // eta + phi x
      } else {
        wx_[q] = w1;
        wy_[q] = w2;
      }
      bound_[q] = opt_.layer.bound(mu, sol_.pn[q]);
    }
  TangentialOptions to;
  to.tolerance = opt_.tolerance;
  to.max_iterations = opt_.max_iterations;
  to.warm_start = opt_.warm_start && have_previous_ && previous_kind_ == kind;
  sol_.tangential = tsolver_->solve(*op_, kind, wx_.data(), wy_.data(), bound_.data(), sol_.px.data(),
                                    sol_.py.data(), sol_.state.data(), to);
  have_previous_ = sol_.tangential.converged;
  previous_kind_ = kind;
  double Fx = 0.0, Fy = 0.0, Mz = 0.0;
  for (int j = 0; j < g.my; ++j)
    for (int i = 0; i < g.mx; ++i) {
      const int q = g.index(i, j);
      Fx += sol_.px[q];
      Fy += sol_.py[q];
      Mz += g.x(i) * sol_.py[q] - g.y(j) * sol_.px[q];
    }
  const double dA = g.element_area();
  sol_.Fx = Fx * dA;
  sol_.Fy = Fy * dA;
  sol_.Mz = Mz * dA;
  sol_.n_adhesion = sol_.tangential.n_adhesion;
  sol_.n_slip = sol_.tangential.n_slip;
  if (!sol_.tangential.converged && opt_.throw_on_failure)
    throw NumericalError("mim: tangential solver (" +
                         std::string(kind == TangentialProblem::SteadyRolling ? "steady rolling" : "shift") +
                         ") did not converge in " + std::to_string(sol_.tangential.iterations) +
                         " iterations (residual " + num(sol_.tangential.residual) + ", tolerance " +
                         num(opt_.tolerance) + "; w = " + num(w1) + ", " + num(w2) + ", " + num(w3) + ")");
}

const MimSolution& MimSolver::solve_normal(const ContactGrid& grid, const std::vector<double>& gap, double Fz,
                                           const Material& material) {
  prepare(grid, material);
  normal(gap, Fz);
  std::fill(sol_.px.begin(), sol_.px.end(), 0.0);
  std::fill(sol_.py.begin(), sol_.py.end(), 0.0);
  sol_.Fx = sol_.Fy = sol_.Mz = 0.0;
  have_previous_ = false;
  return sol_;
}

const MimSolution& MimSolver::solve_gap(const ContactGrid& grid, const std::vector<double>& gap, double Fz,
                                        const Creepages& creep, const Material& material) {
  for (double v : {creep.xi, creep.eta, creep.phi})
    if (!std::isfinite(v)) throw InputError("mim: creepages must be finite");
  prepare(grid, material);
  normal(gap, Fz);
  tangential(TangentialProblem::SteadyRolling, creep.xi, creep.eta, creep.phi, material.mu);
  return sol_;
}

const MimSolution& MimSolver::solve_hertz(const HertzPatch& patch, const Creepages& creep,
                                          const Material& material, const MimSolution* start) {
  check_patch(patch);
  const ContactGrid g = grid_for_patch(patch.a, patch.b, opt_.grid);
  prepare(g, material);
  const ContactGrid& gg = sol_.grid;
  for (int j = 0; j < gg.my; ++j)
    for (int i = 0; i < gg.mx; ++i) gap_[gg.index(i, j)] = patch.A * gg.x(i) * gg.x(i) + patch.B * gg.y(j) * gg.y(j);
  for (double v : {creep.xi, creep.eta, creep.phi})
    if (!std::isfinite(v)) throw InputError("mim: creepages must be finite");
  normal(gap_, patch.Fz, start);
  tangential(TangentialProblem::SteadyRolling, creep.xi, creep.eta, creep.phi, material.mu);
  return sol_;
}

const MimSolution& MimSolver::solve_shift_hertz(const HertzPatch& patch, double Wx, double Wy,
                                                const Material& material) {
  check_patch(patch);
  if (!std::isfinite(Wx) || !std::isfinite(Wy)) throw InputError("mim: shift must be finite");
  const ContactGrid g = grid_for_patch(patch.a, patch.b, opt_.grid);
  prepare(g, material);
  const ContactGrid& gg = sol_.grid;
  for (int j = 0; j < gg.my; ++j)
    for (int i = 0; i < gg.mx; ++i) gap_[gg.index(i, j)] = patch.A * gg.x(i) * gg.x(i) + patch.B * gg.y(j) * gg.y(j);
  normal(gap_, patch.Fz);
  tangential(TangentialProblem::Shift, Wx, Wy, 0.0, material.mu);
  return sol_;
}

namespace {

// The model's a/b domain (MimModel::compute).
constexpr double kMinAspect = 0.01, kMaxAspect = 100.0;

class MimWorkspace final : public TangentialWorkspace {
 public:
  MimWorkspace(const MimOptions& o, const MimOptions* half)
      : solver(o), coarse(half ? std::make_unique<MimSolver>(*half) : nullptr) {}
  MimSolver solver;                   // the grid N
  std::unique_ptr<MimSolver> coarse;  // the half grid N/2 (Richardson extrapolation only)
};

// Tangential model "mim": the exact steady-rolling solution for the Hertzian
// patch of the input. Reduction factors scale the creepages (k11 xi, k22 eta,
// k23 phi), the normalised-table interpretation of physics-reference sec. 11.
//
// Richardson extrapolation (default; Richardson 1911, the h -> 0 limit of a
// first-order method): the forces converge linearly with the element size h
// (first-order rolling step, mim_model.hpp), F_N = F + C h, so with the half
// grid N_c = N/2 (rounded down; element size exactly 2 h when N is even)
//   F = (N F_N - N_c F_c) / (N - N_c)            (2 F_N - F_{N/2} for even N).
// Measured on tests/data/contact/spin_reference (764 states, a/b 0.2 - 5):
// extrapolated grid 60 against extrapolated grid 120 within 0.232 % of mu Fz
// (mean 0.03 %), where the plain grids differ by up to 0.487 % (mean 0.07 %);
// the half-grid solve adds about 20 % to the cost. Tried and not taken: a
// second-order upwind rolling step (3 u_i - 4 u_{i+1} + u_{i+2})/(2 dx)
// converges pure creepage with h^2 but leaves spin cases first-order (worst
// state 0.506 % between grid 60 and 120). Stick fraction and iterations
// describe the grid N solve.
class MimModel final : public TangentialModel {
 public:
  MimModel(const MimOptions& o, bool richardson) : opt_(o), half_(o), richardson_(richardson) {
    opt_.check();
    if (richardson_ && opt_.grid < 8)
      throw InputError("mim: Richardson extrapolation needs a grid of at least 8 elements across the minor axis "
                       "(got " + std::to_string(opt_.grid) + "); use a finer grid (--grid) or no extrapolation "
                       "(--extrapolation none)");
    half_.grid = opt_.grid / 2;
  }
  std::string_view name() const override { return "mim"; }
  std::unique_ptr<TangentialWorkspace> make_workspace() const override {
    return std::make_unique<MimWorkspace>(opt_, richardson_ ? &half_ : nullptr);
  }
  ContactForces compute(const ContactInput& in, TangentialWorkspace* ws) const override {
    std::unique_ptr<MimWorkspace> local;
    auto* w = dynamic_cast<MimWorkspace*>(ws);
    if (!w) {
      local = std::make_unique<MimWorkspace>(opt_, richardson_ ? &half_ : nullptr);
      w = local.get();
    }
    HertzPatch patch = in.patch;
    if (!(patch.a > 0.0) || !(patch.b > 0.0)) patch = hertz_from_load(patch.A, patch.B, patch.Fz, in.material);
    // a/b outside [kMinAspect, kMaxAspect]: the grid's long side grows with the ratio into minutes and
    // gigabytes (a 1 N flange patch of a/b 385 in `railsim wheelset-contact`: 63 s, 1.5 GB, within the memory
    // cap). The patch is solved at the nearest edge of the domain with its size sqrt(ab) and load kept, as
    // mim_table holds a/b at its table's edge, and flagged invalid. Wheel-rail patches lie within a/b
    // 0.05-20; `railsim contact` refuses a case outside this domain (support_contact_cases.cpp).
    const double aspect = patch.a / patch.b;
    const bool held = aspect > 0.0 && std::isfinite(aspect) &&  // else: solve_hertz refuses the patch, naming it
                      !(aspect >= kMinAspect * (1 - 1e-9) && aspect <= kMaxAspect * (1 + 1e-9));
    if (held) {
      const double size = std::sqrt(patch.a * patch.b), r = std::sqrt(std::clamp(aspect, kMinAspect, kMaxAspect));
      patch = hertz_from_semi_axes(size * r, size / r, patch.Fz, in.material);
    }
    const Creepages c{in.reduction.k11 * in.creep.xi, in.reduction.k22 * in.creep.eta,
                      in.reduction.k23 * in.creep.phi};
    // The half grid first: its pressure starts the fine grid's normal iteration.
    const MimSolution* h = w->coarse ? &w->coarse->solve_hertz(patch, c, in.material) : nullptr;
    const MimSolution& s = w->solver.solve_hertz(patch, c, in.material, h);
    ContactForces f;
    f.Fx = s.Fx;
    f.Fy = s.Fy;
    f.Mz = s.Mz;
    f.iterations = s.normal.iterations + s.tangential.iterations;
    f.stick_fraction = s.n_contact > 0 ? static_cast<double>(s.n_adhesion) / s.n_contact : -1.0;
    bool converged = s.converged();
    if (h) {
      const double N = opt_.grid, Nc = half_.grid;
      auto extrapolate = [&](double fine, double coarse) { return (N * fine - Nc * coarse) / (N - Nc); };
      f.Fx = extrapolate(s.Fx, h->Fx);
      f.Fy = extrapolate(s.Fy, h->Fy);
      f.Mz = extrapolate(s.Mz, h->Mz);
      f.iterations += h->normal.iterations + h->tangential.iterations;
      converged = converged && h->converged();
    }
    if (held) {
      f.valid = false;
      f.reason = "mim: a/b outside [0.01, 100], MIM's domain (solved at its edge, sqrt(ab) and load kept)";
    }
    if (!converged) {
      f.valid = false;
      f.reason = "mim: solver did not converge";
    }
    return f;
  }

 private:
  MimOptions opt_, half_;
  bool richardson_;
};

}  // namespace
}  // namespace railsim::contact::mim

namespace railsim::contact {
std::unique_ptr<TangentialModel> make_mim(const TangentialModelOptions& options) {
  mim::MimOptions o;
  if (options.grid != 0) o.grid = options.grid;
  if (options.tolerance != 0.0) o.tolerance = options.tolerance;
  return std::make_unique<mim::MimModel>(o, options.extrapolation != GridExtrapolation::None);
}
}  // namespace railsim::contact
