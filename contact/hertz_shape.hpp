// Shape of a Hertz contact ellipse from the ratio of the relative curvatures.
//
// Solves Hertz's shape equation (physics-reference.md sec. 1.4; Johnson 1985,
// "Contact Mechanics", eq. 4.39)
//   A/B = [K(e) - E(e)] / [E(e)/(1-e^2) - K(e)],   A <= B, b/a = g = sqrt(1 - e^2),
// for the semi-axis ratio g, with K, E the complete elliptic integrals of
// PARAMETER m = e^2 (Boost.Math takes the MODULUS k = e). Dimensionless.
//
// hertz_shape_exact: the reference solution. The equation is written in the
// cancellation-free Carlson form A/B = (1-m) R_D / (3 R_F - R_D) with
// R_F = R_F(0, 1-m, 1), R_D = R_D(0, 1-m, 1) (Carlson 1979; Boost.Math) and
// solved for ln(a/b) by Boost's safeguarded Newton-Raphson (bisection fallback)
// inside a guaranteed bracket, started from the least-squares fit of
// physics-reference.md sec. 1.5. Converged to < 1e-12 in ln(a/b); K and E are
// those of the returned g.
//
// hertz_shape: the same solution, fast. For B/A <= 1e4 (a/b up to ~480) g, K and
// E are read from piecewise Chebyshev interpolants in L = ln(B/A) (64 pieces of
// degree 7) built once from hertz_shape_exact; their error against the exact
// solution is below 1e-14 relative (tested), so the result is the exact solution
// to double precision at the cost of a logarithm and three polynomials. Beyond
// B/A = 1e4 it calls hertz_shape_exact.
#pragma once

namespace railsim::contact {

// The ellipse shape: g = minor/major semi-axis ratio in (0, 1], and K, E of
// parameter e^2 = 1 - g^2. For A <= B the major axis is along x.
struct HertzShape {
  double g;   // minor / major semi-axis
  double K;   // K(e), complete elliptic integral of the first kind
  double E;   // E(e), complete elliptic integral of the second kind
};

// ratio = min(A,B)/max(A,B) in [1e-10, 1]; throws InputError outside (with the
// range) and NumericalError if the root-find does not converge.
HertzShape hertz_shape(double ratio);
HertzShape hertz_shape_exact(double ratio);

// The forward direction, no root-find: K, E and the curvature ratio
// min(A,B)/max(A,B) belonging to a given semi-axis ratio g in (0, 1].
struct HertzShapeAndRatio {
  HertzShape shape;
  double ratio;
};
HertzShapeAndRatio hertz_shape_from_axes(double g);

}  // namespace railsim::contact
