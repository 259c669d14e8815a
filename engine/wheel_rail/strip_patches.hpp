// Distributed normal contact of one wheel from its strips
// (contact/geometry/strip_contact_table.hpp): normal loads and contact
// patches for a given vertical approach of the wheel.
//
// Strip j (normal gap g_j at the rigid pose, contact angle delta_j, Winkler
// modulus kappa_j = E* f_j) is penetrated by
//   p_j = (w - side a_j dphi) cos(delta_j) - g_j             [m, normal]
// (w the wheel's vertical approach from the rigid pose, dphi the roll beyond
// the rigid pose's, a_j the strip's lateral position) and carries
// kappa_j p_j per unit width while p_j > 0. Between neighbouring strips the
// penetration is taken linear and integrated exactly up to its zero crossing
// (trapezoid, or the triangle up to the edge), and each strip receives half
// of each adjacent segment's load: W_j. The load of a wheel is thus
// continuous and piecewise smooth in w and in the pose, also where a patch
// opens, closes, or its load slides through the flange root (the rigid
// contact point jumps there; the loads do not). For a quadratic gap this is
// Hertz's N = K delta^{3/2} (the strips' f is calibrated so; up to the strip
// discretisation).
// Patches: runs of neighbouring loaded strips. Per patch the load N = sum W_j
// and the load-weighted angle, lateral position, lead, rolling radius (height
// below the axle) and longitudinal curvature A; its equivalent ellipse (for
// the tangential models) is Hertz's for the patch's A and the lateral
// curvature B_e of the parabola that has the patch's largest penetration p_max
// and its width at p_max/2 (exact for a quadratic gap).
// With PatchShape::semi_hertz the ellipse handed to the tangential models has
// instead the area and length of the semi-Hertzian patch of Ayasse & Chollet
// (2005; physics-reference sec. 5.2; contact/geometry/semi_hertz.hpp): with
// the Hertz ellipse (a, b) above at the approach delta = p_max, the virtual
// penetration eps delta, eps = B_e b^2 / delta, and the corrected curvature
// c_A A_j, c_A = B_e b^2 / (A a^2), each strip's virtual interpenetration
// g_j = p_j - (1 - eps) delta gives the half-length x_j = sqrt(g_j / (c_A A_j)).
// The patch's area S = int 2 x(q) dq (g linear between strips, integrated
// exactly) and its length 2 a_s, a_s = max x_j, give the ellipse a_s,
// b_s = S / (pi a_s). For a quadratic gap this is the Hertz ellipse; where
// the curvatures vary across the patch (flange root) its area and shape
// follow the profiles. The loads are the strips' either way. Units SI.
#pragma once

#include "contact/geometry/strip_contact_table.hpp"
#include "engine/wheel_rail/contact_geometry.hpp"

namespace railsim::engine {

// Shape of the ellipse a patch hands to the tangential models (above).
enum class PatchShape { hertz, semi_hertz };

struct StripLoads {
  int n = 0;                                          // patches
  ContactPointGeometry patch[WheelGeometry::kMaxPoints];  // semi-axes at the patch's load (N0 = N)
  double N[WheelGeometry::kMaxPoints] = {};
  double vertical = 0.0;    // sum over patches of N cos(delta + side phi_abs) (the wheel's vertical load)
  double rate_weight[WheelGeometry::kMaxPoints] = {};  // per patch: sum W_j cos(delta_j) (damping)
};

// Loads of one wheel's strips; phi_side = side x the wheelset's roll (for the
// vertical component), dphi_side = side x the roll beyond the rigid pose.
void strip_loads(const contact::StripSet& strips, double w, double dphi_side, double phi_side, double Es,
                 StripLoads& out, bool with_patches = true, PatchShape shape = PatchShape::hertz);

// The vertical approach w at which the wheel carries the vertical load Q
// (dphi = 0: the lateral model's roll is the rigid pose's), and the loads there;
// solved to 1e-10 Q (unless the bracket narrows to 1e-15 m or 100 evaluations
// pass first: out.vertical then tells what the loads carry). warm_start
// (optional, in and out): the approach above the wheel's smallest strip gap,
// where the solve starts (<= 0: 0.1 mm; else within [1 nm, 1 mm]) and, when
// solved to the tolerance, what it found (as MuJoCo's mjData::qacc_warmstart:
// the same wheel's last solution starts the next; the result then depends on
// it within the tolerance only).
double strip_approach_for_load(const contact::StripSet& strips, double Q, double phi_side, double Es, StripLoads& out,
                               PatchShape shape = PatchShape::hertz, double* warm_start = nullptr);

}  // namespace railsim::engine
