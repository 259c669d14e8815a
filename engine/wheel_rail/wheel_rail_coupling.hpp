// Wheel-rail coupling: the creep forces of one contact point from its
// creepages, normal load and patch, through the contact interface.
//
// The tangential model is chosen by name from the contact registry
// (`tangential:` in the scenario; contact/registry.hpp) and called per contact
// with the patch at the current load (the geometry's semi-axes at N0, or the
// prescribed patch at N_ref, scaled by (N/N0)^{1/3}, Hertz), the creepages,
// material and reduction factors. Every contact input also carries the
// geometry's creep coefficients (contact::GeometryCoefficients): the
// prescribed f11 ... f33 at N_ref (N_ref 0: the wheel's static load), else the
// contact table's C11, C22, C23; the model "coefficients" (contact/
// coefficients.cpp: Kalker's linear theory on them, saturation none | she as
// DYTSI, cooperrider-car.md §7.5) reads them, the other models ignore them.
// Forces are those of the rail on the wheel in the contact frame
// (contact/types.hpp).
#pragma once

#include <memory>
#include <string>

#include "contact/tangential_model.hpp"
#include "contact/types.hpp"
#include "engine/wheel_rail/contact_geometry.hpp"

namespace railsim::engine {

struct CouplingOptions {
  std::string tangential = "coefficients";
  std::string saturation = "none";  // model "coefficients" only: contact::saturation_laws()
  contact::Material material;       // E, nu, mu
  double shear_modulus = 0.0;       // G for the geometry's C_ij (model "coefficients"); 0 = material.shear_modulus()
  contact::ReductionFactors reduction;
  // Prescribed creep coefficients at N_ref (model "coefficients"); 0 = from the geometry.
  double f11 = 0.0, f22 = 0.0, f23 = 0.0, f33 = 0.0;
  double N_ref = 0.0;  // 0: the static wheel load
  // Patch semi-axes at N_ref when the geometry has none (conical wheels).
  double patch_a = 0.0, patch_b = 0.0;
  bool spin = true;    // include spin creepage
  // Full model: viscous damping of each wheel's normal approach [N s/m]
  // (wheelset_contact.hpp); 0 = none (DYTSI).
  double normal_damping = 0.0;
};

class WheelRailCoupling {
 public:
  WheelRailCoupling() : WheelRailCoupling(CouplingOptions{}) {}
  explicit WheelRailCoupling(const CouplingOptions& o);
  const CouplingOptions& options() const { return opt_; }
  // The tangential model (built once, from the registry).
  const contact::TangentialModel* model() const { return model_.get(); }
  std::unique_ptr<contact::TangentialWorkspace> make_workspace() const;
  // Creep forces for one contact. N: normal load [N]; N_static: static load of
  // this wheel (reference when N_ref = 0). No allocation. `used` (optional):
  // receives the contact input the forces were computed from (patch at this
  // load, creepages, material, reductions, the geometry's coefficients).
  contact::ContactForces forces(const ContactPointGeometry& g, double N, double N_static, const contact::Creepages& cr,
                                double V, contact::TangentialWorkspace* ws,
                                contact::ContactInput* used = nullptr) const;
  std::string describe() const;

 private:
  CouplingOptions opt_;
  std::shared_ptr<const contact::TangentialModel> model_;
};

}  // namespace railsim::engine
