// Kalker's creep coefficients C11, C22, C23, C33 of the linear theory of rolling
// contact, as functions of the patch shape a/b and Poisson's ratio nu.
//
// Sources (physics-reference.md sec. 2.2-2.4):
//   Table: Kalker (1967) thesis; Kalker (1990) "Three-dimensional elastic bodies
//   in rolling contact", Table E.3 (C11, C22, C23 identical to the data of
//   CONTACT m_hertz.f90). The C33 column is marked [U] in the reference (from
//   memory of Kalker 1967 / Johnson 1985 Table 8.1, not checked against a
//   primary source): treat spin moments as provisional.
//   Nodes: a/b = 0.1 ... 1.0 (a < b) and b/a = 0.9 ... 0.1 (a > b), nu = 0, 0.25, 0.5.
//   Between nodes in a/b: monotone piecewise-cubic Hermite (PCHIP, Fritsch-Butland
//   slopes from Boost.Math) in the variable ln(a/b) - exact at the nodes, C1,
//   no overshoot beyond neighbouring node values.
//   In nu: the quadratic in 1/C through nu = 0, 0.25, 0.5 (CONTACT's rule, sec. 2.4).
//   Beyond the table (a/b < 0.1 or > 10): Kalker's asymptotes (Kalker 1990 App. E,
//   via CONTACT `linrol`, sec. 2.3), multiplied by a correction that equals
//   table/asymptote at the table edge and decays linearly to 1 as min(a,b)/max(a,b)
//   -> 0, so C is continuous at the edge and tends to the asymptote.
//   C33 for a << b: pi^2 / (16 (1-nu) g) [U]. C33 for a >> b: no asymptote known
//   ([GAP]); held at the table's b/a = 0.1 value.
//
// Units: dimensionless. Use: Fx = -G c^2 C11 xi, Fy = -G c^2 C22 eta - G c^3 C23 phi,
// Mz = G c^3 C23 eta - G c^4 C33 phi, c = sqrt(ab) (see types.hpp).
#pragma once

namespace railsim::contact {

struct KalkerCoefficients {
  double C11, C22, C23, C33;
};

// a_over_b: semi-axis along x over semi-axis along y, positive and finite;
// nu in (0, 0.5]. Throws InputError otherwise. No allocation; thread-safe.
KalkerCoefficients kalker_coefficients(double a_over_b, double nu);

// The range of a/b covered by the table (outside it the asymptotes are used).
inline constexpr double kKalkerTableMinAspect = 0.1;
inline constexpr double kKalkerTableMaxAspect = 10.0;

}  // namespace railsim::contact
