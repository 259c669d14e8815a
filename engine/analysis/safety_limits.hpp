// Running-safety limit values: flange climbing (Nadal, Weinstock, EN 14363
// (Y/Q)_2m), track-shift force (Prud'homme), vertical wheel force, wheel
// unloading, quasi-static guiding and vertical forces, and the two
// instability criteria of EN 14363 (normal method: Sum Y; simplified method:
// bogie-frame lateral acceleration).
//
// Sources and confidence (tags of physics-reference.md):
// - Nadal (1908), single wheel: (Y/Q)_lim = (tan g - mu) / (1 + mu tan g),
//   g flange contact angle (physics-reference §9.1) [K] + table [C].
// - Weinstock (1984), axle sum: Nadal(flanging wheel) + mu (§9.2) [K].
// - Prud'homme / EN 14363 track-shift force: (Sum Y)_2m,lim = k1 (10 + 2 Q0/3) kN
//   with Q0 the static wheel load in kN (= 10 + P0/3, P0 = 2 Q0 the axle load);
//   k1 = 1.0 for locomotives, power units, multiple units and passenger
//   coaches, 0.85 for freight wagons (§9.3) [K]. Example: P0 = 160 kN -> 63.3 kN.
// - (Y/Q)_2m,lim = 0.8 for R >= 250 m (and straight track), 1.2 for R < 250 m
//   (§9.3 [K]; issue 17; the 1.2 is also the Nadal value at 70 deg, mu 0.36).
// - Vertical wheel force, track loading: Q_max,lim = 90 kN + Q0, capped by the
//   vehicle speed: 200 kN (V <= 160 km/h), 190 (160 < V <= 200), 180
//   (200 < V <= 250), 170 (250 < V <= 300), 160 kN (V > 300 km/h) (UIC 518 /
//   EN 14363:2005 track-loading table, author's knowledge) [K].
// - Quasi-static values in curves: Y_qst,lim = 60 kN, Q_qst,lim = 145 kN
//   (EN 14363 track loading in small-radius curves, author's knowledge) [K].
// - Wheel unloading dQ/Q0 <= 0.6 (the quasi-static twist-test limit, §9.3 [K];
//   applied here to the dynamic run as a screening value).
// - Instability, normal method: rms of Sum Y band-passed f0 +- 2 Hz over a
//   sliding 100 m window <= (Sum Y)_2m,lim / 2 (§9.3 [K]; the band-pass and
//   sliding rms confirmed by the gensys.se UIC 518 course page [V]).
// - Instability, simplified method: rms of the bogie-frame lateral
//   acceleration above the wheelsets, band f0 +- 2 Hz, sliding 100 m window,
//   <= (12 - m_b / 5) / 2 m/s^2, m_b the bogie mass in t (frame and its
//   wheelsets) (§9.3, exact constants [U]).
// Units: forces in N, masses in kg, speeds in m/s, radii in m, angles in rad.
#pragma once

namespace railsim::engine {

// Nadal's limit for a flange angle gamma [rad] and friction mu.
double nadal_limit(double flange_angle, double mu);

// Weinstock's axle-sum limit: Nadal(flanging wheel) + mu (non-flanging tread).
double weinstock_limit(double flange_angle, double mu);

// Prud'homme limit k1 (10 + P0/3) kN [N] for the static axle load P0 [N]; k1 in (0, 1].
double prudhomme_limit(double axle_load, double k1 = 1.0);

enum class VehicleCategory { passenger, locomotive, multiple_unit, freight };
const char* vehicle_category_name(VehicleCategory c);
// k1 of the track-shift force limit: 1.0, or 0.85 for freight wagons.
double track_shift_factor(VehicleCategory c);

// (Y/Q)_2m limit for the smallest curve radius R [m] of a track section
// (infinity: straight): 0.8 for R >= 250 m, 1.2 below.
double yq_2m_limit(double radius);

// Q_max limit [N] for the static wheel load Q0 [N] and the highest speed of the run [m/s].
double qmax_limit(double static_wheel_load, double max_speed);

inline constexpr double kYqstLimit = 60e3;          // [N]
inline constexpr double kQqstLimit = 145e3;         // [N]
inline constexpr double kWheelUnloadingLimit = 0.6; // dQ/Q0 [-]

// Normal-method instability limit [N]: half the track-shift force limit.
double instability_sum_y_limit(double axle_load, double k1 = 1.0);

// Simplified-method limit of the bogie-frame lateral acceleration rms [m/s^2]
// for the bogie mass m_b [kg]: (12 - m_b[t] / 5) / 2.
double bogie_frame_acceleration_limit(double bogie_mass);

}  // namespace railsim::engine
