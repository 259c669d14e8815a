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

#include <memory>
#include <string_view>

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
  ContactForces solve(const ContactInput& in, TangentialWorkspace* ws = nullptr) const;
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
};

}  // namespace railsim::contact
