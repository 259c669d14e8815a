// FASTSIM: Kalker's fast algorithm for the simplified theory of rolling contact.
//
// Source: Kalker, J.J. (1982) "A fast algorithm for the simplified theory of
// rolling contact", VSD 11, 1-13; flexibilities as in CONTACT's `simpflex`
// (physics-reference.md sections 3.1-3.3).
//
// Simplified (Winkler) theory: the tangential surface displacement is L times
// the local traction. The three flexibilities are chosen so that the no-slip
// limit reproduces Kalker's linear theory (section 2.1) exactly in the
// continuum:
//   L1 = 8a / (3 G C11 k11)            (longitudinal creepage xi)
//   L2 = 8a / (3 G C22 k22)            (lateral creepage eta)
//   L3 = pi a sqrt(a/b) / (4 G C23 k23) (spin phi)
// so reduction factors k_ij act as L/k (physics-reference section 11).
//
// Flexibility blending (default; Vollebregt & Voltr 2023, "Improved accuracy
// for FASTSIM using one or three flexibility values", VSD 61, 309-317, as in
// CONTACT's FASTSIM, user guide "Flexibilities of the simplified theory"):
// with three flexibilities the saturated traction follows the rigid slip
// weighted by 1/L1, 1/L2, 1/L3, not the rigid slip itself, which is wrong at
// large combined creepage and spin. The three are blended towards one
// creepage-weighted combination
//   L = (xi^2 + eta^2 + psi^2) / (xi^2/L1 + eta^2/L2 + psi^2/L3),
//   psi = phi (3 pi a / 32)   (spin as the creepage with the same moment of
//                              the no-slip traction: (pi a^2/4) / (8a/3)),
//   L_i <- (1 - w) L_i + w L,  w = min(1, f/3),
//   f = |(xi, eta, l phi)| / |(xi*, eta*, l phi*)|,
// with the saturation creepages xi* = mu Fz/(G c^2 C11 k11),
// eta* = mu Fz/(G c^2 C22 k22), phi* = mu Fz/(G c^3 C23 k23) and, as CONTACT
// (which works in mm and rad/mm), the length l = 1 mm. At small creepage
// w -> 0 and the linear-theory slopes are exact. (Our implementation of the
// blending from the description; not checked against output of CONTACT's
// FASTSIM, of which tests/data/reference/contact holds none.)
// Measured on railsim's exact reference set (tests/data/contact/spin_reference,
// MIM grid 120, 764 states, a/b 0.2 - 5, grid 20 x 20), max / mean error in %
// of mu Fz: blended 21.2 / 2.81, Kalker's three flexibilities 24.0 / 4.20,
// three + parabolic bound 22.2 / 5.06. Blending is the default ("fastsim");
// "fastsim_kalker" keeps the three, "fastsim_parabolic" is Kalker's original.
//
// Algorithm (strip marching): the ellipse x^2/a^2 + y^2/b^2 <= 1 is cut into
// ny strips (uniform or cosine spacing in y); each strip y_j is cut into nx
// elements (uniform or cosine spacing in x) and marched from its leading edge
// x = +a_j (traction zero) through the element centres x_k towards the
// trailing edge. Per step dx = x_{k-1} - x_k (particles move in -x):
//   p* = p_{k-1} - (xi/L1 - phi y_j/L3,  eta/L2 + phi x_mid/L3) dx
// and p_k = p* when |p*| <= g(x_k, y_j) (adhesion), else p_k = g p*/|p*| (slip).
// Tractions live at element centres, so the no-slip traction (linear in x for
// xi, eta) is integrated exactly by the midpoint rule; strips likewise:
//   Fx = sum p_x dA, Fy = sum p_y dA, Mz = sum (x p_y - y p_x) dA.
//
// Traction bound g = mu p(x, y):
//   elliptic (default, Hertz):  p = 3 Fz/(2 pi a b) sqrt(1 - x^2/a^2 - y^2/b^2)
//   parabolic (Kalker 1982):    p = 2 Fz/(pi a b)  (1 - x^2/a^2 - y^2/b^2)
// The pressure is scaled by a constant (fixed per grid) so that its
// discretised integral equals Fz exactly; full sliding then gives exactly
// |F| = mu Fz on any grid.
//
// Units: SI (m, N, Pa; spin 1/m). Signs as in contact/types.hpp (forces of the
// rail on the wheel; positive creepage gives negative force;
// Fx = -G c^2 C11 xi, Fy = -G c^2 C22 eta - G c^3 C23 phi,
// Mz = G c^3 C23 eta - G c^4 C33 phi in the linear limit; FASTSIM reproduces
// the C11, C22, C23 terms, not C33 nor the C23 term of Mz).
//
// The grid is a property of the model (built once); solve() allocates nothing
// and needs no workspace.
#pragma once

#include <memory>
#include <type_traits>
#include <vector>

#include "contact/registry.hpp"
#include "contact/tangential_model.hpp"

namespace railsim::contact {

enum class TractionBound { elliptic, parabolic };
// Flexibilities: Kalker's three (L1, L2, L3 per creepage component, exact
// linear-theory slopes) or CONTACT's blend of the three towards one combined
// flexibility at large creepage (Vollebregt & Voltr 2023; see below).
enum class FastsimFlexibility { three, blended };
enum class GridSpacing { uniform, cosine };

// One strip's result in a strip model: force per unit width (fx, fy), moment
// about the strip's own centre line per unit width mz, adhesion length adh.
struct StripForces {
  double fx = 0.0, fy = 0.0, mz = 0.0, adh = 0.0;
};

// Sums of a strip model over its strips: a strip at lateral position y of
// half-length x_half and width dy, with per-unit-width force (fx, fy), moment
// about its own centre line mz and adhesion length adh, adds its forces, its
// moment about the patch centre (mz - y fx), its area and its stick area.
struct StripSums {
  double Fx = 0.0, Fy = 0.0, Mz = 0.0, area = 0.0, stick = 0.0;
  void add(double fx, double fy, double mz, double y, double x_half, double adh, double dy) {
    Fx += fx * dy;
    Fy += fy * dy;
    Mz += (mz - y * fx) * dy;
    area += 2.0 * x_half * dy;
    stick += adh * dy;
  }
};

// Strip x element grid in coordinates normalised by the semi-axes
// (X = x/a_j along a strip, Y = y/b across strips). Shared by FASTSIM and FaStrip.
struct StripGrid {
  int nx = 0;                // elements per strip
  int ny = 0;                // strips
  std::vector<double> X;     // nx+1 element boundaries along a strip, X[0] = +1 (leading) ... X[nx] = -1
  std::vector<double> Xc;    // nx element centres (evaluation points), descending
  std::vector<double> dX;    // nx element widths
  std::vector<double> Y;     // ny strip centres in (-1, 1)
  std::vector<double> dY;    // ny strip widths (sum 2)
  std::vector<double> t;     // ny strip half-length factors sqrt(1 - Y^2): a_j = a t_j
  // Marching steps (per a_j): from the previous evaluation point (the leading
  // edge X = 1 for the first) to Xc[k], step[k] = Xc[k-1] - Xc[k], and the
  // step times its midpoint, step_mid[k] = step[k] (Xc[k-1] + Xc[k]) / 2;
  // the element's first moment centre_dX[k] = Xc[k] dX[k].
  std::vector<double> step, step_mid, centre_dX;

  // Build; nx, ny >= 2 (InputError otherwise).
  static StripGrid make(int nx, int ny, GridSpacing spacing_x, GridSpacing spacing_y);
  // The registry's grid option for a strip model: N gives N x N elements, N in
  // [2, 1000] (InputError naming `model` otherwise); 0 keeps `fallback`.
  static int size_option(const TangentialModelOptions& options, const char* model, int fallback);
};

// The strips [0, ny) of a strip model in consecutive groups of N = 1..5
// strips, group(j0, std::integral_constant<std::size_t, N>{}) for each (fours;
// the rest as 5, 3+3, 4+3, 3, 2 or 1, so that a strip is left alone only when
// ny = 1). A model marches the strips of one group in one loop: each strip's
// march is a chain of dependent operations (a square root and a division
// where the traction bound acts), and independent chains side by side
// overlap in the processor (FASTSIM 20 x 20: 1.9 -> 1.0 us a call). The
// arithmetic per strip is that of one strip at a time.
template <class Group>
void for_strip_groups(std::size_t ny, Group&& group) {
  using F1 = std::integral_constant<std::size_t, 1>;
  using F2 = std::integral_constant<std::size_t, 2>;
  using F3 = std::integral_constant<std::size_t, 3>;
  using F4 = std::integral_constant<std::size_t, 4>;
  using F5 = std::integral_constant<std::size_t, 5>;
  std::size_t j = 0;
  for (; ny - j >= 8; j += 4) group(j, F4{});
  switch (ny - j) {  // 0 to 7 strips left
    case 7:
      group(j, F4{});
      group(j + 4, F3{});
      break;
    case 6:
      group(j, F3{});
      group(j + 3, F3{});
      break;
    case 5: group(j, F5{}); break;
    case 4: group(j, F4{}); break;
    case 3: group(j, F3{}); break;
    case 2: group(j, F2{}); break;
    case 1: group(j, F1{}); break;
    default: break;
  }
}

// NumericalError for a non-finite strip-model force, naming the model and the
// patch (out of line: strip_model_result's fast path then needs no stack frame).
[[noreturn]] void throw_non_finite_strip_force(const char* model, const ContactInput& in);

// Result of a strip model from its sums over the strips (forces, moment, stick
// and total area); NumericalError naming the model and the patch when a force
// is not finite. One test for the three: x * 0 is +-0 for a finite x and NaN for
// an infinity or NaN, and a sum of zeros is zero (FASTSIM 5 x 5: the three
// isfinite tests and the out-of-line call cost 3-4 ns of a 160 ns call).
inline ContactForces strip_model_result(const char* model, const ContactInput& in, const StripSums& sums) {
  if (!(sums.Fx * 0.0 + sums.Fy * 0.0 + sums.Mz * 0.0 == 0.0)) [[unlikely]]
    throw_non_finite_strip_force(model, in);
  ContactForces out;
  out.Fx = sums.Fx;
  out.Fy = sums.Fy;
  out.Mz = sums.Mz;
  out.stick_fraction = sums.area > 0.0 ? sums.stick / sums.area : 1.0;
  return out;
}

struct FastsimOptions {
  int nx = 20;  // elements per strip (rolling direction)
  int ny = 20;  // strips (lateral)
  TractionBound bound = TractionBound::elliptic;
  FastsimFlexibility flexibility = FastsimFlexibility::blended;
  GridSpacing spacing_x = GridSpacing::uniform;
  GridSpacing spacing_y = GridSpacing::uniform;
};

class Fastsim final : public TangentialModel {
 public:
  explicit Fastsim(const FastsimOptions& options = {}, const char* name = "fastsim");
  std::string_view name() const override { return name_; }
  ContactForces compute(const ContactInput& in, TangentialWorkspace* ws) const override;
  const FastsimOptions& options() const { return options_; }

 private:
  FastsimOptions options_;
  const char* name_;  // registry name (static text)
  StripGrid grid_;
  std::vector<double> bound_shape_;  // ny*(nx+1): normalised bound at each node (t_j sqrt(1-X^2) or t_j^2 (1-X^2))
  double load_scale_ = 1.0;          // continuum load / discretised load of the pressure shape
};

// CONTACT's blend of Kalker's flexibilities (L1, L2, L3 in/out: Kalker's
// 8a/(3 G C11), 8a/(3 G C22), pi a sqrt(a/b)/(4 G C23), with the reduction
// factors) towards one combined flexibility at large creepage (Vollebregt &
// Voltr 2023).
void blend_flexibilities(const ContactInput& in, double& L1, double& L2, double& L3);

// Checks shared by FASTSIM and FaStrip: returns false when there is no load
// (Fz <= 0: zero forces), throws InputError naming `model` on non-finite or
// non-positive semi-axes, a negative friction coefficient or bad material.
bool check_tangential_input(const ContactInput& in, const char* model);

// Registry factories ("fastsim" blended + elliptic; "fastsim_kalker" three
// flexibilities + elliptic; "fastsim_parabolic" three + parabolic):
// options.grid = N gives N x N (N in [2, 1000]); 0 = 20 x 20.
// Default 20 x 20 because the error at large spin is first order in the
// element length along the strips (pure spin, circular patch, vs CONTACT:
// 29 % at 10 x 10, 11.5 % at 20 x 20); cost about 3 us per call (bench_fastsim).
std::unique_ptr<TangentialModel> make_fastsim(const TangentialModelOptions& options);
std::unique_ptr<TangentialModel> make_fastsim_kalker(const TangentialModelOptions& options);
std::unique_ptr<TangentialModel> make_fastsim_parabolic(const TangentialModelOptions& options);

}  // namespace railsim::contact
