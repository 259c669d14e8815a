// Critical speed of a vehicle: linear (eigenvalues), nonlinear by a
// bifurcation sweep, and by ramping.
//
// Definitions (physics-reference.md section 8.4; True 2013, VSD 51(3);
// Polach & Kaiser 2012):
// - linear critical speed V_L: the Hopf point of the centred running
//   solution, where the largest real part of the oscillatory modes crosses
//   zero (engine/linearisation.hpp);
// - nonlinear critical speed V_NL: the lowest speed at which a hunting limit
//   cycle survives. The bifurcation sweep runs constant speeds, each from a
//   strongly disturbed state ("down" branch: large initial lateral shift of
//   every wheelset) and from a weakly disturbed one ("up" branch), and records
//   the settled amplitude of each wheelset's lateral shift (amplitude after
//   the transients, results/limit_cycle.hpp). V_NL is the lowest speed of the
//   down branch with a settled amplitude above the threshold that is not
//   followed by a decaying speed (the hunting range must be contiguous up to
//   the top of the sweep).
// - ramping: start above V_NL on the hunting attractor, decelerate slowly; the
//   critical speed is the speed where the envelope of the lateral motion starts
//   its final collapse (decay faster than collapse_rate down to below the
//   threshold). The ramp must be slow against the decay of the transients
//   (True 2013), so the result depends on the deceleration: halve it until the
//   result converges.
// Speeds in m/s inside; the summary reports km/h as well.
#pragma once

#include <string>
#include <vector>

#include "core/stop_request.hpp"
#include "engine/analysis/sweep_runner.hpp"
#include "engine/io/scenario.hpp"

namespace railsim::engine {

struct BifurcationOptions {
  double v_min = 20.0;               // [m/s]
  double v_max = 80.0;               // [m/s]
  double v_step = 5.0;               // [m/s]
  double duration = 8.0;             // simulated time per point [s]
  double large_disturbance = 8e-3;   // initial lateral shift, down branch [m]
  double small_disturbance = 0.5e-3; // initial lateral shift, up branch [m]
  double threshold = 0.5e-3;         // settled amplitude that counts as hunting [m]
  double tail_fraction = 0.3;        // part of the record used for the settled amplitude
  // A point still decaying faster than this (relative change of the half-cycle
  // peaks over the tail) is a transient, not a limit cycle, whatever its amplitude.
  double decay_tolerance = 0.05;
  bool up_branch = true;             // also sweep the weakly disturbed branch
  // Path following on the down branch: after the parallel sweep, the speeds
  // below the lowest hunting one are run one after the other, each started
  // from the final state of the speed above, until the limit cycle is lost, so
  // the branch is followed down to its fold whatever the disturbance. Threads
  // only (the final states are kept in one file).
  bool continuation = false;
  int threads = 0;                   // 0: all cores
  bool use_mpi = false;              // spread the points over mpirun ranks (MPI started in main())
  std::string label = "bifurcation sweep";  // progress messages
  StopRequest stop;                  // polled by every run: InterruptedError (finished points stay in the file)
};

// Branch of a bifurcation sweep: down = from the large initial lateral shift
// (reaches the hunting limit cycle), up = from the small one.
enum class Branch { down, up };
const char* branch_name(Branch b);  // "down", "up"

struct BifurcationPoint {
  double speed = 0.0;                // [m/s]
  Branch branch = Branch::down;
  double amplitude = 0.0;            // max over wheelsets of the settled amplitude [m]
  double frequency = 0.0;            // of the wheelset with the largest amplitude [Hz]
  double growth = 0.0;               // relative amplitude change over the tail
  // Run stopped by a derailment, or by its motion leaving the model's range
  // (ModelRangeError: a wheel lifting in the lateral model, a geometry without
  // flange run out of) after its lateral motion had grown (a wheelset further
  // out than it started and than the threshold) -> treated as hunting.
  bool failed = false;
  // Run stopped by a numerical failure (integrator, NaN, absurd state), or
  // out of the model's range before its motion grew: the point has no verdict, and a sweep whose verdict
  // depends on it has no critical speed (BifurcationResult::undetermined).
  bool numerical_failure = false;
  bool continued = false;            // down branch: started from the limit cycle of the speed above
};

struct BifurcationResult {
  std::vector<BifurcationPoint> points;  // sorted: branch, then speed
  double nonlinear_critical_speed = 0.0; // [m/s]; NaN when no hunting was found in the range
  double resolution = 0.0;               // speed step of the sweep [m/s]
  // Limit cycle at the fold: amplitude [m] and frequency [Hz] of the down
  // branch at nonlinear_critical_speed (the lowest hunting speed); NaN without one.
  double fold_amplitude = 0.0, fold_frequency = 0.0;
  // Why there is no critical speed although the sweep ran (empty: the verdict
  // stands): walking down from the top of the sweep, a point stopped by a
  // numerical failure, or a point whose run was too short to show a cycle in
  // its tail (amplitude above the threshold, fewer than two half-cycles), came
  // before the hunting range ended; or the down branch still hunts at the
  // lowest speed of the sweep (the critical speed lies at or below v_min: the
  // range must reach lower). `undetermined_kind` says which.
  std::string undetermined;
  enum class Undetermined { none, numerical_failure, too_short, below_range } undetermined_kind = Undetermined::none;
};

// Hunting: the run derailed, or a settled amplitude above the threshold that is
// not decaying by more than decay_tolerance over the tail. A numerical failure
// or a run too short to measure a cycle is not hunting (and has no verdict:
// point_state failed / too_short).
bool is_hunting(const BifurcationPoint& p, const BifurcationOptions& o);

// What a point's run did by its end (for charts and reports), with the
// threshold and decay_tolerance of `o`:
//   settled   amplitude above the threshold, |growth| <= decay_tolerance: a limit cycle;
//   growing   amplitude above the threshold, still growing (counts as hunting);
//   decaying  amplitude above the threshold, still decaying (not hunting);
//   centred   amplitude at or below the threshold (back to the centred running);
//   stopped   the run derailed (wheelset past its flange), or its motion
//             left the model's range after it grew (e.g. a wheel lifting in
//             the lateral model): counts as hunting;
//   failed    the run stopped on a numerical failure (or out of range before
//             its motion grew): no verdict;
//   too_short amplitude above the threshold but no measurable cycle in the tail
//             (fewer than two half-cycles): no verdict, the runs need more time.
enum class PointState { settled, growing, decaying, centred, stopped, failed, too_short };
inline constexpr int kPointStates = 7;
PointState point_state(const BifurcationPoint& p, const BifurcationOptions& o);
const char* point_state_name(PointState s);

// Run (or resume) the sweep; results are written to `points_csv` as they finish.
BifurcationResult bifurcation_sweep(const Scenario& scenario, const BifurcationOptions& options,
                                    const std::string& points_csv);

struct RampingOptions {
  double v_start = 80.0;             // [m/s]
  double v_end = 10.0;               // [m/s]
  double deceleration = 0.5;         // [m/s^2]
  double disturbance = 8e-3;         // initial lateral shift of every wheelset [m]
  double threshold = 0.5e-3;         // half-cycle peak that still counts as hunting [m]
  double collapse_rate = 0.1;        // envelope decay rate that marks the collapse [1/s]
  double settle_time = 3.0;          // constant speed at v_start before the ramp [s]
  double output_interval = 0.002;    // sampling of the lateral shifts [s]
  StopRequest stop;                  // polled by the runs: InterruptedError
};

struct RampingResult {
  double critical_speed = 0.0;       // [m/s]; NaN: no hunting at v_start or still hunting at the end
  bool hunting_at_start = false;
  bool hunting_at_end = false;
  double start_speed = 0.0;          // [m/s] the speed the ramp really started from (options.v_start)
  // Where the critical speed was read: time [s] and envelope peak [m] at the
  // start of the final collapse (NaN when no critical speed).
  double critical_time = 0.0, critical_amplitude = 0.0;
  // The vehicle derailed (the physics: a wheelset past its flange) while
  // settling at the start speed or during the ramp: the message, and no
  // critical speed (the record keeps what was run). Empty: it did not.
  std::string derailment;
  // The lateral motion grew until it left the model's range (ModelRangeError:
  // the lateral model's wheel lift, a flangeless geometry run out of) while
  // settling or during the ramp: hunting beyond what the model covers, as a
  // bifurcation sweep counts it; the message, no critical speed. (Such a stop
  // before the motion grew is a numerical failure: NumericalError.)
  std::string range_stop;
  // Either of the two: the ramp ended on the physics, not at v_end.
  bool stopped() const { return !derailment.empty() || !range_stop.empty(); }
  std::vector<double> time, speed, max_lateral;  // envelope record (for charts)
  double wall_time = 0.0;
};

// A numerical failure of either phase throws NumericalError (no verdict); a
// derailment, or the grown motion leaving the model's range, is a result
// (RampingResult::derailment, range_stop).
RampingResult ramping(const Scenario& scenario, const RampingOptions& options);

// Linear critical speed by bisection of the largest real part over [v_lo, v_hi];
// NaN when stable over the whole range; v_lo when already unstable there (the
// critical speed lies at or below v_lo: see linearly_unstable).
double linear_critical_speed(const Scenario& scenario, double v_lo, double v_hi);
// Whether the linearised vehicle is unstable at speed v [m/s] (a real part
// above kUnstableGrowth, the bisection's threshold).
bool linearly_unstable(const Scenario& scenario, double v);

// InputError when the tangential model `model` solves a contact patch and the
// scenario gives none (conical wheels with prescribed creep coefficients only
// work with 'coefficients'); nothing for an empty name.
void check_model_has_patch(const Scenario& scenario, const std::string& model);

// Copy of the scenario with another tangential model and/or reduction factors
// (empty model name: keep; nullptr reduction: keep; factors given this way
// are recorded by their numbers, scenario.reduction).
Scenario with_contact(const Scenario& scenario, const std::string& tangential_model,
                      const contact::ReductionFactors* reduction);

// Copy of the scenario with the reduction `spec` (a layer's factors computed
// for the scenario's nominal patch, cached in cache_dir; engine/io/scenario.hpp
// apply_reduction) and, when tangential_model is not empty, that model.
Scenario with_reduction(const Scenario& scenario, const contact::ReductionSpec& spec, const std::string& where,
                        const std::string& cache_dir = "", const std::string& tangential_model = "");

}  // namespace railsim::engine
