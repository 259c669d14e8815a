// The tangential (creep-force) model interface.
//
// A model is built once from its options and never mutated while a vehicle is
// integrated. Models that need scratch memory (FASTSIM grids, the exact MIM
// solver) create it once through make_workspace(); solve() then does not
// allocate. Models without scratch memory return nullptr and ignore the pointer.
//
// Models are created by name through the registry (registry.hpp).
#pragma once

#include <memory>
#include <string_view>

#include "contact/types.hpp"

namespace railsim::contact {

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
  // Forces of the rail on the wheel for one contact.
  virtual ContactForces solve(const ContactInput& in, TangentialWorkspace* ws) const = 0;
};

}  // namespace railsim::contact
