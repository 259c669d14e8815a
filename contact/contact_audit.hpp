// Contact audit: how far each registered tangential model is from the exact
// theory on a given list of contact states (for example the contacts sampled
// from a vehicle run), and which models meet a tolerance there.
//
// Every state (Hertzian patch a, b, A, B, Fz; material; creepages xi, eta,
// phi; reduction factors) is solved with the exact MIM (Kalker 1990, railsim's
// contact/mim, `grid` elements across the minor axis) and with each model;
// the error of a model on a state is the tangential force-vector difference
// over the Coulomb bound, e = |(Fx, Fy) - (Fx, Fy)_MIM| / (mu Fz), the
// measure of issue 15 and of tests/data/contact/spin_reference. Per model:
// largest, mean and 95th-percentile error, the worst state, the number of
// states the model flagged invalid, the mean cost per call (steady clock,
// one call per state: indicative only) and whether max <= tolerance.
// A model that throws on a state (NumericalError) counts as failing there
// (error +inf). States without load (Fz <= 0) are skipped.
// Units: SI; errors and tolerance as fractions of mu Fz.
#pragma once

#include <string>
#include <vector>

#include "contact/types.hpp"

namespace railsim::contact {

struct ContactAuditOptions {
  int mim_grid = 60;           // MIM elements across the minor axis, in [8, 400]
  double mim_tolerance = 1e-6; // MIM tangential tolerance, in (0, 1e-2]
  double tolerance = 0.05;     // a model meets the audit when its max error <= this, in (0, 1]
  // Models to audit by registry name; empty = every registered model that is
  // not tabulated (mim_table needs its cached table: name it to include it).
  std::vector<std::string> models;
  std::string cache_dir;       // table cache folder for tabulated models
};

struct ModelAudit {
  std::string model;
  double max_error = 0.0;   // [-] of mu Fz
  double mean_error = 0.0;
  double p95_error = 0.0;
  std::size_t worst_state = 0;  // index into the audited states
  int flagged_invalid = 0;      // states the model itself flagged outside its domain
  int failed = 0;               // states where the model threw
  double mean_cost_ns = 0.0;    // per call, indicative
  bool meets_tolerance = false;
};

struct ContactAuditResult {
  std::vector<ContactForces> reference;   // MIM per state (zero forces where skipped)
  std::vector<bool> audited;              // false: state skipped (no load)
  std::vector<ModelAudit> models;         // in the order of the registry / of options.models
  std::vector<std::vector<double>> errors;  // errors[m][s], NaN where skipped
  double tolerance = 0.0;
  // Names of the audited models meeting the tolerance, cheapest first.
  std::vector<std::string> meeting_tolerance() const;
};

// Throws InputError for an empty state list, an unknown model name or options
// outside their ranges (the message names the option and the range).
ContactAuditResult audit_contacts(const std::vector<ContactInput>& states, const ContactAuditOptions& options = {});

}  // namespace railsim::contact
