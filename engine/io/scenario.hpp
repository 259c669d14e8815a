// A scenario: vehicle + track + speed + contact choices + integrator +
// duration, read from YAML (scenarios/*.yaml) through config::InputNode.
//
//   name: single_wheelset_defect
//   vehicle: ../vehicles/single_wheelset.yaml     # relative to this file
//   track: ../tracks/x.yaml | {inline track, track/track_file.hpp format}
//   speed: 30            # [m/s]  (or speed_kmh: 108)
//   acceleration: 0      # [m/s^2], speed profile V = V0 + a t
//   start_distance: 0    # [m], track distance of the vehicle reference at t = 0
//   duration: 5          # [s]
//   output_interval: 0.005
//   wheelset_model: lateral | full
//   wheelset_roll: kinematic | none      # lateral model (model.hpp)
//   axle_rotation: free | imposed        # lateral model: beta a state, or Omega = V / r0 (model.hpp)
//   max_lateral_shift: 0.05   # [m], optional (default: geometry range)
//   track_flexibility:        # optional; rigid rails without it (engine/wheel_rail/track_flexibility.hpp)
//     lateral: {mass: 370, stiffness: 5.5e7, damping: 7e4}   # per wheelset [kg, N/m, N s/m]
//     vertical: {mass: 180, stiffness: 7.15e7, damping: 6e4,  # per rail under each wheel (full model)
//                bending_stiffness: 6.38e6}                  # rail EI [N m^2], optional: the rails follow
//                                       # the vertical geometry as a beam on its foundation
//     # mass 1..1e5 kg, stiffness 1e5..1e10 N/m, damping 0..1e8 N s/m, bending_stiffness 1e4..1e9 N m^2;
//     # with bending_stiffness the track is at most 1e5 / beta m long (beta = (stiffness / 8 EI)^(1/3))
//   contact:
//     geometry: {type: conical, r0: 0.46, conicity: 0.2, l0: 0.75, contact_angle: 0,
//                flange_clearance: 0.009, flange_stiffness: 1.5e7, max_shift: 0.05}
//             | {type: table, file: ../vehicles/contact_tables/RSGEO_S1002_UIC60_1in40.dat}
//             | {type: profiles, wheel: S1002, rail: UIC60, inclination: 1/40, gauge: 1.435,
//                flange_back: 1.36, r0: 0.46, max_shift: 0.015, step: 1e-4}   # engine/wheel_rail/profile_geometry.hpp
//     normal: hertz | semi_hertz          # profiles: each patch's ellipse for the tangential models
//                                       # (Hertz of its curvatures, or the semi-Hertzian area and length;
//                                       # engine/wheel_rail/strip_patches.hpp)
//     tangential: coefficients | <contact registry name>
//     saturation: none | she            # coefficients only
//     material: {E: 2.1e11, nu: 0.28, mu: 0.3, shear_modulus: 8.2e10}
//     reduction: none                   # contact/reduction.hpp syntax, also layer:h=125e-6,G3=820e6
//     creep_coefficients: {f11: 1e7, f22: 1e7, f23: 0, f33: 0, N_ref: 0}
//     patch: {a: 6e-3, b: 4e-3, N_ref: 60000}
//     spin: true
//     static_approach: 7e-5             # full model, conical wheels: Hertz approach at the static load [m]
//   integrator: {method: cvode_bdf, rtol: 1e-6, atol: 1e-8, max_step: 0.001, jacobian: fd,
//                linear_solver: dense, max_steps: 100000, min_step: 1e-12}
//                # max_step in (0, duration] (omit it for no limit); min_step below the output
//                # interval and max_step
//                max_order: 0, stability_limit_detection: false,  # cvode_bdf: BDF order cap, CVODE's
//                # detection of the stability limit of orders 3-5 (lightly damped stiff modes)
//                jacobian_max_age: 400   # cvode_bdf: most steps between Jacobian evaluations, 1..1e6
//                atol_contact_modes: 0   # [m/s, rad/s] atol of the wheelsets' spin perturbations and
//                # (full model) vertical and roll velocities; 0 = atol (integrator.hpp)
//   start_distance must lie on the track ([0, length]); |acceleration| <= 10 m/s^2;
//   at most kMaxOutputSamples output samples; a key given twice is an error.
//   start: equilibrium | nominal        # (quasi-)static state at t = 0 (default) or x = 0
//   initial: {ws1.lateral: 0.001}       # state name: value (deviations from the start state)
//   critical_speed:                     # optional: analysis settings that suit this vehicle
//     {v_min_kmh: 150, v_max_kmh: 350, v_step_kmh: 10, duration: 6, disturbance_mm: 5,
//      small_disturbance_mm: 0.5, threshold_mm: 0.5, continuation: false,
//      ramping: {v_start_kmh: 290, disturbance_mm: 0.5, deceleration: 0.5}}
//   running_safety: {vehicle_category: passenger}  # optional: kept in Scenario::running_safety,
//                                       # read by engine/analysis/safety_settings.hpp
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "config/yaml_input.hpp"
#include "contact/geometry/wheel_rail_geometry.hpp"
#include "contact/reduction.hpp"
#include "engine/wheel_rail/geometry_registry.hpp"
#include "engine/integrators/integrator.hpp"
#include "engine/model.hpp"

namespace railsim::engine {

// Settings of `railsim critical-speed` for this scenario (the command line
// overrides them), in SI: the file's km/h and mm are converted when read.
struct CriticalSpeedSettings {
  double v_min = 80.0 / 3.6, v_max = 300.0 / 3.6, v_step = 20.0 / 3.6;  // sweep range and step [m/s]
  double duration = 6.0;               // simulated time per sweep point [s]
  double disturbance = 8e-3;           // lateral shift that starts the down branch [m]
  double small_disturbance = 0.5e-3;   // up branch [m]
  double threshold = 0.5e-3;           // settled amplitude that counts as hunting [m]
  bool continuation = false;           // path following on the down branch
  double ramp_start = 0.0;             // [m/s]; 0: v_max
  double ramp_disturbance = 0.0;       // [m]; 0: disturbance
  double deceleration = 0.5;           // [m/s^2]
};

// Limits of a scenario (README "Exit codes and limits"): output samples of a
// run (duration / output_interval + 1; every sample is kept in memory, about
// 2 kB each for the four-wheelset coach, and written to channels.csv) and
// the size of `acceleration` [m/s^2] (a braking train reaches about 1.5).
inline constexpr double kMaxOutputSamples = 1e6;
inline constexpr double kMaxAcceleration = 10.0;

struct Scenario {
  std::string name;
  std::string file;
  // Legal but implausible inputs (physics sanity), "file:line: key 'k': value
  // ... (usual range ...)"; also logged as warnings when read.
  std::vector<std::string> warnings;
  // Warnings about the scenario's own run, its speed and duration (the leading
  // wheelset running past the track's defined length): logged and recorded by
  // run_scenario only, not by analyses that choose their own speeds and
  // durations (critical-speed, modes).
  std::vector<std::string> run_warnings;
  // The scenario's `running_safety:` section, read by the run's evaluation
  // (engine/analysis/safety_settings.hpp); empty when absent.
  std::optional<config::InputNode> running_safety;
  Model model;  // finalized
  IntegratorOptions integrator;
  double duration = 1.0;
  double output_interval = 0.01;
  Eigen::VectorXd x0;
  std::string geometry_description;
  // Equivalent conicity of the wheel-rail geometry at 3 mm amplitude (EN 15302
  // regression on Delta r(y) of the main contact points, contact_geometry.hpp).
  double equivalent_conicity_3mm = 0.0;
  // Largest acceleration of the start state [m/s^2, rad/s^2] (equilibrium.hpp).
  double start_residual = 0.0;
  CriticalSpeedSettings critical_speed;
  // The reduction factors as the user gave them (key contact.reduction),
  // resolved: model.coupling carries spec.k.
  contact::ReductionSpec reduction;
  // Nominal contact patch: centred wheelset, static load of the first wheel,
  // from the geometry's semi-axes at its reference load (or the scenario's
  // patch / Hertz curvatures); for distributed contact (profiles) the most
  // loaded strip patch of the centred wheel under that vertical load, Fz its
  // normal load. A and B from Hertz for those semi-axes; Fz = 0 when the
  // scenario gives no patch (prescribed creep coefficients only).
  contact::HertzPatch nominal_patch;
  // Material of the creep forces (E from the shear modulus when one is given).
  contact::Material creep_material;
  // A layer's computed factors (reduction.form == layer), else default.
  contact::mim::LayerReduction layer;
};

Scenario load_scenario(const std::string& path);
Scenario load_scenario(const config::InputNode& root, const std::string& base_dir);

// Use `spec` as the scenario's reduction factors: presets and numbers as given;
// a third-body layer computed by the exact solver for nominal_patch (cached in
// cache_dir, empty = default cache folder), and with a limiting stress tau_c
// the friction coefficient of the creep forces lowered to the layer's limit
// (contact/mim/third_body.hpp). Throws InputError naming `where` when a layer
// has no patch to work on.
void apply_reduction(Scenario& sc, contact::ReductionSpec spec, const std::string& where,
                     const std::string& cache_dir = "");

}  // namespace railsim::engine
