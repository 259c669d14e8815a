// Contact audit of a vehicle run ("model no more than the scene needs", as
// evidence per run; issue 15 item 7): n of the run's own contact states
// (contact_state_sample.hpp: the extremes and the rest evenly in time) solved
// with the exact MIM at a fine grid and with every registered tangential
// model (contact/contact_audit.hpp), the error of the model the run used, and
// which cheaper or more accurate model would have met a tolerance over this
// run's contacts.
//
// The run's own model is re-solved on the sampled inputs with the run's
// options (`reproduction`: the largest |F_run - F_resolved| / (mu N), zero
// when the states are the run's own); it is audited even where comparisons
// leave it out by default (a tabulated model, mim_table; the model on the
// geometry's coefficients, "coefficients", with the run's saturation law and
// the coefficients each sampled input carries). A state whose patch has
// semi-axes but no curvatures A, B (a contact table's patch) gets the
// Hertzian curvatures that give those semi-axes at its load
// (contact::hertz_from_semi_axes; MIM needs the gap), counted in
// `completed_patches`.
// Files (write_contact_audit): DIR/contact_audit.csv, one row per state x
// model (the state: time, distance, wheelset, side, patch, contact angle, a,
// b, A, B, p0, Fz, xi, eta, phi, mu, k11, k22, k23, V, why it was chosen; the
// model's Fx, Fy, Mz, valid, the MIM reference Fx, Fy, Mz, the error in % of
// mu Fz, the time of the call in us), and DIR/contact_audit.png: max error
// against the median cost per call per model (log-log), p95 as hollow markers, the
// run's model highlighted, the tolerance and the MIM reference's cost drawn.
// Units SI; errors as fractions of mu Fz (per cent in the files); costs in ns
// (us in the files).
#pragma once

#include <string>
#include <vector>

#include "contact/contact_audit.hpp"
#include "engine/analysis/contact_state_sample.hpp"
#include "engine/wheel_rail/wheel_rail_coupling.hpp"
#include "results/chart.hpp"
#include "results/json_writer.hpp"

namespace railsim::engine {

struct RunContactAuditOptions {
  int samples = 0;           // states to audit, in [1, 10000] (0: none, ScenarioRunOptions)
  double tolerance = 0.02;   // of mu Fz, in (0, 1]
  int threads = 1;           // in [1, 64]
  int mim_grid = 60;         // reference grid, in [8, 400]
  double mim_tolerance = 1e-6;
  std::string cache_dir;     // for a tabulated run model
  StopRequest stop;          // polled before each state (InterruptedError)
};

struct RunContactAudit {
  std::string run_model;                 // name in result.models
  std::vector<RunContactState> states;   // the sampled states
  std::vector<std::string> why;          // per state: why it was chosen
  std::size_t recorded_states = 0;       // all loaded patches of the run
  std::size_t recorded_rows = 0;
  std::size_t completed_patches = 0;     // sampled states given Hertzian curvatures (see above)
  contact::ContactAuditResult result;
  contact::AuditVerdict verdict;
  double reproduction = 0.0;             // max |F_run - F_resolved| / (mu N) of the run's model
  double wall_seconds = 0.0;
};

// `run`: the run's coupling options (tangential model and saturation law).
// Throws InputError for options outside their ranges or no recorded state,
// NumericalError when the reference fails.
RunContactAudit run_contact_audit(const ContactStateRecorder& recorder, const CouplingOptions& run,
                                  const RunContactAuditOptions& options);

// The summary document's "contact_audit" section.
results::Json contact_audit_json(const RunContactAudit& audit, const Model& model);

// Max error against cost per model; `title_tail` names the run.
results::Chart contact_audit_chart(const RunContactAudit& audit, const std::string& title_tail);

// DIR/contact_audit.csv (the chart is drawn by the caller, with the run's other charts).
void write_contact_audit_csv(const RunContactAudit& audit, const Model& model, const std::string& path);

}  // namespace railsim::engine
