// Running safety of a recorded run (run_history.hpp) the EN 14363 way: the
// on-track assessment quantities per wheel, wheelset, running gear and car
// body, each with its processing steps, per track section and zone
// (track_zones.hpp), limit, margin, where and when (safety_quantity.hpp),
// plus Nadal's instantaneous flange-climbing check and the lateral shifts.
//
// Processing (defaults in safety_settings.hpp with their sources; filters in
// results/iir_filter.hpp, zero phase):
//   wheel (Y, Q of every wheel low-passed at 20 Hz):
//     yq_2m            (Y/Q)_2m: Y/Q of the filtered forces, 2 m sliding mean
//                      every 0.5 m, max(|F1|, |F2|) per section; limit 0.8
//                      (R >= 250 m) or 1.2 (R < 250 m)
//     q_max            Q_max: filtered Q, F2; limit min(90 kN + Q0, speed cap)
//     wheel_unloading  dQ/Q0 = (Q0 - Q)/Q0 of the filtered Q, F2 (i.e. Q at F1); limit 0.6
//     y_qst, q_qst, yq_qst  quasi-static values in circular curves: F0 (50 %)
//                      of the filtered Y, Q, Y/Q; limits 60 kN, 145 kN, none
//   wheelset:
//     sum_y_2m         (Sum Y)_2m: filtered Y_left + Y_right, 2 m sliding mean
//                      every 0.5 m, max(|F1|, |F2|); limit k1 (10 + 2 Q0/3) kN
//     sum_y_rms        instability, normal method: Sum Y band-passed f0 +- 2 Hz,
//                      sliding rms over 100 m every 10 m, maximum; limit half
//                      the track-shift limit
//   running gear (each bogie frame point above a wheelset):
//     bogie_ay_rms     instability, simplified method: lateral acceleration
//                      band-passed f0 +- 2 Hz, sliding rms 100 m every 10 m,
//                      maximum; limit (12 - m_b/5)/2 m/s^2
//   car body (above each bogie centre and at the ends):
//     car_ay, car_az   accelerations band-passed 0.4..10 Hz, max(|F1|, |F2|)
//     car_ay_rms, car_az_rms  rms of the same per section
//     car_ay_qst       lateral acceleration low-passed 20 Hz, F0 in curves
//     (ride characteristics: reported without limits)
// f0 is the scenario's running_safety.hunting_frequency_hz, else the dominant
// frequency (results/spectrum.hpp) of the unfiltered Sum Y between 1 and 15 Hz,
// of the wheelset with the strongest peak.
// Nadal (flange climbing), per wheel, against Nadal's limit for the flange
// angle of the geometry (flange_angle()): the verdict is on the 2 m sliding
// mean (every 0.5 m, the windows of (Y/Q)_2m) of the unfiltered |Y/Q|. Nadal's
// limit is the quasi-static balance of a wheel sliding up its flange; a climb
// takes metres (flange height over the angle of attack: 30 mm / 10 mrad = 3 m),
// and the instantaneous ratio passes it in short impacts that climb nothing
// (Toumi's derailment case: peak Y/Q 1.27 against Nadal 0.94 without
// derailment; EN 14363's own Y/Q is the 2 m mean). The largest instantaneous
// |Y/Q| and the longest continuous stretch above the limit are reported
// beside it. A vehicle that does not advance has no 2 m windows: its verdict
// is then on the instantaneous peak (conservative), with a note.
// Lateral shift of every wheelset: relative to the rails (for flange contact)
// and absolute (design centre line), labelled.
// Distances are the track distance of the item (wheelset, or measuring point);
// times in s. A filter that the sampling cannot carry (cut-off above 0.45 fs)
// is not applied and the step says so. Units: N, m, s, rad, m/s^2.
#pragma once

#include <string>
#include <vector>

#include "engine/analysis/run_history.hpp"
#include "engine/analysis/safety_limits.hpp"
#include "engine/analysis/safety_quantity.hpp"
#include "engine/analysis/safety_settings.hpp"
#include "engine/analysis/track_zones.hpp"
#include "engine/wheel_rail/contact_geometry.hpp"

namespace railsim::engine {

struct FlangeAngle {
  double angle = 0.0;        // [rad]
  double geometry_max = 0.0; // largest contact angle found in the geometry [rad]
  bool fallback = false;     // true when `angle` is the fallback value
  std::string source;        // human-readable origin
};

// Largest contact angle of `g` over shifts in [-max_shift, max_shift] (all
// contact points, `samples` shifts); below `min_flank` the geometry is taken to
// have no flange flank and `fallback` is used (70 deg, the S1002 maximum flank
// angle, physics-reference §9.1).
FlangeAngle flange_angle(const ContactGeometry& g, double fallback = 70.0 * 3.14159265358979323846 / 180.0,
                         double min_flank = 45.0 * 3.14159265358979323846 / 180.0, int samples = 801);

// A maximum and where it occurs.
struct Peak {
  double value = 0.0;
  double distance = 0.0;  // track distance of the item [m]
  double time = 0.0;      // [s]
};

struct WheelSafety {
  Peak max_abs_yq;               // instantaneous |Y/Q|, unfiltered
  Peak max_yq_2m;                // largest 2 m sliding mean of the unfiltered |Y/Q| (the Nadal verdict)
  double longest_exceedance = 0; // longest continuous distance with instantaneous |Y/Q| above Nadal [m]
  bool nadal_on_2m = false;      // true: the verdict is on max_yq_2m; false: on the instantaneous peak
  bool nadal_pass = true;
};

struct WheelsetSafety {
  std::string name;
  double static_wheel_load = 0.0;  // Q0 [N]
  WheelSafety wheel[2];            // left, right
  Peak max_shift;                  // max |lateral shift| relative to the rails [m]
  Peak max_shift_absolute;         // max |lateral shift| relative to the design centre line [m]
  bool pass = true;                // Nadal on both wheels and every limited quantity of the wheelset and its wheels
};

struct SafetyProcessing {
  double sample_rate = 0.0;                // [Hz], 0 when the sampling is not uniform
  std::string force_filter;                // description of the 20 Hz low-pass, or why not applied
  bool force_filter_applied = false;
  std::string acceleration_filter;         // 0.4..10 Hz band-pass
  bool acceleration_filter_applied = false;
  std::string instability_filter;          // f0 +- 2 Hz band-pass
  bool instability_filter_applied = false;
  double hunting_frequency = 0.0;          // f0 [Hz]
  std::string hunting_frequency_source;
};

struct RunSafety {
  double flange_angle = 0.0;     // [rad]
  double mu = 0.0;
  double nadal = 0.0;            // (Y/Q) limit
  double max_speed = 0.0;        // [m/s]
  double k1 = 1.0;               // track-shift force factor
  SafetySettings settings;
  SafetyProcessing processing;
  bool en14363_evaluated = true; // false when the vehicle does not advance (no distance windows)
  bool instability_evaluated = true;  // false when the run is shorter than the rms window
  std::vector<std::string> notes;
  std::vector<TrackSection> sections;
  std::vector<WheelsetSafety> wheelsets;
  std::vector<Quantity> quantities;
  bool pass = true;

  // The quantity `name` of `item`, or nullptr.
  const Quantity* find(const std::string& name, const std::string& item) const;
};

// Throws std::invalid_argument for an empty history or no sections.
RunSafety evaluate_run_safety(const RunHistory& h, const std::vector<TrackSection>& sections, double flange_angle,
                              double mu, const SafetySettings& settings = {});
// Same on one straight section (histories without a track).
RunSafety evaluate_run_safety(const RunHistory& h, double flange_angle, double mu,
                              const SafetySettings& settings = {});

// Item names used in RunSafety::quantities.
std::string wheel_item(const std::string& wheelset, int side);  // "ws1 left", "ws1 right"

}  // namespace railsim::engine
