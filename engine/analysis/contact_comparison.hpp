// Tangential contact models against the exact solver on a set of contact
// cases: errors, cost per call, the Pareto front of cost against accuracy and
// a failure map (`railsim compare-contact` writes and prints the result).
//
// Reference: the MIM boundary-element model ("mim", contact/mim/) on a fine
// grid (options.reference_grid elements across the minor axis, tolerance
// options.reference_tolerance), one timed call per case; its cost is the
// median over the cases (the first solve on a new grid also sets up the solver).
// Errors: contact/force_error.hpp (fractions relative to the reference
// resultant |F_ref|, Mz relative to |Mz_ref|). Cost per call: solve_timed
// (engine/analysis/timed_solve.hpp), in microseconds.
// Pareto front: over (mean cost per call, max error of F) of the models
// (results/pareto_front.hpp).
// Failure map: on the patch of one case, a grid of creepage magnitude s (in
// one direction, log-spaced from 0.03 to 3 times the full-slip creepage
// 3 mu Fz / (G c^2 C) of the cubic laws, C = C11, C22 or their root mean square
// for the diagonal, c = sqrt(ab)) and spin phi (linear from 0 to twice the
// normalised spin unit mu Fz / (G c^3 C23)) [1/m]; a point fails for a model
// when its error of F exceeds options.failure_threshold (or is NaN).
#pragma once

#include <string>
#include <vector>

#include "contact/force_error.hpp"
#include "contact/tangential_model.hpp"
#include "contact/types.hpp"

namespace railsim::engine {

struct ComparisonCase {
  std::string id;
  contact::ContactInput input;
};

// A model to compare (not owned); ws may be null for models without scratch.
struct ComparedModel {
  std::string name;
  std::string description;
  const contact::TangentialModel* model = nullptr;
  contact::TangentialWorkspace* ws = nullptr;
};

enum class CreepDirection { longitudinal, lateral, diagonal };
// "longitudinal", "lateral", "diagonal"; InputError naming `where` otherwise.
CreepDirection parse_creep_direction(const std::string& name, const std::string& where);
const char* creep_direction_name(CreepDirection d);

struct ContactComparisonOptions {
  int reference_grid = 60;            // MIM elements across the minor axis
  double reference_tolerance = 1e-8;  // MIM tangential solver tolerance
  int map_points = 16;                // failure map points per axis; 0: no map
  std::size_t map_case = 0;           // index of the case whose patch the map uses
  CreepDirection map_direction = CreepDirection::lateral;
  double failure_threshold = 0.10;    // error of F above which the map marks a failure [-]
};

struct ModelStats {
  double max_F = 0.0, sum_F = 0.0, sum_F2 = 0.0;  // error of F [-]
  double max_Fx = 0.0, max_Fy = 0.0, max_Mz = 0.0;
  double sum_cost_us = 0.0, max_cost_us = 0.0;
  int cases = 0, invalid = 0;
  int map_points = 0, map_failures = 0;
  double mean_F() const;
  double rms_F() const;
  double mean_cost_us() const;
};

struct ModelCaseResult {
  contact::ContactForces forces;
  contact::ForceError error;
  double cost_us = 0.0;
};

struct FailureMapAxes {
  std::vector<double> creepage;  // magnitude |(xi, eta)| [-], log-spaced
  std::vector<double> spin;      // phi [1/m], linear from 0
  double dir_x = 0.0, dir_y = 1.0;
  double creepage_full_slip = 0.0;  // 3 mu Fz / (G c^2 C)
  double spin_unit = 0.0;           // mu Fz / (G c^3 C23)
};
FailureMapAxes failure_map_axes(const contact::ContactInput& in, CreepDirection direction, int points);

struct FailureMapPoint {
  std::size_t model = 0;  // index into the compared models
  double creepage = 0.0;  // magnitude s [-]
  contact::Creepages creep;
  contact::ForceError error;
  bool failed = false;
};

struct FailureMap {
  FailureMapAxes axes;
  std::vector<FailureMapPoint> points;  // spin outer, creepage, then model inner
  double wall_time_s = 0.0;
};

struct ContactComparison {
  std::vector<contact::ContactForces> reference;  // per case
  std::vector<double> reference_cost_us;          // per case, one call each
  double reference_median_cost_us = 0.0;
  std::vector<std::vector<ModelCaseResult>> results;  // [model][case]
  std::vector<ModelStats> stats;                      // per model (map counts included)
  std::vector<bool> pareto_front;                     // per model
  bool has_map = false;
  FailureMap map;
};

ContactComparison compare_contact_models(const std::vector<ComparisonCase>& cases,
                                         const std::vector<ComparedModel>& models,
                                         const ContactComparisonOptions& options);

}  // namespace railsim::engine
