// Influence coefficients of uniform surface tractions on rectangular elements
// of an elastic half-space, for two quasi-identical bodies in contact.
//
// A uniform pressure p on the rectangle |x'| <= dx/2, |y'| <= dy/2 produces
// the normal displacement difference (Love 1929, integration of Boussinesq's
// point-load solution; Johnson 1985, eq. 3.25 for one body, doubled for two)
//   u_z(x, y) = (1 - nu)/(pi G) * I_r,   I_r = integral of 1/r over the element.
// A uniform tangential traction q_x (Cerruti 1882; Johnson 1985, eq. 3.86a,b)
//   u_x = 1/(pi G) [(1 - nu) I_r + nu I_xx] q_x,  u_y = nu/(pi G) I_xy q_x,
// and symmetrically for q_y (x <-> y), with I_xx = integral of x^2/r^3,
// I_xy = integral of x y/r^3. The closed-form corner sums used here are
//   I_r  = [x asinh(y/|x|) + y asinh(x/|y|)],  I_xx = [y asinh(x/|y|)],
//   I_yy = [x asinh(y/|x|)],  I_xy = [-r],
// evaluated with alternating signs at the four corners (x, y measured from
// the element corners to the field point); the ln|x| parts cancel in the sum.
//
// Two bodies with the same G and nu (quasi-identical): the normal-tangential
// coupling vanishes. For dissimilar bodies the coupling (Johnson 1985,
// eq. 3.86c; Kalker's difference parameter K) is available through
// coupling_zx/coupling_zy, but the solvers assume K = 0 (off by default).
//
// Units: lengths in m, G in Pa; coefficients in m/Pa (displacement per unit
// traction). Sign: displacements are those of body 1 minus body 2 under the
// traction that body 2 exerts on body 1, so that u = A p with A positive
// definite; a positive pressure closes the gap.
#pragma once

namespace railsim::contact::mim {

// Elastic constants of the contact pair: combined shear modulus G and
// Poisson's ratio nu (identical bodies: the material's own), and Kalker's
// difference parameter K = (1/4)[(1-2nu1)/G1 - (1-2nu2)/G2] * G (0 when the
// bodies are quasi-identical).
struct ElasticPair {
  double G = 82.03125e9;  // combined shear modulus [Pa]: 2/G = 1/G1 + 1/G2
  double nu = 0.28;       // combined Poisson's ratio [-]
  double K = 0.0;         // difference parameter [-]; 0 = quasi-identical

  // Combined constants of two bodies (Kalker 1990, sec. 1.6):
  // 1/G = (1/G1 + 1/G2)/2, nu/G = (nu1/G1 + nu2/G2)/2,
  // K/G = ((1-2nu1)/G1 - (1-2nu2)/G2)/4.
  static ElasticPair from_bodies(double G1, double nu1, double G2, double nu2);
};

// Closed-form element integrals at the offset (X, Y) of the field point from
// the element centre, element size dx x dy [m].
double integral_inv_r(double X, double Y, double dx, double dy);   // I_r  [m]
double integral_x2_r3(double X, double Y, double dx, double dy);   // I_xx [m]
double integral_y2_r3(double X, double Y, double dx, double dy);   // I_yy [m]
double integral_xy_r3(double X, double Y, double dx, double dy);   // I_xy [m]
double integral_x_r2(double X, double Y, double dx, double dy);    // integral of x/r^2 [m]

// Normal displacement difference per unit pressure [m/Pa].
double influence_zz(const ElasticPair& m, double X, double Y, double dx, double dy);
// Tangential displacement differences per unit tangential traction [m/Pa].
double influence_xx(const ElasticPair& m, double X, double Y, double dx, double dy);
double influence_yy(const ElasticPair& m, double X, double Y, double dx, double dy);
double influence_xy(const ElasticPair& m, double X, double Y, double dx, double dy);
// Coupling: normal displacement difference per unit q_x (resp. q_y), which is
// -(K/(pi G)) * integral of x/r^2 (Johnson 1985, eq. 3.86c, two bodies);
// zero for quasi-identical bodies.
double coupling_zx(const ElasticPair& m, double X, double Y, double dx, double dy);
double coupling_zy(const ElasticPair& m, double X, double Y, double dx, double dy);

}  // namespace railsim::contact::mim
