// Wheel-rail coupling: the creep forces of one contact point from its
// creepages, normal load and patch, through the contact interface.
//
// Two ways, chosen by name (`tangential:` in the scenario):
//  - "coefficients": Kalker's linear theory with creep coefficients
//      f11 = G a b C11 k11, f22 = G a b C22 k22, f23 = G (ab)^{3/2} C23 k23,
//      f33 = G (ab)^2 C33 k23
//    taken from the contact-geometry table (a, b scaled by (N/N0)^{1/3},
//    Hertz) or prescribed at a reference load N_ref and scaled as
//    f11, f22 ~ N^{2/3}, f23 ~ N, f33 ~ N^{4/3} (a, b ~ N^{1/3});
//      Fx = -f11 xi,  Fy = -f22 eta - f23 phi,  Mz = f23 eta - f33 phi
//    (Kalker 1990 App. E; physics-reference §2.1), optionally saturated on the
//    resultant with the Shen-Hedrick-Elkins (1983) cubic as DYTSI does
//    (cooperrider-car.md §7.5): u = |F|/(mu N), |F|sat = mu N (u - u^2/3 + u^3/27)
//    for u < 3, else mu N; Mz scaled alike.
//  - any tangential model of the contact registry (contact/registry.hpp):
//    linear, chopaya, fastsim, ... called per contact with the Hertz patch,
//    creepages, material and reduction factors.
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
  std::string saturation = "none";  // coefficients only: none | she
  contact::Material material;       // E, nu, mu
  double shear_modulus = 0.0;       // G for creep forces; 0 = material.shear_modulus()
  contact::ReductionFactors reduction;
  // Prescribed creep coefficients at N_ref (coefficients mode); 0 = from the patch.
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
  WheelRailCoupling() = default;
  explicit WheelRailCoupling(const CouplingOptions& o);
  const CouplingOptions& options() const { return opt_; }
  // Tangential model (registry mode) or nullptr.
  const contact::TangentialModel* model() const { return model_.get(); }
  std::unique_ptr<contact::TangentialWorkspace> make_workspace() const;
  // Creep forces for one contact. N: normal load [N]; N_static: static load of
  // this wheel (reference when N_ref = 0). No allocation. `used` (optional):
  // receives the contact input the forces were computed from (patch at this
  // load, creepages, material, reductions; in both modes).
  contact::ContactForces forces(const ContactPointGeometry& g, double N, double N_static, const contact::Creepages& cr,
                                double V, contact::TangentialWorkspace* ws,
                                contact::ContactInput* used = nullptr) const;
  std::string describe() const;

 private:
  CouplingOptions opt_;
  std::shared_ptr<const contact::TangentialModel> model_;
  double G_ = 0.0;
};

}  // namespace railsim::engine
