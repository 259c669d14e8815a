// Shared by the FASTSIM and FaStrip tests: CONTACT's exact creep curves for a
// circular Hertzian patch (tests/data/reference/contact/creep_curves_circ_exact.csv,
// units mm, N, N mm, spin rad/mm; README.md there) and the error of a
// tangential model against them, per family (long, lat, spin).
#pragma once

#include <algorithm>
#include <numbers>
#include <cmath>
#include <string>
#include <vector>

#include "contact/tangential_model.hpp"
#include "results/csv_writer.hpp"
#include "test_support.hpp"

namespace railsim::test {

struct CreepCase {
  std::string family;  // long | lat | spin
  contact::ContactInput in;
  double Fx, Fy, Mz;   // exact [N, N, N m]
};

inline std::vector<CreepCase> load_circular_creep_curves() {
  const auto t = results::read_csv(reference_path("contact/creep_curves_circ_exact.csv"));
  std::vector<CreepCase> cases;
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    CreepCase c;
    c.family = t.rows[r][t.column("family")];
    c.in.patch.a = t.number(r, "a_mm") * 1e-3;
    c.in.patch.b = t.number(r, "b_mm") * 1e-3;
    c.in.patch.Fz = t.number(r, "FN_N");
    c.in.patch.p0 = 3.0 * c.in.patch.Fz / (2.0 * std::numbers::pi * c.in.patch.a * c.in.patch.b);
    // README: E = 210000 MPa, nu = 0.28 (G = 82031.25 MPa).
    c.in.material = contact::Material{210.0e9, 0.28, t.number(r, "mu")};
    c.in.creep = {t.number(r, "cksi"), t.number(r, "ceta"), t.number(r, "cphi_per_mm") * 1e3};
    c.Fx = t.number(r, "Fx_N");
    c.Fy = t.number(r, "Fy_N");
    c.Mz = t.number(r, "Mz_Nmm") * 1e-3;
    cases.push_back(c);
  }
  return cases;
}

// Largest errors of a model over one family, skipping the zero-creepage row:
//   force: |F - F_ref| / |F_ref| of the driven component (Fx for long, Fy else);
//   force_muN: the same difference over mu Fz;
//   moment: |Mz - Mz_ref| / max|Mz_ref| over the family (lat and spin only).
struct FamilyError {
  double force = 0.0, force_muN = 0.0, moment = 0.0;
  int points = 0;
};

inline FamilyError family_error(const contact::TangentialModel& m, const std::vector<CreepCase>& cases,
                                const std::string& family) {
  FamilyError e;
  double mz_max = 0.0;
  for (const auto& c : cases)
    if (c.family == family) mz_max = std::max(mz_max, std::abs(c.Mz));
  auto ws = m.make_workspace();
  for (const auto& c : cases) {
    if (c.family != family) continue;
    if (c.in.creep.xi == 0.0 && c.in.creep.eta == 0.0 && c.in.creep.phi == 0.0) continue;
    const contact::ContactForces f = m.solve(c.in, ws.get());
    const bool lon = family == "long";
    const double ref = lon ? c.Fx : c.Fy;
    const double got = lon ? f.Fx : f.Fy;
    e.force = std::max(e.force, std::abs(got - ref) / std::abs(ref));
    e.force_muN = std::max(e.force_muN, std::abs(got - ref) / (c.in.material.mu * c.in.patch.Fz));
    if (!lon && mz_max > 0.0) e.moment = std::max(e.moment, std::abs(f.Mz - c.Mz) / mz_max);
    ++e.points;
  }
  return e;
}

}  // namespace railsim::test
