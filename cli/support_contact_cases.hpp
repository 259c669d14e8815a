// Contact case files for the contact-model commands (`railsim contact`,
// `railsim demo`, `railsim compare-contact`): reading, Hertz solution and the
// result CSV.
//
// CASES.yaml:
//   material: {E: 2.1e11, nu: 0.28, mu: 0.3}     # Pa, -, -; nu in (0, 0.5]
//   reduction: elastic_fe                         # optional: preset | k | "k11,k22,k23" | {k11, k22, k23}
//   cases:
//     - {id: tread, A: 1.087, B: 1.667, Fz: 75000, xi: 0.001, eta: 0, phi: 0}
//     - {id: patch, a: 0.0065, b: 0.0049, Fz: 75000, xi: 0, eta: 0.001, phi: 0.2, V: 30}
// Each case has either the relative curvatures A, B [1/m] or the semi-axes a, b [m]
// (the curvatures then follow from the Hertz shape equation and the load), the
// normal load Fz [N] in [1, 1e7], the creepages xi, eta [-] and phi [1/m] in [-1000, 1000], and optionally the
// rolling speed V [m/s] (slip-velocity-dependent friction). Unknown keys, missing
// keys and out-of-range values are InputErrors naming file, line and key.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "config/yaml_input.hpp"
#include "contact/tangential_model.hpp"
#include "contact/types.hpp"
#include "engine/analysis/timed_solve.hpp"
#include "results/csv_writer.hpp"

namespace railsim::cli {

struct ContactCase {
  std::string id;
  contact::ContactInput input;  // Hertz patch solved, creepages, material, reduction
};

struct ContactCaseSet {
  std::string file;
  contact::Material material;
  contact::ReductionFactors reduction;  // from the file, or none
  std::vector<ContactCase> cases;
  // Legal but implausible inputs (mu above 1), "file:line: key 'k': value ...
  // (usual range ...)"; also logged as warnings when read.
  std::vector<std::string> warnings;
};

// Read a case set from a parsed YAML document (the root mapping).
ContactCaseSet read_contact_cases(const config::InputNode& root);
// Load and read a case file.
ContactCaseSet load_contact_cases(const std::string& path);
// Replace the reduction factors of every case (the --reduction option).
void set_reduction(ContactCaseSet& set, const contact::ReductionFactors& k);

// Timed model calls: engine/analysis/timed_solve.hpp.
using engine::solve_timed;
using engine::TimedForces;

// Result CSV: id, model, reduction, A, B, a, b, p0, Fz, xi, eta, phi, Fx, Fy, Mz,
// valid, reason, iterations, time_ns (SI units; forces of the rail on the wheel).
std::vector<std::string> contact_csv_columns();
void write_contact_row(results::CsvWriter& csv, const ContactCase& c, std::string_view model,
                       const TimedForces& r);

}  // namespace railsim::cli
