// Value types of the wheel-rail contact interface.
//
// Conventions (see ../shared/docs/architecture.md, "Coordinates and signs"):
// - SI units: m, N, Pa, rad; spin creepage phi in 1/m (rad/m).
// - Contact frame: x rolling direction, y lateral in the contact plane, n normal.
// - Creepages after Kalker: rigid slip velocity over rolling speed;
//   xi longitudinal, eta lateral, phi spin.
// - Forces are the forces of the rail on the wheel in the contact frame. As in
//   Kalker's theory a positive creepage gives a negative force:
//   Fx = -G c^2 C11 xi, Fy = -G c^2 C22 eta - G c^3 C23 phi,
//   Mz = G c^3 C23 eta - G c^4 C33 phi (Kalker 1990, App. E).
// - Semi-axis a lies along x (rolling), b along y (lateral).
#pragma once

namespace railsim::contact {

// Elastic and friction properties of the (identical) wheel and rail materials.
struct Material {
  double E = 210.0e9;   // Young's modulus [Pa]
  double nu = 0.28;     // Poisson's ratio [-], in (0, 0.5]
  double mu = 0.3;      // Coulomb friction coefficient [-]

  // Shear modulus G = E / (2 (1 + nu)) [Pa].
  double shear_modulus() const { return E / (2.0 * (1.0 + nu)); }
  // Combined plane-strain modulus of two identical bodies,
  // E* = E / (2 (1 - nu^2)) = G / (1 - nu) [Pa] (Johnson 1985, eq. 4.22).
  double combined_modulus() const { return E / (2.0 * (1.0 - nu * nu)); }

  // Material from shear modulus and Poisson's ratio (E = 2 G (1 + nu)).
  static Material from_shear_modulus(double G, double nu, double mu) {
    return Material{2.0 * G * (1.0 + nu), nu, mu};
  }
};

// Kalker creepages: xi, eta dimensionless; phi spin in 1/m.
struct Creepages {
  double xi = 0.0;
  double eta = 0.0;
  double phi = 0.0;
};

// Reduction factors on Kalker's creep coefficients: C11 -> k11 C11,
// C22 -> k22 C22, C23 -> k23 C23 (C33 follows k23). 1 = theory.
struct ReductionFactors {
  double k11 = 1.0;
  double k22 = 1.0;
  double k23 = 1.0;
};

// Hertzian contact patch: relative curvatures A (rolling direction) and B
// (lateral) in 1/m, semi-axes a (along x) and b (along y) in m, maximum
// pressure p0 in Pa, approach (mutual normal approach of distant points) in m,
// and the normal load Fz in N that produces it.
struct HertzPatch {
  double A = 0.0;
  double B = 0.0;
  double a = 0.0;
  double b = 0.0;
  double p0 = 0.0;
  double approach = 0.0;
  double Fz = 0.0;
};

// Creep coefficients the contact geometry gives instead of Kalker's table at
// the patch's a/b: an RSGEO-type contact table's C_ij at this patch, or
// coefficients prescribed in force units at a reference load. Read by the
// model "coefficients" (contact/coefficients.cpp) only; the other models
// compute theirs from the patch and ignore these. Zero = not given.
struct GeometryCoefficients {
  // Kalker's coefficients at this patch [-], used when C11 > 0 (the tables
  // carry no C33: 0 there).
  double C11 = 0.0, C22 = 0.0, C23 = 0.0, C33 = 0.0;
  // f11, f22 [N], f23 [N m], f33 [N m^2] at the load Fz_ref [N], used when
  // f11 > 0 (before C_ij), scaled with the load as f11, f22 ~ Fz^(2/3),
  // f23 ~ Fz, f33 ~ Fz^(4/3) (Hertz: a, b ~ Fz^(1/3)).
  double f11 = 0.0, f22 = 0.0, f23 = 0.0, f33 = 0.0;
  double Fz_ref = 0.0;
  // Shear modulus G for the C_ij [Pa]; 0 = Material::shear_modulus().
  double shear_modulus = 0.0;
};

// Everything a tangential model needs for one contact.
struct ContactInput {
  HertzPatch patch;            // normal solution (patch size, load)
  Creepages creep;             // xi, eta, phi [-, -, 1/m]
  Material material;           // E, nu, mu
  ReductionFactors reduction;  // k11, k22, k23
  double rolling_speed = 0.0;  // [m/s], only for slip-velocity-dependent friction
  GeometryCoefficients coefficients;  // optional, model "coefficients" only (see above)
};

// Result of a tangential model for one contact (forces of the rail on the wheel).
struct ContactForces {
  double Fx = 0.0;  // longitudinal force [N]
  double Fy = 0.0;  // lateral force [N]
  double Mz = 0.0;  // spin moment about the contact normal [N m]
  // Diagnostics.
  bool valid = true;                 // false: used outside its validity domain
  const char* reason = "";           // static text saying why, when !valid
  int iterations = 0;                // solver iterations (0 for closed forms)
  double stick_fraction = -1.0;      // adhesion area / contact area, -1 if unknown
};

}  // namespace railsim::contact
