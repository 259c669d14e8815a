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
//    excess is removed from s).
//    Slip zone with spin: a strip slides from the first point (seen from the
//    leading edge) where the TOTAL traction q e + s reaches the bound, not from
//    Carter's pure-creepage split point d - a'. Behind that point the strip
//    theory adds nothing more (its increments q(x) - q(x_prev) are dropped) and
//    the total is marched as in FASTSIM: spin increments as above plus the
//    creepage pull s <- s - (xi/L1, eta/L2) dx with Kalker's
//    L1 = 8a/(3 G C11 k11), L2 = 8a/(3 G C22 k22), then the bound again.
//    Without spin q <= mu p everywhere, the bound is never hit and Carter's
//    solution is reproduced exactly; with pure spin q = 0 and the model is
//    FASTSIM with the elliptic bound. Without any pull the saturated strip
//    traction could not hold its direction against the accumulated spin
//    traction (creepage + spin near saturation lost up to 86 % of the force).
//    (Tried and rejected: spin's longitudinal slip -phi y_j inside the strip
//    theory, or a separate flexibility calibrated on C33: worse against
//    CONTACT's exact pure-spin curve than the single L3. Pulling only in
//    Carter's slip zone behind d - a' and keeping the strip-theory increments
//    there (the previous model): creepage + spin max 16.2 %, mean 7.6 %, worse
//    than FASTSIM, because the pure-creepage strip traction kept priority over
//    spin. Keeping the strip-theory increments in Carter's adhesion zone after
//    the bound is hit: max 12.0 %, mean 5.5 %, but worse with longitudinal
//    creepage + spin (11 - 12 % against 4 - 11 %).
//    Spreading spin's longitudinal slip into the strip's split only: no gain.)
// 5. Integration: the strip-theory traction is integrated analytically over
//    each element (force and first moment), the spin correction by the
//    midpoint rule at element centres; strips by the midpoint rule. The
//    compliances, L3 and the pressure are scaled by constants of the grid
//    (discretised / continuum moment) so that on ANY grid the small-creepage
//    slopes for xi, eta, phi (Fy) and the saturated force mu Fz are exact.
//    Pure creepage without spin is then independent of the grid along x.
//
// Accuracy (measured, see tests/contact_fastsim and `railsim compare-contact
// scenarios/compare_contact_cases.yaml`, MIM grid 60 as reference, error of the
// force vector relative to |F_MIM|): pure creepage max 2.5 %, mean 0.65 %
// (FASTSIM 6.0 %, 3.1 %), pure spin max 10.8 %, mean 3.6 % (FASTSIM 11.3 %,
// 3.9 %), creepage + spin max 13.6 %, mean 5.5 % (FASTSIM 15.2 %, 6.6 %),
// closer than FASTSIM on 8 of the 12 combined cases; on the failure map
// (lateral creepage x spin, 8 x 8, tread patch) max 6.3 % (FASTSIM 6.7 %).
// LIMITS: the wide patch (a/b = 0.4) with spin stays at 10 - 14 % (as FASTSIM:
// the Winkler spin part underestimates the lateral spin force there); small
// lateral creepage + spin on it is worse than FASTSIM (11.5 % against 6.6 %).
// The combined full-slip cases are FASTSIM's figures to 0.1 % (the strips
// slide almost from the leading edge). Mz with spin is no better than
// FASTSIM's. The coupling in Sichani's paper is presumably different.
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
  ContactForces compute(const ContactInput& in, TangentialWorkspace* ws) const override;
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
