// Quasi-static curving results of a recorded run (run_history.hpp): for every
// stretch where all wheelsets run in the same circular curve (constant,
// non-zero curvature and zero curvature rate at every wheelset; transitions
// excluded), after a settling length, the mean and extremes per wheelset of
//   - the angle of attack: wheelset yaw relative to the track at the wheelset,
//     signed positive when the wheelset heads toward the outer rail
//     (aoa = -sign(kappa) psi; the usual sign for a leading flanging wheelset);
//   - the lateral shift relative to the track (positive toward the outer rail);
// and per wheel of Y, Q, Y/Q and the wear number T-gamma (wear_number.hpp, with
// the spin term). Also the unbalanced lateral acceleration in the track plane
//   a_nc = V^2 kappa cos(phi_c) - g sin(phi_c)   (toward the curve centre, signed
//                                                 with the curve: > 0 deficiency)
// and the quasi-static check Sum Y (all wheels) = M a_nc sign(kappa), M the total
// vehicle mass: the rails must supply the uncompensated centripetal force
// (Iwnicki (ed.) 2006, Handbook of Railway Vehicle Dynamics, ch. 8;
// physics-reference §10.1). Units: m, rad, N, m/s^2.
#pragma once

#include <string>
#include <vector>

#include "engine/analysis/run_history.hpp"

namespace railsim::engine {

struct CurvingOptions {
  double settle_distance = 50.0;  // excluded after all wheelsets entered the circular curve [m]
  double min_length = 10.0;       // shorter bodies (after settling) are not reported [m]
};

struct Stat {
  double mean = 0.0, min = 0.0, max = 0.0;
};

struct WheelCurving {
  bool outer = false;
  Stat Y, Q, yq, Tgamma;
};

struct WheelsetCurving {
  std::string name;
  Stat angle_of_attack;  // [rad], > 0 heading toward the outer rail
  Stat lateral_shift;    // [m], > 0 toward the outer rail
  WheelCurving wheel[2]; // left, right
};

struct CurveResult {
  double curvature = 0.0;  // [1/m], > 0 left
  double cant = 0.0;       // cant angle [rad]
  double start = 0.0, end = 0.0;  // vehicle reference distances of the evaluated body [m]
  std::size_t samples = 0;
  double mean_speed = 0.0;  // [m/s]
  double unbalanced_acceleration = 0.0;  // a_nc [m/s^2], > 0 cant deficiency
  double sum_Y = 0.0;        // mean of the sum of Y over all wheels [N]
  double expected_sum_Y = 0.0;  // M a_nc sign(kappa) [N]
  std::vector<WheelsetCurving> wheelsets;
};

// One result per circular curve met by the whole vehicle (empty on straight track).
std::vector<CurveResult> evaluate_curving(const RunHistory& h, const CurvingOptions& opt = {});

}  // namespace railsim::engine
