// Hertz normal contact of two elastic bodies of the same material.
//
// Computes the elliptic contact patch (semi-axes a along x = rolling direction,
// b along y = lateral), the maximum pressure p0 and the approach (mutual normal
// approach of distant points) from the relative curvatures A (x) and B (y), the
// normal load Fz and the material; and the reverse (load from approach).
//
// Sources (physics-reference.md sections 1.2-1.5):
//   Hertz (1882); Johnson (1985) "Contact Mechanics" sec. 4.2, eq. (4.22) for E*.
//   Shape equation  A/B = [K(e) - E(e)] / [E(e)/(1-e^2) - K(e)]   (A <= B, a >= b),
//   a^3 = 3 Fz E(e) / (2 pi E* (A+B) (1-e^2)),  b = a sqrt(1-e^2),
//   p0 = 3 Fz / (2 pi a b),  approach = (A+B) b^2 K(e) / E(e),
//   with K, E complete elliptic integrals of PARAMETER m = e^2 (Boost.Math takes
//   the MODULUS k = e) and E* = E / (2 (1 - nu^2)) for identical materials.
//   The ellipse shape (g = b/a, K, E) from the curvature ratio comes from
//   hertz_shape.hpp: exact to double precision (piecewise Chebyshev table of the
//   root-found solution for B/A <= 1e4, the root-find itself beyond).
//
// Units: curvatures 1/m, lengths m, load N, pressure Pa. A and B are the sums of
// the principal curvatures of both bodies divided by two (gap h = A x^2 + B y^2).
// When A > B the patch is longer across (b > a); `a` is always along x.
#pragma once

#include "contact/hertz_shape.hpp"
#include "contact/types.hpp"

namespace railsim::contact {

// Hertz solution for a given normal load Fz [N]. Throws InputError when A, B or
// Fz is not a positive finite number or the material is invalid.
HertzPatch hertz_from_load(double A, double B, double Fz, const Material& m);

// Reverse problem: the load (and patch) that gives the approach [m].
// N = K_H approach^{3/2}. Throws InputError for non-positive inputs.
HertzPatch hertz_from_approach(double A, double B, double approach, const Material& m);

// Curvatures from a given patch: the relative curvatures A, B that make a patch
// with semi-axes a (x) and b (y) under the load Fz (shape equation used forwards,
// no root finding). Returns the full patch (A, B, a, b, p0, approach, Fz).
HertzPatch hertz_from_semi_axes(double a, double b, double Fz, const Material& m);

// Classical Hertz coefficients (Timoshenko; physics-reference.md sec. 1.3):
//   a = m [3 Fz / (4 E* (A+B))]^{1/3},  b = n [same]^{1/3},
//   approach = r [(9/16) Fz^2 (A+B) / E*^2]^{1/3},
// with m = [2 E(e) / (pi (1-e^2))]^{1/3}, n = m sqrt(1-e^2), r = 2 K(e) / (pi m)
// for the major axis. Here m belongs to the semi-axis along x and n to the one
// along y, so for A > B (b > a) m < n. r = 1 for a circle.
struct HertzCoefficients {
  double m, n, r;
};
HertzCoefficients hertz_coefficients(double A, double B);

// The load-dependent part alone, for a shape computed once with
// hertz_shape(min(A,B)/max(A,B)): the shape depends on the curvature ratio only,
// so wheel-rail geometry tables can store it and each time step costs a cube root.
// Same result as hertz_from_load(A, B, Fz, m).
HertzPatch hertz_from_shape(double A, double B, const HertzShape& shape, double Fz, const Material& m);

}  // namespace railsim::contact
