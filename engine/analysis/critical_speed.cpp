// Critical speed by eigenvalues, bifurcation sweep and ramping; see critical_speed.hpp.
#include "engine/analysis/critical_speed.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <limits>

#include "contact/registry.hpp"
#include "core/atomic_file.hpp"
#include "core/content_hash.hpp"
#include "core/errors.hpp"
#include "engine/analysis/state_store.hpp"
#include "engine/linearisation.hpp"
#include "engine/elements/rigid_body.hpp"
#include "engine/simulation.hpp"
#include "engine/system.hpp"
#include "results/limit_cycle.hpp"

namespace railsim::engine {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Initial state: every wheelset shifted laterally by `shift` (same sign: the
// in-phase start that excites the hunting mode of bogie vehicles most directly).
Eigen::VectorXd disturbed_state(const Scenario& sc, double shift) {
  Eigen::VectorXd x = sc.x0;
  for (const auto& b : sc.model.bodies)
    if (b.q_index[kLat] >= 0) x[b.q_index[kLat]] = shift;
  return x;
}

Scenario at_speed(const Scenario& sc, double v0, double accel) {
  Scenario s = sc;
  s.model.speed.v0 = v0;
  s.model.speed.accel = accel;
  return s;
}

struct PointOutcome {
  double amplitude = 0.0, frequency = 0.0, growth = 0.0;
  bool failed = false;             // derailed
  bool numerical_failure = false;  // stopped by the numerics
};

// One constant-speed run from the state x0; the final state goes to *x_end.
PointOutcome run_point(const Scenario& base, double speed, const Eigen::VectorXd& x0, const BifurcationOptions& o,
                       Eigen::VectorXd* x_end = nullptr) {
  const Scenario sc = at_speed(base, speed, 0.0);
  const std::size_t nw = sc.model.wheelsets.size();
  std::vector<double> t;
  std::vector<std::vector<double>> y(nw);
  const double dt = std::min(sc.output_interval, 0.005);
  t.reserve(static_cast<std::size_t>(o.duration / dt) + 2);
  Observer obs = [&](double ti, const Eigen::VectorXd& x, const Data&) {
    t.push_back(ti);
    for (std::size_t w = 0; w < nw; ++w) y[w].push_back(x[sc.model.bodies[sc.model.wheelsets[w].body].q_index[kLat]]);
    if (x_end) *x_end = x;
  };
  PointOutcome out;
  std::string range_stop;  // the message of a run whose motion left the model's range
  try {
    simulate(sc.model, sc.integrator, x0, o.duration, dt, obs, o.stop);
  } catch (const DerailmentError& e) {
    // A run that derails is hunting violently: it counts as unstable, with the
    // amplitude it had reached.
    spdlog::warn("speed {:.1f} km/h: run derailed ({}); counted as hunting", speed * 3.6, e.what());
    out.failed = true;
  } catch (const ModelRangeError& e) {
    range_stop = e.what();
  } catch (const NumericalError& e) {
    // The numerics broke down: says nothing about the physics, no verdict here.
    spdlog::error("speed {:.1f} km/h: numerical failure ({}); this point has no verdict", speed * 3.6, e.what());
    out.numerical_failure = true;
  }
  for (std::size_t w = 0; w < nw; ++w) {
    if (t.size() < 8) break;
    const auto lc = results::settled_amplitude(t, y[w], o.tail_fraction);
    if (lc.amplitude > out.amplitude) {
      out.amplitude = lc.amplitude;
      out.frequency = lc.frequency;
      out.growth = lc.growth;
    }
  }
  if (!range_stop.empty()) {
    // The motion left the model's range (a wheel lifting in the lateral model,
    // a geometry without flange run out of). After the lateral motion had
    // grown (some wheelset further out than it started, and than the
    // threshold) that is the instability the sweep looks for: it counts as
    // hunting, as a derailment does. Without that growth (at the start, or
    // while the motion decayed) it says nothing about the physics: no verdict.
    double grown = 0.0;  // largest |y| over its start (or the threshold), over the wheelsets [m]
    for (std::size_t w = 0; w < nw && !y[w].empty(); ++w) {
      double peak = 0.0;
      for (double v : y[w]) peak = std::max(peak, std::abs(v));
      grown = std::max(grown, peak - std::max(std::abs(y[w].front()), o.threshold));
    }
    if (grown > 0.1 * o.threshold) {
      spdlog::warn("speed {:.1f} km/h: run stopped after its lateral motion grew by {:.2f} mm ({}); counted as "
                   "hunting",
                   speed * 3.6, grown * 1e3, range_stop);
      out.failed = true;
    } else {
      spdlog::error("speed {:.1f} km/h: the run left the model's range before its motion grew ({}); this point "
                    "has no verdict",
                    speed * 3.6, range_stop);
      out.numerical_failure = true;
    }
  }
  return out;
}

// The points file of a bifurcation sweep, one format for every kind of sweep
// (plain, continuation phase 1, the continuation chain): the columns below
// (column "down": 1 on the down branch, 0 on the up branch) and the key
// "<branch>:<speed %.6g m/s>", or "chain:<speed>" for a down-branch point
// started from the final state of the speed above (path following). Column
// "stop": 0 the run reached its end, 1 it derailed or left the model's range
// after its lateral motion grew (counts as hunting), 2 numerical failure, or
// out of range before the motion grew (no verdict).
// (Files of earlier versions had "failed", 1 for any stop: they are refused.)
const std::vector<std::string> kPointColumns = {"speed_m_s", "down", "amplitude_m", "frequency_hz", "growth", "stop"};
constexpr const char* kChainPrefix = "chain";

std::string point_key(Branch b, bool chained, double v) {
  char key[64];
  std::snprintf(key, sizeof key, "%s:%.6g", chained ? kChainPrefix : branch_name(b), v);
  return key;
}

bool is_chain_key(const std::string& key) { return key.substr(0, key.find(':')) == kChainPrefix; }

std::vector<double> point_row(double v, Branch b, const PointOutcome& r) {
  return {v, b == Branch::down ? 1.0 : 0.0, r.amplitude, r.frequency, r.growth,
          r.numerical_failure ? 2.0 : (r.failed ? 1.0 : 0.0)};
}

// The finished points as read back (a resumed sweep reads them from its
// files): a value that cannot come from a run (not finite, a "down" or
// "failed" column out of its codes) means a damaged file, not a result.
const std::vector<SweepResult>& checked_points(const std::vector<SweepResult>& rows, const std::string& file) {
  for (const SweepResult& r : rows) {
    bool ok = r.values.size() == kPointColumns.size();
    for (std::size_t i = 0; ok && i < r.values.size(); ++i) ok = std::isfinite(r.values[i]);
    ok = ok && r.values[0] > 0.0 && (r.values[1] == 0.0 || r.values[1] == 1.0) && r.values[2] >= 0.0 &&
         r.values[3] >= 0.0 && (r.values[5] == 0.0 || r.values[5] == 1.0 || r.values[5] == 2.0);
    if (!ok)
      throw InputError(file + ": point '" + r.key + "' has a value no run gives (not finite, or a column out of its "
                       "range): a damaged file; delete its line (or the file and its .part files) to compute it again");
  }
  return rows;
}

BifurcationPoint point_of(const SweepResult& r) {
  BifurcationPoint p;
  p.speed = r.values[0];
  p.branch = r.values[1] > 0.5 ? Branch::down : Branch::up;
  p.amplitude = r.values[2];
  p.frequency = r.values[3];
  p.growth = r.values[4];
  p.failed = r.values[5] > 0.5 && r.values[5] < 1.5;
  p.numerical_failure = r.values[5] >= 1.5;
  p.continued = is_chain_key(r.key);
  return p;
}

// The points of a sweep (down branch from v_max downwards, then the up branch)
// and the branch of each, by point index.
struct SweepPlan {
  std::vector<SweepPoint> points;  // params: {speed [m/s]}
  std::vector<Branch> branch;
};

SweepPlan sweep_plan(const BifurcationOptions& o) {
  SweepPlan plan;
  const long n_speeds = static_cast<long>(std::floor((o.v_max - o.v_min) / o.v_step + 1e-9)) + 1;
  for (const Branch b : {Branch::down, Branch::up}) {
    if (b == Branch::up && !o.up_branch) continue;
    for (long i = 0; i < n_speeds; ++i) {
      const double v = o.v_max - static_cast<double>(i) * o.v_step;
      plan.points.push_back({static_cast<long>(plan.points.size()), point_key(b, false, v), {v}});
      plan.branch.push_back(b);
    }
  }
  return plan;
}

SweepOptions sweep_options(const BifurcationOptions& o, const std::string& output, bool use_mpi) {
  SweepOptions so;
  so.output = output;
  // Only deterministic values go into the points file, so that thread and MPI
  // runs of the same sweep write identical files (no wall times here).
  so.result_columns = kPointColumns;
  so.threads = o.threads;
  so.use_mpi = use_mpi;
  so.label = o.label;
  return so;
}

// One sweep point, the same for every kind of sweep: the run from its branch's
// disturbance; with `states`, the final state of a down-branch run that did not
// stop is kept under the point's key.
std::vector<double> run_sweep_point(const Scenario& sc, const BifurcationOptions& o, const SweepPlan& plan,
                                    const SweepPoint& p, StateStore* states) {
  const double v = p.params[0];
  const Branch b = plan.branch[static_cast<std::size_t>(p.index)];
  const bool keep = states && b == Branch::down;
  Eigen::VectorXd x_end;
  const PointOutcome r = run_point(
      sc, v, disturbed_state(sc, b == Branch::down ? o.large_disturbance : o.small_disturbance), o,
      keep ? &x_end : nullptr);
  if (keep && !r.failed && !r.numerical_failure) states->put(p.key, x_end);
  return point_row(v, b, r);
}

// Where the hunting limit cycle collapsed during the ramp. The envelope of the
// lateral motion is sampled at its half-cycle peaks. While the speed is above
// the critical speed the peaks stay (nearly) constant: the limit cycle only
// drifts with speed. The collapse is the last unbroken run of peaks that decay
// faster than `collapse_rate` (logarithmic rate, 1/s) and ends below the
// threshold; the critical speed is the speed at the start of that run. Using
// the start of the decay rather than the threshold crossing removes most of the
// lag of a finite deceleration (True 2013).
double collapse_speed(const std::vector<double>& t, const std::vector<double>& v, const std::vector<double>& env,
                      std::size_t first, const RampingOptions& o, bool& hunting_at_end, long& at) {
  at = -1;
  std::vector<std::size_t> peaks;
  for (std::size_t i = std::max<std::size_t>(first, 1); i + 1 < env.size(); ++i)
    if (env[i] >= env[i - 1] && env[i] > env[i + 1]) peaks.push_back(i);
  hunting_at_end = false;
  if (peaks.empty()) return o.v_start;
  // Last peak above the threshold: the collapse is complete after it.
  long last = -1;
  for (long k = static_cast<long>(peaks.size()) - 1; k >= 0; --k)
    if (env[peaks[static_cast<std::size_t>(k)]] > o.threshold) {
      last = k;
      break;
    }
  if (last < 0) return o.v_start;
  if (t.back() - t[peaks[static_cast<std::size_t>(last)]] < 1.0) {
    hunting_at_end = true;  // still oscillating at the end of the ramp
    return std::numeric_limits<double>::quiet_NaN();
  }
  // Walk back one peak at a time while the envelope over the second before
  // the peak decays faster than collapse_rate. The one-second window spans the
  // beat between wheelsets; stepping by single peaks (not by whole windows)
  // keeps the reading independent of where a window grid happens to fall, so
  // a change at the integrator's tolerance level cannot move it by a window.
  auto rate = [&](std::size_t k0, std::size_t k1) {
    const std::size_t i0 = peaks[k0], i1 = peaks[k1];
    return std::log(env[i1] / env[i0]) / (t[i1] - t[i0]);
  };
  std::size_t k = static_cast<std::size_t>(last);
  while (k > 0) {
    std::size_t j = k;
    while (j > 0 && t[peaks[k]] - t[peaks[j]] < 1.0) --j;
    if (j == k || rate(j, k) > -o.collapse_rate) break;
    --k;
  }
  at = static_cast<long>(peaks[k]);
  return v[peaks[k]];
}

}  // namespace

namespace {
BifurcationResult collect(const std::vector<SweepResult>& rows, const BifurcationOptions& o);
BifurcationResult continuation_sweep(const Scenario& scenario, const BifurcationOptions& o, const SweepPlan& plan,
                                     const std::string& points_csv);
}  // namespace

const char* branch_name(Branch b) { return b == Branch::up ? "up" : "down"; }

bool is_hunting(const BifurcationPoint& p, const BifurcationOptions& o) {
  const PointState s = point_state(p, o);
  return s == PointState::stopped || s == PointState::settled || s == PointState::growing;
}

PointState point_state(const BifurcationPoint& p, const BifurcationOptions& o) {
  if (p.numerical_failure) return PointState::failed;
  if (p.failed) return PointState::stopped;
  if (!(p.amplitude > o.threshold)) return PointState::centred;
  if (!(p.frequency > 0.0)) return PointState::too_short;
  if (p.growth > o.decay_tolerance) return PointState::growing;
  if (p.growth < -o.decay_tolerance) return PointState::decaying;
  return PointState::settled;
}

const char* point_state_name(PointState s) {
  switch (s) {
    case PointState::settled: return "settled";
    case PointState::growing: return "growing";
    case PointState::decaying: return "decaying";
    case PointState::centred: return "centred";
    case PointState::stopped: return "stopped";
    case PointState::failed: return "failed";
    case PointState::too_short: return "too_short";
  }
  return "settled";
}

void check_model_has_patch(const Scenario& sc, const std::string& model) {
  if (model.empty() || contact::find_tangential_model(model).geometry_coefficients || sc.nominal_patch.Fz > 0.0) return;
  throw InputError("tangential model '" + model + "' needs a contact patch, and scenario '" + sc.name + "' (" +
                   sc.file + ") gives none: its conical wheels carry prescribed creep coefficients only. Add "
                   "contact.patch {a, b, N_ref} or geometry curvatures (A, B), use a table or profiles geometry, "
                   "or keep the model 'coefficients'");
}

Scenario with_contact(const Scenario& scenario, const std::string& tangential_model,
                      const contact::ReductionFactors* reduction) {
  check_model_has_patch(scenario, tangential_model);
  Scenario s = scenario;
  CouplingOptions o = s.model.coupling.options();
  if (!tangential_model.empty()) o.tangential = tangential_model;
  if (reduction) {
    o.reduction = *reduction;
    o.material.mu = s.creep_material.mu;  // a layer's friction limit goes with the layer
    contact::ReductionSpec spec;
    spec.form = (reduction->k11 == reduction->k22 && reduction->k22 == reduction->k23) ? contact::ReductionForm::uniform
                                                                                     : contact::ReductionForm::factors;
    spec.k = *reduction;
    spec.text = contact::describe_reduction(*reduction);
    s.reduction = spec;
    s.layer = {};
  }
  s.model.coupling = WheelRailCoupling(o);
  return s;
}

Scenario with_reduction(const Scenario& scenario, const contact::ReductionSpec& spec, const std::string& where,
                        const std::string& cache_dir, const std::string& tangential_model) {
  check_model_has_patch(scenario, tangential_model);
  Scenario s = scenario;
  if (!tangential_model.empty()) {
    CouplingOptions o = s.model.coupling.options();
    o.tangential = tangential_model;
    s.model.coupling = WheelRailCoupling(o);
  }
  apply_reduction(s, spec, where, cache_dir);
  return s;
}

bool linearly_unstable(const Scenario& scenario, double v) {
  return max_real_part(scenario.model, v) > kUnstableGrowth;
}

double linear_critical_speed(const Scenario& scenario, double v_lo, double v_hi) {
  const double lo = max_real_part(scenario.model, v_lo);
  const double hi = max_real_part(scenario.model, v_hi);
  // The same threshold as the bisection: an undamped mode at rounding level is not a loss of stability.
  if (lo > kUnstableGrowth) return v_lo;   // already unstable at the bottom of the range
  if (hi <= kUnstableGrowth) return kNaN;  // stable over the whole range
  return critical_speed(scenario.model, v_lo, v_hi);
}

namespace {

// What a sweep's points depend on besides their speed and branch, one
// "key value" line each: the sweep's options, the integrator's settings and
// the model itself, seen through its right-hand side at 30 m/s (sweeps over
// any speed range share their common speeds) from the down branch's disturbed state and from the start state (an FNV-1a hash
// of the state derivatives: any change of the vehicle, track, contact model
// or reduction changes it, as it changes the runs).
std::string sweep_settings(const Scenario& scenario, const BifurcationOptions& o) {
  const auto num = [](double v) {
    char b[40];
    std::snprintf(b, sizeof b, "%.17g", v);
    return std::string(b);
  };
  std::string s = "railsim bifurcation sweep settings 1\n";
  s += "duration_s " + num(o.duration) + "\n";
  s += "large_disturbance_m " + num(o.large_disturbance) + "\n";
  s += "small_disturbance_m " + num(o.small_disturbance) + "\n";
  s += "threshold_m " + num(o.threshold) + "\n";
  s += "tail_fraction " + num(o.tail_fraction) + "\n";
  s += "decay_tolerance " + num(o.decay_tolerance) + "\n";
  const IntegratorOptions& i = scenario.integrator;
  s += "integrator " + i.method + " rtol " + num(i.rtol) + " atol " + num(i.atol) + " max_step " + num(i.max_step) +
       " initial_step " + num(i.initial_step) + " min_step " + num(i.min_step) + " max_steps " +
       std::to_string(i.max_steps) + " jacobian " + i.jacobian + " linear_solver " + i.linear_solver + " max_order " +
       std::to_string(i.max_order) + " stability_limit_detection " + std::to_string(int(i.stability_limit_detection)) +
       " atol_contact_modes " + num(i.atol_contact_modes) + " jacobian_max_age " + std::to_string(i.jacobian_max_age) +
       "\n";
  // At a fixed speed (30 m/s), not the sweep's top: sweeps over other speed
  // ranges share the points of their common speeds.
  const Scenario sc = at_speed(scenario, 30.0, 0.0);
  Data data(sc.model);
  data.warm_start = false;  // the bits of each evaluation, not of the one before (Data::warm_start)
  Eigen::VectorXd xdot(sc.model.n_states);
  ContentHash h;
  for (const Eigen::VectorXd& x : {disturbed_state(sc, o.large_disturbance), Eigen::VectorXd(sc.x0)}) {
    rhs(sc.model, data, 0.0, x.data(), xdot.data());
    h.bytes(xdot.data(), sizeof(double) * std::size_t(xdot.size()));
  }
  char hex[24];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h.value()));
  s += "model " + sc.name + " " + std::to_string(sc.model.n_states) + " states, equations " + hex + "\n";
  return s;
}

// A sweep resumes from its points file only when it was made with the same
// settings (OUT.settings, written before the first point): otherwise its
// points would be taken for this sweep's. InputError naming what differs.
void check_resumable(const Scenario& scenario, const BifurcationOptions& o, const std::string& points_csv) {
  namespace fs = std::filesystem;
  const std::string file = points_csv + ".settings";
  const std::string now = sweep_settings(scenario, o);
  std::error_code ec;
  if (fs::exists(file, ec)) {
    std::ifstream in(file, std::ios::binary);
    const std::string before((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (before == now) return;
    // The first line that differs, old and new.
    std::istringstream a(before), b(now);
    std::string la, lb;
    while (std::getline(a, la) && std::getline(b, lb) && la == lb) {
    }
    throw InputError(points_csv + ": this folder holds a sweep made with other settings (" + file + ": '" + la +
                     "', now '" + lb + "'); its points are not this sweep's: give another output folder, or remove "
                     "this one to start again");
  }
  // Under mpirun rank 0 alone checks for settings-less points and writes the
  // file (another rank may see rank 0's first points, written after it).
  if (mpi_context().rank != 0) return;
  bool points = false;
  for (const std::string& f : {points_csv, points_csv + ".part0", points_csv + ".sweep.csv", points_csv + ".chain.csv"})
    points = points || (fs::is_regular_file(f, ec) && fs::file_size(f, ec) > 0 && !ec);
  if (points)
    throw InputError(points_csv + ": this folder holds sweep points without their settings file (" + file +
                     "; written by an earlier version): they cannot be checked against this sweep's settings; give "
                     "another output folder, or remove this one to start again");
  const fs::path dir = fs::path(file).parent_path();
  if (!dir.empty()) fs::create_directories(dir);
  write_file_atomically(file, now);
}

}  // namespace

BifurcationResult bifurcation_sweep(const Scenario& scenario, const BifurcationOptions& o,
                                    const std::string& points_csv) {
  if (!(o.v_min > 0.0 && o.v_max > o.v_min && o.v_step > 0.0))
    throw InputError("bifurcation sweep: need 0 < v_min < v_max and v_step > 0");
  const SweepPlan plan = sweep_plan(o);
  check_resumable(scenario, o, points_csv);
  if (o.continuation) return continuation_sweep(scenario, o, plan, points_csv);
  const auto fn = [&](const SweepPoint& p) { return run_sweep_point(scenario, o, plan, p, nullptr); };
  return collect(checked_points(run_sweep(plan.points, fn, sweep_options(o, points_csv, o.use_mpi)), points_csv), o);
}

namespace {

BifurcationResult collect(const std::vector<SweepResult>& rows, const BifurcationOptions& o) {
  BifurcationResult res;
  res.resolution = o.v_step;
  for (const auto& r : rows) res.points.push_back(point_of(r));
  std::sort(res.points.begin(), res.points.end(), [](const auto& a, const auto& b) {
    return a.branch != b.branch ? a.branch < b.branch : a.speed < b.speed;
  });
  // V_NL: lowest speed of a contiguous hunting range on the down branch that
  // reaches the top of the sweep.
  res.nonlinear_critical_speed = kNaN;
  std::vector<const BifurcationPoint*> down;
  for (const auto& p : res.points)
    if (p.branch == Branch::down) down.push_back(&p);
  res.fold_amplitude = res.fold_frequency = kNaN;
  for (auto it = down.rbegin(); it != down.rend(); ++it) {
    const PointState s = point_state(**it, o);
    if (s == PointState::failed || s == PointState::too_short) {
      // The hunting range cannot be followed past this point: no verdict.
      char buf[400];
      const bool top = it == down.rbegin();
      if (s == PointState::failed)
        std::snprintf(buf, sizeof buf,
                      "the run at %.1f km/h on the down branch stopped on a numerical failure "
                      "(see the log); %s, so there is no critical speed",
                      (*it)->speed * 3.6,
                      top ? "it is the top of the sweep, where the hunting range must start"
                          : "the hunting range above it cannot be followed past it");
      else
        std::snprintf(buf, sizeof buf,
                      "the run at %.1f km/h on the down branch is too short to show a cycle: amplitude %.2f mm "
                      "with fewer than two half-cycles in the last %.0f %% of its %.3g s; raise the duration "
                      "per point (--duration)",
                      (*it)->speed * 3.6, (*it)->amplitude * 1e3, o.tail_fraction * 100.0, o.duration);
      res.undetermined = buf;
      res.undetermined_kind = s == PointState::failed ? BifurcationResult::Undetermined::numerical_failure
                                                      : BifurcationResult::Undetermined::too_short;
      res.nonlinear_critical_speed = res.fold_amplitude = res.fold_frequency = kNaN;
      break;
    }
    if (!is_hunting(**it, o)) break;
    res.nonlinear_critical_speed = (*it)->speed;
    res.fold_amplitude = (*it)->amplitude;
    res.fold_frequency = (*it)->frequency;
    if (std::next(it) == down.rend()) {
      // Hunting down to the lowest speed swept: the fold is not in the range.
      char buf[300];
      std::snprintf(buf, sizeof buf,
                    "the down branch still hunts at the lowest speed of the sweep, %.1f km/h: the critical speed lies "
                    "at or below it; lower the sweep's lowest speed (--v-min)",
                    (*it)->speed * 3.6);
      res.undetermined = buf;
      res.undetermined_kind = BifurcationResult::Undetermined::below_range;
      res.nonlinear_critical_speed = res.fold_amplitude = res.fold_frequency = kNaN;
    }
  }
  return res;
}

// Path following on the down branch, in two phases.
// 1. Every point of both branches runs in parallel, as without continuation;
//    the down-branch runs keep their final states.
// 2. From the lowest speed V_h of the contiguous hunting range of phase 1, a
//    serial chain steps down: each speed starts from the final state of the one
//    above (on the limit cycle while it exists), until a speed no longer hunts
//    or a run stops: that is the fold of the branch. The chain's results
//    replace phase 1's down-branch results at its speeds (keys "chain:<v>").
// Above V_h the large disturbance already reaches the branch, so only the few
// speeds between V_h and the fold run serially. Files: OUT.sweep.csv (phase 1),
// OUT.down.states (final states), OUT.chain.csv (phase 2, rewritten after each
// chain point); merged into OUT. An interrupted run resumes from them.
BifurcationResult continuation_sweep(const Scenario& scenario, const BifurcationOptions& o, const SweepPlan& plan,
                                     const std::string& points_csv) {
  if (mpi_context().size > 1)
    throw InputError("bifurcation sweep: continuation (--continuation, or continuation: true in the scenario's "
                     "critical_speed section) keeps the final states of the runs in one file: use threads "
                     "(--threads), or --no-continuation under mpirun");
  const std::filesystem::path out_path(points_csv);
  if (out_path.has_parent_path()) std::filesystem::create_directories(out_path.parent_path());
  StateStore states(points_csv + ".down.states", scenario.model.n_states);

  // Phase 1: the plain sweep, keeping the down branch's final states (threads only).
  std::vector<SweepResult> rows = run_sweep(
      plan.points, [&](const SweepPoint& p) { return run_sweep_point(scenario, o, plan, p, &states); },
      sweep_options(o, points_csv + ".sweep.csv", false));
  checked_points(rows, points_csv + ".sweep.csv");

  // Phase 2: the chain below V_h. Down rows in descending speed (the order of `points`).
  std::vector<SweepResult*> down;
  for (const auto& p : plan.points)
    if (plan.branch[static_cast<std::size_t>(p.index)] == Branch::down)
      for (auto& r : rows)
        if (r.index == p.index) down.push_back(&r);
  long lowest = -1;  // position in `down` of V_h
  for (std::size_t i = 0; i < down.size() && is_hunting(point_of(*down[i]), o); ++i) lowest = static_cast<long>(i);
  const std::string chain_csv = points_csv + ".chain.csv";
  std::vector<SweepResult> chain = read_finished_points(chain_csv, kPointColumns.size(), &kPointColumns);
  checked_points(chain, chain_csv);
  if (lowest >= 0 && static_cast<std::size_t>(lowest) + 1 < down.size()) {
    const SweepResult& vh = *down[static_cast<std::size_t>(lowest)];
    std::string from = vh.key;
    if (!states.find(from) && !point_of(vh).failed && !point_of(vh).numerical_failure) {
      // Its state was lost (an interrupted write): the run is deterministic, run it again.
      Eigen::VectorXd x_end;
      const PointOutcome r = run_point(scenario, vh.values[0], disturbed_state(scenario, o.large_disturbance), o,
                                       &x_end);
      if (!r.failed && !r.numerical_failure) states.put(from, x_end);
    }
    if (!states.find(from))
      spdlog::warn("bifurcation sweep: the run at {:.1f} km/h stopped, so no limit cycle to follow below it",
                   vh.values[0] * 3.6);
    for (std::size_t i = static_cast<std::size_t>(lowest) + 1; i < down.size() && states.find(from); ++i) {
      SweepResult& target = *down[i];
      const double v = target.values[0];
      const std::string key = point_key(Branch::down, true, v);
      auto done = std::find_if(chain.begin(), chain.end(), [&](const SweepResult& r) { return r.key == key; });
      if (done == chain.end() ||
          (is_hunting(point_of(*done), o) && !point_of(*done).failed && !states.find(key))) {
        spdlog::info("{}: following the branch down to {:.1f} km/h", o.label, v * 3.6);
        Eigen::VectorXd x_end;
        const PointOutcome r = run_point(scenario, v, *states.find(from), o, &x_end);
        if (!r.failed && !r.numerical_failure) states.put(key, x_end);
        if (done != chain.end()) chain.erase(done);
        chain.push_back({target.index, key, point_row(v, Branch::down, r)});
        write_sweep_file(chain_csv, kPointColumns, chain);
        done = chain.end() - 1;
      }
      target.key = done->key;
      target.values = done->values;
      const BifurcationPoint p = point_of(*done);
      if (!is_hunting(p, o) || p.failed) break;
      from = key;
    }
  }
  write_sweep_file(points_csv, kPointColumns, rows);
  return collect(rows, o);
}

}  // namespace

RampingResult ramping(const Scenario& scenario, const RampingOptions& o) {
  if (!(o.v_start > o.v_end && o.v_end > 0.0 && o.deceleration > 0.0))
    throw InputError("ramping: need v_start > v_end > 0 and deceleration > 0");
  RampingResult res;
  res.start_speed = o.v_start;
  res.critical_time = res.critical_amplitude = kNaN;
  const auto t0 = std::chrono::steady_clock::now();
  const Scenario sc = at_speed(scenario, o.v_start, 0.0);
  const std::size_t nw = sc.model.wheelsets.size();

  // Phase 1: settle at v_start on the attractor reached from the disturbance.
  // Phase 2: decelerate to v_end. Both are one simulation with a speed profile
  // V(t) = v_start for t < settle_time, then v_start - a (t - settle_time);
  // implemented as two runs, the second started from the final state of the first.
  std::vector<double> t_all, v_all, ymax_all;
  Eigen::VectorXd x_end;
  auto record = [&](const Scenario& s, double t_offset) {
    return Observer([&, t_offset](double ti, const Eigen::VectorXd& x, const Data&) {
      double m = 0.0;
      for (std::size_t w = 0; w < nw; ++w) m = std::max(m, std::fabs(x[s.model.bodies[s.model.wheelsets[w].body].q_index[kLat]]));
      t_all.push_back(t_offset + ti);
      v_all.push_back(s.model.speed.speed(ti));
      ymax_all.push_back(m);
      x_end = x;
    });
  };
  const auto derailed = [&](const DerailmentError& e, const char* phase) {
    res.derailment = std::string("the vehicle derailed ") + phase + ": " + e.what();
    res.critical_speed = kNaN;
    spdlog::warn("ramping: {}", res.derailment);
  };
  // A stop on leaving the model's range: a result when the lateral motion of
  // this phase (records from `first`) had grown by a tenth of the threshold
  // over its start value and the threshold (the bifurcation sweep's rule,
  // run_point), else rethrown as the numerical failure it is.
  const auto left_range = [&](const ModelRangeError& e, std::size_t first, const char* phase) {
    double peak = 0.0;
    for (std::size_t i = first; i < ymax_all.size(); ++i) peak = std::max(peak, ymax_all[i]);
    const double start = first < ymax_all.size() ? ymax_all[first] : 0.0;
    const double grown = peak - std::max(start, o.threshold);
    if (!(grown > 0.1 * o.threshold))
      throw NumericalError(std::string("ramping: numerical failure ") + phase + " (the run left the model's range "
                           "before its motion grew): " + e.what());
    char head[200];
    std::snprintf(head, sizeof head, "the lateral motion grew by %.2f mm and left the model's range %s: ", grown * 1e3,
                  phase);
    res.range_stop = head + std::string(e.what()) +
                     " (hunting beyond what the model covers: lower the start speed, or use the full wheelset model)";
    res.critical_speed = kNaN;
    spdlog::warn("ramping: {}", res.range_stop);
  };
  try {
    simulate(sc.model, sc.integrator, disturbed_state(sc, o.disturbance), o.settle_time, o.output_interval,
             record(sc, 0.0), o.stop);
  } catch (const DerailmentError& e) {
    char phase[96];
    std::snprintf(phase, sizeof phase, "while settling at the start speed %.1f km/h (lower the start speed)",
                  o.v_start * 3.6);
    derailed(e, phase);
  } catch (const ModelRangeError& e) {
    char phase[96];
    std::snprintf(phase, sizeof phase, "while settling at the start speed %.1f km/h", o.v_start * 3.6);
    left_range(e, 0, phase);
  } catch (const NumericalError& e) {
    throw NumericalError(std::string("ramping: numerical failure while settling at the start speed: ") + e.what());
  }
  // Hunting at the start: the last second of the settling run still oscillates.
  double late_peak = 0.0;
  for (std::size_t i = 0; i < t_all.size(); ++i)
    if (t_all[i] > o.settle_time - 1.0) late_peak = std::max(late_peak, ymax_all[i]);
  res.hunting_at_start = res.stopped() || late_peak > o.threshold;
  if (res.stopped()) {
    // No ramp: the record ends where the vehicle derailed or left the model's range.
  } else if (!res.hunting_at_start) {
    res.critical_speed = kNaN;
    spdlog::warn("ramping: no hunting at {:.1f} km/h (peak {:.2f} mm in the last second): raise the start speed",
                 o.v_start * 3.6, late_peak * 1e3);
  } else {
    Scenario ramp = sc;
    ramp.model.speed.v0 = o.v_start;
    ramp.model.speed.accel = -o.deceleration;
    ramp.model.speed.s0 = sc.model.speed.distance(o.settle_time);
    const double duration = (o.v_start - o.v_end) / o.deceleration;
    const std::size_t first_ramp = t_all.size();
    try {
      simulate(ramp.model, ramp.integrator, x_end, duration, o.output_interval, record(ramp, o.settle_time), o.stop);
    } catch (const DerailmentError& e) {
      derailed(e, "during the ramp");
    } catch (const ModelRangeError& e) {
      left_range(e, first_ramp, "during the ramp");
    } catch (const NumericalError& e) {
      throw NumericalError(std::string("ramping: numerical failure during the ramp: ") + e.what());
    }
    if (!res.stopped()) {
      long at = -1;
      res.critical_speed = collapse_speed(t_all, v_all, ymax_all, first_ramp, o, res.hunting_at_end, at);
      if (at >= 0) {
        res.critical_time = t_all[static_cast<std::size_t>(at)];
        res.critical_amplitude = ymax_all[static_cast<std::size_t>(at)];
      }
    }
  }
  res.time = std::move(t_all);
  res.speed = std::move(v_all);
  res.max_lateral = std::move(ymax_all);
  res.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return res;
}

}  // namespace railsim::engine
