// Running-safety criteria: flange climbing (Nadal, Weinstock), track-shift
// force (Prud'homme) and wheel unloading, evaluated the EN 14363 / UIC 518 way.
//
// Sources (physics-reference.md section 9):
// - Nadal (1908): single-wheel flange-climbing limit
//     (Y/Q)_lim = (tan g - mu) / (1 + mu tan g),  g flange contact angle.
// - Weinstock (1984): axle sum  |Y/Q|_flanging + |Y/Q|_other <= Nadal + mu.
// - Prud'homme: track-shift force limit (Sum Y)_lim = alpha (10 + P0/3) kN,
//   P0 static axle load in kN; alpha = 1 (passenger, locomotives), 0.85 (freight).
// - EN 14363 / UIC 518 evaluation: Y/Q and Sum Y as sliding means over 2 m,
//   sampled every 0.5 m; flange-climbing limit (Y/Q)_2m <= 0.8 for R >= 250 m;
//   wheel unloading dQ/Q0 <= 0.6. The standard also low-passes at 20 Hz and uses
//   the 99.85 % percentile; both the maximum and that percentile are reported.
// Units: forces in N, distances in m, angles in rad. Y is the lateral force of
// the rail on the wheel in the track plane, Q the vertical wheel force (> 0).
#pragma once

#include <string>
#include <vector>

namespace railsim::engine {

// Nadal's limit for a flange angle gamma [rad] and friction mu.
double nadal_limit(double flange_angle, double mu);

// Weinstock's axle-sum limit: Nadal(flanging wheel) + mu (non-flanging tread).
double weinstock_limit(double flange_angle, double mu);

// Prud'homme limit [N] for the static axle load P0 [N]; alpha in (0, 1].
double prudhomme_limit(double axle_load, double alpha = 1.0);

struct SafetyLimits {
  double yq_limit = 0.8;            // (Y/Q)_2m limit
  double wheel_unloading = 0.6;     // dQ/Q0 limit
  double prudhomme_alpha = 1.0;     // 1.0 passenger/loco, 0.85 freight
  double window = 2.0;              // sliding window [m]
  double step = 0.5;                // window sampling [m]
  double percentile = 99.85;        // EN 14363 percentile for the estimated maximum
};

// A maximum of a windowed quantity and where it occurs.
struct WindowedMaximum {
  double max_abs = 0.0;         // largest |sliding mean|
  double at_distance = 0.0;     // window centre where it occurs [m]
  double percentile = 0.0;      // the SafetyLimits::percentile of |sliding mean|
  double limit = 0.0;
  bool pass = true;             // max_abs <= limit
};

// Time histories of one axle (left and right wheel), sampled along distance.
struct AxleForces {
  std::string name;                 // e.g. "wheelset 1"
  std::vector<double> distance;     // strictly increasing [m]
  std::vector<double> Y_left, Q_left, Y_right, Q_right;  // [N]
  double static_wheel_load = 0.0;   // Q0 [N]
};

struct AxleSafety {
  std::string name;
  WindowedMaximum yq_left, yq_right;  // (Y/Q)_2m per wheel
  WindowedMaximum sum_y;              // (Sum Y)_2m against Prud'homme
  double max_unloading = 0.0;         // max (Q0 - Q)/Q0 over both wheels
  double unloading_at = 0.0;          // where [m]
  bool unloading_pass = true;
  bool pass = true;
};

// EN 14363-style evaluation of one axle. Throws std::invalid_argument on
// inconsistent series (length mismatch, fewer than two samples, Q0 <= 0).
AxleSafety evaluate_axle(const AxleForces& f, const SafetyLimits& limits = {});

}  // namespace railsim::engine
