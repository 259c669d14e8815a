// The tangential (creep-force) model interface.
//
// A model is built once from its options and never mutated while a vehicle is
// integrated. Models that need scratch memory (FASTSIM grids, the exact MIM
// solver) create it once through make_workspace(); solve() then does not
// allocate. Models without scratch memory return nullptr and ignore the pointer.
//
// The Coulomb bound is a law of the interface, not of each model: solve()
// returns the model's forces limited to |(Fx, Fy)| <= mu Fz
// (contact/coulomb_bound.hpp), where mu is the model's friction coefficient
// (friction_coefficient(); Material::mu unless the law has its own, e.g.
// Polach's slip-velocity-dependent mu). The only model exempt is Kalker's
// unsaturated linear theory ("linear"), which is the small-creepage reference
// by definition and flags large forces instead.
//
// Deep full slip: for a bounded model, creepages whose largest of |xi|, |eta|,
// |phi| sqrt(ab) exceeds kFullSlipCreepage are scaled down to it before
// compute() (the force no longer depends on their size, only on their
// ratios). A non-finite force from any model is a NumericalError naming the
// model and the contact.
//
// Models are created by name through the registry (registry.hpp).
#pragma once

#include <cmath>
#include <memory>
#include <string_view>

#include "contact/coulomb_bound.hpp"
#include "contact/types.hpp"

namespace railsim::contact {

// |creepage| beyond which a bounded model sees the creepage scaled down (above).
inline constexpr double kFullSlipCreepage = 1e6;

class TangentialWorkspace {
 public:
  virtual ~TangentialWorkspace() = default;
};

class TangentialModel {
 public:
  virtual ~TangentialModel() = default;
  // Registry name, e.g. "chopaya".
  virtual std::string_view name() const = 0;
  // Scratch memory for solve(); nullptr when the model needs none.
  virtual std::unique_ptr<TangentialWorkspace> make_workspace() const { return nullptr; }
  // Forces of the rail on the wheel for one contact, within the Coulomb bound
  // (see above; a force limited by more than 0.1 % is flagged invalid, saying why).
  // Inline, so that a call on a model of known type reaches compute() directly,
  // its result built in the caller's slot, and the bound is tested in place
  // (FASTSIM 5 x 5: the extra call level and the out-of-line bound cost about
  // 6 ns of a 177 ns call).
  ContactForces solve(const ContactInput& in, TangentialWorkspace* ws = nullptr) const {
    // Deep full slip (a bounded law): the force is mu Fz along a direction set by
    // the creepages' ratios alone, so creepages beyond kFullSlipCreepage are
    // scaled down to it, direction kept (their squares overflow beyond 1e154 and
    // the models' forces collapsed to 0 or NaN).
    const double k = kFullSlipCreepage, phi = in.creep.phi;
    const bool deep = std::abs(in.creep.xi) > k || std::abs(in.creep.eta) > k ||
                      phi * phi * std::abs(in.patch.a * in.patch.b) > k * k;
    ContactForces f = deep ? solve_deep_slip(in, ws) : compute(in, ws);
    if (!deep) [[likely]]
      check_and_bound(in, in, f);
    return f;
  }
  // The friction coefficient of the bound |F| <= mu Fz for this contact.
  virtual double friction_coefficient(const ContactInput& in) const { return in.material.mu; }
  // False only for the unsaturated linear theory.
  virtual bool coulomb_bounded() const { return true; }

 protected:
  // The model's own forces (before the Coulomb bound).
  virtual ContactForces compute(const ContactInput& in, TangentialWorkspace* ws) const = 0;

 private:
  // solve() beyond kFullSlipCreepage (kept out of the common path).
  ContactForces solve_deep_slip(const ContactInput& in, TangentialWorkspace* ws) const;
  // The model's forces f for `in`, computed for `used` (in itself, or its
  // creepages scaled down to kFullSlipCreepage): NumericalError when not
  // finite, then the Coulomb bound with the model's friction coefficient for
  // `used`. apply_coulomb_bound is called only for a force not clearly inside
  // the bound (|F|^2 < (1 - 1e-9) (mu Fz)^2 cannot round to |F| > mu Fz), so the
  // result is that of calling it always.
  void check_and_bound(const ContactInput& in, const ContactInput& used, ContactForces& f) const {
    if (!std::isfinite(f.Fx + f.Fy + f.Mz)) [[unlikely]]
      throw_non_finite(in);
    if (coulomb_bounded() && in.patch.Fz > 0.0) {
      const double muFz = friction_coefficient(used) * in.patch.Fz;
      if (!(f.Fx * f.Fx + f.Fy * f.Fy < (1.0 - 1e-9) * (muFz * muFz))) apply_coulomb_bound(f, muFz);
    }
  }
  // NumericalError naming the model and the contact `in`.
  [[noreturn]] void throw_non_finite(const ContactInput& in) const;
};

}  // namespace railsim::contact
