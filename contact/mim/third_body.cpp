// Third-body layer parameters and reduction factors; see third_body.hpp.
#include "contact/mim/third_body.hpp"

#include <cmath>
#include <string>

#include "contact/mim/mim_model.hpp"
#include "core/errors.hpp"

namespace railsim::contact::mim {

void ThirdBodyLayer::check() const {
  if (!(h >= 0.0) || !std::isfinite(h) || h > 0.1)
    throw InputError("third-body layer: thickness h must lie in [0, 0.1] m (got " + std::to_string(h) + ")");
  if (h > 0.0 && (!(G3 > 0.0) || !std::isfinite(G3)))
    throw InputError("third-body layer: shear modulus G3 must be positive when h > 0 (got " + std::to_string(G3) + ")");
  if (!(tau_limit >= 0.0) || !std::isfinite(tau_limit))
    throw InputError("third-body layer: limiting shear stress must be >= 0 (got " + std::to_string(tau_limit) + ")");
}

ReductionFactors third_body_reduction(const HertzPatch& patch, const Material& material,
                                      const ThirdBodyLayer& layer, int n_minor) {
  layer.check();
  // Linear theory: creepages small enough and friction large enough for full adhesion.
  Material m = material;
  m.mu = 1e4;
  const double c = std::sqrt(patch.a * patch.b);
  const double xi = 1e-6, phi = 1e-6 / c;
  auto coefficients = [&](const ThirdBodyLayer& l) {
    MimOptions o;
    o.grid = n_minor;
    o.layer = l;
    o.layer.tau_limit = 0.0;
    MimSolver s(o);
    const double Fx = s.solve_hertz(patch, {xi, 0.0, 0.0}, m).Fx;
    const double Fy = s.solve_hertz(patch, {0.0, xi, 0.0}, m).Fy;
    const double Fy_phi = s.solve_hertz(patch, {0.0, 0.0, phi}, m).Fy;
    return ReductionFactors{Fx, Fy, Fy_phi};
  };
  const ReductionFactors with = coefficients(layer);
  const ReductionFactors without = coefficients(ThirdBodyLayer{});
  return {with.k11 / without.k11, with.k22 / without.k22, with.k23 / without.k23};
}

}  // namespace railsim::contact::mim
