// FaStrip-type tangential model: Kalker's strip theory per strip with an
// analytic adhesion/slip split for the (longitudinal, lateral) creepage and a
// FASTSIM-like treatment of the lateral part of spin, with compliances chosen
// so that the small-creepage slopes equal Kalker's linear theory.
//
// Idea after Sichani, Enblom & Berg (2016) "An alternative to FASTSIM for
// tangential solution of the wheel-rail contact", VSD 54(6) 748-764
// (physics-reference.md section 3.6). THE PER-STRIP FORMULAS OF THAT PAPER
// WERE NOT AVAILABLE to us (not found in any public source we could search);
// what follows is our own derivation from the ingredients the paper names,
// and it is NOT claimed to be numerically identical to Sichani's FaStrip.
//
// Derivation (our own, from Carter 1926 / Kalker 1967 strip theory,
// Johnson 1985 section 8.2):
// 1. Hertz pressure p = p0 sqrt(1 - x^2/a^2 - y^2/b^2) restricted to a strip y
//    is semi-elliptic in x: p = p0_j sqrt(1 - x^2/a_j^2) with
//    a_j = a t_j, p0_j = p0 t_j, t_j = sqrt(1 - y^2/b^2).
// 2. Each strip is a 2-D steady rolling problem (Carter). With a uniform
//    rigid-slip "traction rate" vector w = (w_x, w_y) [Pa] the solution is
//    directed along -w/|w| and has magnitude
//      q(x) = mu p0_j / a_j [ sqrt(a_j^2 - x^2) - sqrt(a'^2 - (x - d)^2) ]
//    with the adhesion zone |x - d| < a' at the leading edge, d = a_j - a',
//    d / a_j = min(1, |w| / (mu p0_j)) (slip fraction, linear in creepage).
//    For a 2-D elastic half-plane w = xi / K with K = 2(1-nu)/G
//    (longitudinal); summed over strips this gives C11 = pi^2/(4(1-nu)),
//    Kalker's a << b asymptote, which checks the derivation.
// 3. Keeping the linear-theory slope: in the no-slip limit a strip carries
//    q = |w| sqrt((a_j - x)/(a_j + x)), whose integral is pi a_j |w|, so
//    Fx = -pi^2 a b xi / (2 Kx). Choosing
//      Kx = pi^2 / (2 G C11 k11),   Ky = pi^2 / (2 G C22 k22)
//    reproduces G ab C11 xi and G ab C22 eta for every a/b; w = (xi/Kx, eta/Ky).
// 4. Spin: FASTSIM-like. A Winkler traction s with Kalker's spin flexibility
//    L3 = pi a sqrt(a/b) / (4 G C23 k23) (which makes the Fy(phi) slope equal
//    to -G c^3 C23 phi) is marched from the leading edge through the element
//    centres,  s <- s + (phi y_j, -phi x_mid) dx / L3,
//    added to the strip-theory traction q e, and the total is returned
//    radially onto the elliptic traction bound mu p when it exceeds it (the
//    excess is removed from s). Without spin s stays zero and the strip
//    solution is reproduced exactly; with pure spin the model is FASTSIM
//    with the elliptic bound.
//    (Tried and rejected: spin's longitudinal slip -phi y_j inside the strip
//    theory, or a separate flexibility calibrated on C33. Against CONTACT's
//    exact pure-spin curve both were worse than the single L3.)
// 5. Integration: the strip-theory traction is integrated analytically over
//    each element (force and first moment), the spin correction by the
//    midpoint rule at element centres; strips by the midpoint rule. The
//    compliances, L3 and the pressure are scaled by constants of the grid
//    (discretised / continuum moment) so that on ANY grid the small-creepage
//    slopes for xi, eta, phi (Fy) and the saturated force mu Fz are exact.
//    Pure creepage without spin is then independent of the grid along x.
//
// Accuracy (measured, see tests/contact_fastsim): against CONTACT's exact
// curves for a circle, pure creepage 1.0-1.6 % (FASTSIM 6-7 %); pure spin as
// FASTSIM (12 % at 20 x 20). KNOWN WEAKNESS: creepage combined with spin. On
// nine live-MIM cases (grid 40, a/b 0.5-2, xi/eta 0.5e-3-2e-3, phi 1-3 1/m)
// the force error reached 23 % (xi 2e-3, eta 1e-3, phi 1.5 1/m: |F| too low)
// where FASTSIM had 8 %: adding the spin traction on top of the strip solution
// and returning the sum onto the bound loses force. The coupling of spin and
// strip theory in Sichani's paper is presumably different; until it is
// obtained, prefer fastsim (or mim_table) when spin and creepage combine.
//
// Units: SI (m, N, Pa, spin 1/m). Signs as contact/types.hpp: forces of the
// rail on the wheel, positive creepage gives negative force; in the linear
// limit Fx = -G c^2 C11 xi, Fy = -G c^2 C22 eta - G c^3 C23 phi exactly; the
// moment slopes are approximate: eta -> Mz comes out as (4/(3 pi)) C22 (a/b)^(1/2)
// instead of C23 (+7 % for a circle), phi -> Mz as FASTSIM's (-16 % on C33).
// Only the elliptic (Hertz) pressure is supported (Carter's solution needs it).
#pragma once

#include <memory>
#include <vector>

#include "contact/fastsim.hpp"
#include "contact/registry.hpp"
#include "contact/tangential_model.hpp"

namespace railsim::contact {

struct FastripOptions {
  int nx = 20;  // elements per strip (matters only with spin)
  int ny = 20;  // strips
  GridSpacing spacing_x = GridSpacing::uniform;
  GridSpacing spacing_y = GridSpacing::uniform;
};

class Fastrip final : public TangentialModel {
 public:
  explicit Fastrip(const FastripOptions& options = {});
  std::string_view name() const override { return "fastrip"; }
  ContactForces solve(const ContactInput& in, TangentialWorkspace* ws = nullptr) const override;
  const FastripOptions& options() const { return options_; }

 private:
  FastripOptions options_;
  StripGrid grid_;
  std::vector<double> sqc_;  // sqrt(1 - X^2) at the element centres
  std::vector<double> An_;   // 0.5 (X sqrt(1-X^2) + asin X) at the element boundaries
  std::vector<double> Bn_;   // -(1-X^2)^1.5 / 3 at the element boundaries
  // Grid constants (discretised moment / continuum moment), see step 5:
  double load_scale_ = 1.0;  // pressure factor (4/3) / sum t^2 dY
  double k_scale_ = 1.0;     // sum t dY / (pi/2)                      (xi, eta slopes)
  double l3_scale_ = 1.0;    // sum t^3 dY * sum (1 - Xc^2) dX / (pi/2) (spin Fy)
};

// Registry factory: options.grid = N gives N strips x N elements; 0 = 20 x 20.
std::unique_ptr<TangentialModel> make_fastrip(const TangentialModelOptions& options);

}  // namespace railsim::contact
