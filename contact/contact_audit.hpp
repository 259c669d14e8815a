// Contact audit: how far each registered tangential model is from the exact
// theory on a given list of contact states (for example the contacts sampled
// from a vehicle run, engine/analysis/run_contact_audit.hpp), and which models
// meet a tolerance there.
//
// Every state (Hertzian patch a, b, A, B, Fz; material; creepages xi, eta,
// phi; reduction factors) is solved with the exact MIM (Kalker 1990, railsim's
// contact/mim, `grid` elements across the minor axis) and with each model;
// the error of a model on a state is the tangential force-vector difference
// over the Coulomb bound, e = |(Fx, Fy) - (Fx, Fy)_MIM| / (mu Fz), the
// measure of issue 15 and of tests/data/contact/spin_reference. Per model:
// largest, mean and 95th-percentile error, the worst state, the number of
// states the model flagged invalid, the mean cost per call (steady clock;
// per state the mean of repeated calls until 20 us have passed, at most 64,
// the reference one call: indicative only, bench/ measures costs) and
// whether max <= tolerance. Costs are compared by their median over the
// states (one preempted timing on a shared machine moves the mean by orders).
// A model that throws on a state (NumericalError) counts as failing there
// (error +inf). States without load (Fz <= 0) or without a patch (a or b
// not positive, e.g. prescribed creep coefficients) are skipped.
// Forces given from elsewhere (computed by code outside the registry, e.g. a
// model under development or another program's results) are audited against
// the same reference by audit_given_forces(); their cost is not measured (NaN).
// audit_verdict() reads the table: the run's model, whether it met the
// tolerance, the cheapest model that did, the cheaper ones that did, and the
// most accurate one.
// States are shared among `threads` worker threads (each with its own
// workspaces); the models are immutable and shared.
// Units: SI; errors and tolerance as fractions of mu Fz; costs in ns.
#pragma once

#include <string>
#include <vector>

#include "contact/types.hpp"
#include "core/stop_request.hpp"

namespace railsim::contact {

struct ContactAuditOptions {
  int mim_grid = 60;           // MIM elements across the minor axis, in [8, 400]
  double mim_tolerance = 1e-6; // MIM tangential tolerance, in (0, 1e-2]
  double tolerance = 0.02;     // a model meets the audit when its max error <= this, in (0, 1]
  // Models to audit by registry name; empty = every registered model compared
  // by default (TangentialModelEntry::compared_by_default(): mim_table needs
  // its cached table, coefficients the geometry's: name them to include them).
  std::vector<std::string> models;
  std::string cache_dir;       // table cache folder for tabulated models
  std::string saturation = "none";  // saturation law of the model "coefficients" (registry.hpp)
  int threads = 1;             // worker threads, in [1, 64]
  StopRequest stop;            // polled before each state: InterruptedError (core/stop_request.hpp)
};

struct ModelAudit {
  std::string model;
  double max_error = 0.0;   // [-] of mu Fz
  double mean_error = 0.0;
  double p95_error = 0.0;
  std::size_t worst_state = 0;  // index into the audited states
  int flagged_invalid = 0;      // states the model itself flagged outside its domain
  int failed = 0;               // states where the model threw
  double mean_cost_ns = 0.0;    // per call, indicative; NaN when not measured (given forces)
  double median_cost_ns = 0.0;  // median over the states (robust to a preempted timing); what ranks costs
  bool meets_tolerance = false;
};

struct ContactAuditResult {
  std::vector<ContactForces> reference;   // MIM per state (zero forces where skipped)
  std::vector<double> reference_cost_ns;  // per state, NaN where skipped
  std::vector<bool> audited;              // false: state skipped (no load or no patch)
  std::vector<ModelAudit> models;         // in the order of the registry / of options.models
  std::vector<std::vector<double>> errors;  // errors[m][s], NaN where skipped, +inf where the model threw
  std::vector<std::vector<ContactForces>> forces;  // forces[m][s] (zero where skipped or failed)
  std::vector<std::vector<double>> cost_ns;        // cost_ns[m][s] of the one call, NaN where skipped or given
  double tolerance = 0.0;
  int mim_grid = 0;
  // Names of the audited models meeting the tolerance, cheapest (median
  // cost) first; models without a measured cost last.
  std::vector<std::string> meeting_tolerance() const;
  // Index of a model by name, -1 if not audited.
  int find(const std::string& model) const;
};

// Throws InputError for an empty state list, an unknown model name or options
// outside their ranges (the message names the option and the range),
// NumericalError when the MIM reference fails on a state.
ContactAuditResult audit_contacts(const std::vector<ContactInput>& states, const ContactAuditOptions& options = {});

// Adds forces computed elsewhere for the same states (one per state) to the
// result as model `name`, with the same statistics (cost not measured).
// Throws InputError when the sizes differ or the name is already audited.
void audit_given_forces(ContactAuditResult& result, const std::string& name, const std::vector<ContactInput>& states,
                        const std::vector<ContactForces>& forces);

// The cheapest audited model (median cost; unmeasured costs last) whose max
// error is within `tolerance` and that never failed, read from the table
// (any tolerance, not only the audit's own); "" when none.
std::string cheapest_within(const ContactAuditResult& result, double tolerance);

struct AuditVerdict {
  std::string run_model;
  int run_index = -1;               // into ContactAuditResult::models; -1: not audited
  bool run_meets = false;
  std::string cheapest_meeting;     // cheapest model meeting the tolerance ("" when none)
  std::vector<std::string> cheaper_meeting;  // meeting it and cheaper than the run's model (cheapest first)
  std::string most_accurate;        // smallest max error (ties: the cheaper)
};

// The verdict for a run that used `run_model` (a name in result.models; the
// registry's "mim" at its default grid is one of the audited models, against
// the finer reference). Throws InputError when run_model is not in the result.
AuditVerdict audit_verdict(const ContactAuditResult& result, const std::string& run_model);

}  // namespace railsim::contact
