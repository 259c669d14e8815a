// Semi-Hertzian normal contact after Ayasse & Chollet (STRIPES).
//
// J.-B. Ayasse, H. Chollet, "Determination of the wheel rail contact patch in
// semi-Hertzian conditions", Vehicle System Dynamics 43(3), 161-172 (2005);
// physics-reference.md sec. 5.2. The patch is cut into longitudinal strips at
// lateral positions q (contact-plane lateral coordinate). Input: the undeformed
// normal gap h(q) across the contact plane and the local longitudinal relative
// curvature A(q) (wheel_rail_geometry.hpp: gap_profile).
// 1. Reference point q0 = argmin h. Equivalent lateral curvature B_e: least
//    squares h - h(q0) = B_e (q - q0)^2 over the interpenetrated part around q0
//    (exact when the profiles are quadratic).
// 2. Curvature correction: Hertz for (A(q0), B_e) gives the semi-axes a, b and
//    approach delta_H at any load. The virtual penetration delta_v = eps delta
//    with eps = B_e b^2 / delta_H and the corrected longitudinal curvature
//    A'(q) = c_A A(q) with c_A = B_e b^2 / (A a^2) make the interpenetration
//    contour of the undeformed profiles coincide with the Hertz ellipse when the
//    gap is quadratic.
// 3. Strip q: interpenetration g(q) = delta_v - (h(q) - h(q0)) > 0, half-length
//    x_L(q) = sqrt(g / A'(q)), semi-elliptic pressure
//    p(x,q) = P sqrt(g(q)/delta_v) sqrt(1 - x^2/x_L^2) (Hertz: P = p0).
//    Several zones (runs where the real interpenetration delta - h is
//    positive) each get the correction of 1.-2. from their own minimum h_z,
//    with delta_v,z = eps_z (delta - h_z): a multi-part patch. P and the
//    elastic condition (4.) belong to the main reference point.
// 4. Load-approach: the elastic approach at the reference point equals delta
//    (Boussinesq, two identical half-spaces: delta = 1/(pi E*) int p / rho dA,
//    as in Kik & Piotrowski 2008), so N = pi E* delta I1 / I2 with
//    I1 = int f dA, I2 = int f / rho dA. The strip integrals of 1/rho are done
//    in closed form across the strip width (asinh) and along x by a kernel
//    G(d/L) tabulated once (tanh-sinh quadrature, cubic B-spline). For a
//    quadratic gap the result is Hertz up to the strip discretisation.
// Units SI (m, N, Pa). Load given as the normal force N.
#pragma once

#include <memory>
#include <vector>

#include "contact/geometry/wheel_rail_geometry.hpp"
#include "contact/types.hpp"

namespace railsim::contact {

struct SemiHertzStrip {
  double q = 0.0;       // lateral position in the contact plane [m]
  double x_half = 0.0;  // strip half-length [m]
  double p_max = 0.0;   // peak pressure of the strip [Pa]
};

struct SemiHertzResult {
  double Fn = 0.0;        // normal load [N]
  double approach = 0.0;  // elastic approach delta [m]
  double virtual_penetration = 0.0;  // delta_v [m]
  double area = 0.0;      // contact area [m^2]
  double p_max = 0.0;     // maximum pressure [Pa]
  double width = 0.0;     // lateral extent over all parts [m]
  double length = 0.0;    // largest strip length 2 x_L [m]
  int parts = 0;          // number of separate patch parts
  double B_equivalent = 0.0;  // B_e [1/m]
  int iterations = 0;
  std::vector<SemiHertzStrip> strips;  // loaded strips only
};

// Scratch for repeated solves (keeps the quadrature tables and buffers).
class SemiHertzWorkspace {
 public:
  SemiHertzWorkspace();
  ~SemiHertzWorkspace();
  struct Impl;
  Impl& impl() { return *impl_; }

 private:
  std::unique_ptr<Impl> impl_;
};

// Solve for the normal load Fn [N] on the gap profile. Throws InputError for
// bad input (non-uniform grid, non-positive load) and NumericalError when the
// iteration fails.
SemiHertzResult semi_hertz_from_load(const GapProfile& gap, double Fn, const Material& material,
                                     SemiHertzWorkspace& ws);

}  // namespace railsim::contact
