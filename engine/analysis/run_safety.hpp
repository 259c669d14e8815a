// Running safety of a recorded run (run_history.hpp): per wheel the maximum
// instantaneous Y/Q against Nadal's flange-climbing limit, and per wheelset
// the EN 14363 evaluation of running_safety.hpp (Y/Q and Sum Y as 2 m sliding
// means against 0.8 and Prud'homme, wheel unloading), each maximum with the
// track distance of the wheelset and the time where it occurs.
//
// Nadal's limit needs the flange angle: flange_angle() takes the largest
// contact angle of the contact geometry over its lateral range (e.g. ~70 deg
// for S1002/UIC60 tables); geometries without a flange flank (conical wheels,
// whose flange is a lateral dead-band spring) fall back to 70 deg, the S1002
// maximum flank angle (physics-reference §9.1), and say so.
// Y/Q is signed in the history; the criteria use |Y/Q| (conservative: both
// flanking directions). A lifted wheel (Q <= 0) has Y/Q = 0 and shows in the
// unloading criterion. Units: N, m, s, rad.
#pragma once

#include <string>
#include <vector>

#include "engine/analysis/run_history.hpp"
#include "engine/analysis/running_safety.hpp"
#include "engine/contact_geometry.hpp"

namespace railsim::engine {

struct FlangeAngle {
  double angle = 0.0;        // [rad]
  double geometry_max = 0.0; // largest contact angle found in the geometry [rad]
  bool fallback = false;     // true when `angle` is the fallback value
  std::string source;        // human-readable origin
};

// Largest contact angle of `g` over shifts in [-max_shift, max_shift] (all
// contact points, `samples` shifts); below `min_flank` the geometry is taken to
// have no flange flank and `fallback` is used.
FlangeAngle flange_angle(const ContactGeometry& g, double fallback = 70.0 * 3.14159265358979323846 / 180.0,
                         double min_flank = 45.0 * 3.14159265358979323846 / 180.0, int samples = 801);

// A maximum and where it occurs.
struct Peak {
  double value = 0.0;
  double distance = 0.0;  // track distance of the wheelset [m]
  double time = 0.0;      // [s]
};

struct WheelSafety {
  Peak max_abs_yq;      // instantaneous |Y/Q|
  bool nadal_pass = true;
  double yq_2m_time = 0.0;  // time where the (Y/Q)_2m maximum occurs
};

struct WheelsetSafety {
  std::string name;
  double static_wheel_load = 0.0;
  WheelSafety wheel[2];          // left, right
  AxleSafety en14363;            // running_safety.hpp (distances: wheelset track distance)
  double sum_y_time = 0.0;       // time of the (Sum Y)_2m maximum
  double unloading_time = 0.0;   // time of the maximum unloading
  bool pass = true;              // Nadal on both wheels and EN 14363
};

struct RunSafety {
  double flange_angle = 0.0;     // [rad]
  double mu = 0.0;
  double nadal = 0.0;            // (Y/Q) limit
  SafetyLimits limits;
  bool en14363_evaluated = true; // false when the vehicle does not advance (no distance windows)
  std::vector<std::string> notes;
  std::vector<WheelsetSafety> wheelsets;
  bool pass = true;
};

// Throws std::invalid_argument for an empty history.
RunSafety evaluate_run_safety(const RunHistory& h, double flange_angle, double mu, const SafetyLimits& limits = {});

}  // namespace railsim::engine
