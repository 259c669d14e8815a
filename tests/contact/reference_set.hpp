// railsim's exact reference set for the tangential models with spin
// (tests/data/contact/spin_reference/, README.md there): 764 contact states on
// four Hertzian patches (a/b 0.2, 1, 1.33, 5; Fz 75 kN, mu 0.3) solved with the
// MIM at 30, 60 and 120 elements across the minor axis without extrapolation
// (mim_grid{30,60,120}.csv). The reference is the registered model "mim" at
// grid 120: the Richardson extrapolation 2 F_120 - F_60 of the two finest
// files (contact/mim/mim_model.cpp). Shared by the tests that hold the models to it.
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "contact/hertz.hpp"
#include "contact/tangential_model.hpp"
#include "results/csv_writer.hpp"
#include "test_support.hpp"

namespace railsim::test {

struct ReferenceState {
  std::string id, patch, family;  // id "<patch>/<family>/<xi>/<eta>/<phi>"
  contact::ContactInput in;
  double Fx = 0.0, Fy = 0.0, Mz = 0.0;  // exact [N, N, N m]
  double muN() const { return in.material.mu * in.patch.Fz; }
};

// The MIM solution of one file (mim_grid30.csv, mim_grid60.csv or mim_grid120.csv)
// of tests/data/contact/<folder>/ (spin_reference, or deep_slip: the small
// patches deep in full slip with spin; ids "<patch>/<scale>/<signs>").
inline std::vector<ReferenceState> load_reference_set(const std::string& file,
                                                      const std::string& folder = "spin_reference") {
  const auto t = results::read_csv(data_path("contact/" + folder + "/" + file));
  const contact::Material m{2.1e11, 0.28, 0.3};  // cases.yaml
  std::vector<ReferenceState> v;
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    ReferenceState s;
    s.id = t.rows[r][t.column("id")];
    s.patch = s.id.substr(0, s.id.find('/'));
    const std::string rest = s.id.substr(s.id.find('/') + 1);
    s.family = rest.substr(0, rest.find('/'));
    s.in.patch = contact::hertz_from_semi_axes(t.number(r, "a"), t.number(r, "b"), t.number(r, "Fz"), m);
    s.in.material = m;
    s.in.creep = {t.number(r, "xi"), t.number(r, "eta"), t.number(r, "phi")};
    s.Fx = t.number(r, "Fx");
    s.Fy = t.number(r, "Fy");
    s.Mz = t.number(r, "Mz");
    v.push_back(s);
  }
  return v;
}

// Richardson extrapolation 2 F_fine - F_coarse of two grid files with element
// sizes h and 2 h: what the registered model "mim" returns at the fine grid.
inline std::vector<ReferenceState> extrapolated_reference_set(const std::string& fine, const std::string& coarse) {
  std::vector<ReferenceState> f = load_reference_set(fine);
  const std::vector<ReferenceState> c = load_reference_set(coarse);
  if (c.size() != f.size()) throw std::runtime_error("reference set: " + fine + " and " + coarse + " differ in size");
  for (std::size_t i = 0; i < f.size(); ++i) {
    if (c[i].id != f[i].id) throw std::runtime_error("reference set: row " + std::to_string(i) + " differs in id");
    f[i].Fx = 2.0 * f[i].Fx - c[i].Fx;
    f[i].Fy = 2.0 * f[i].Fy - c[i].Fy;
    f[i].Mz = 2.0 * f[i].Mz - c[i].Mz;
  }
  return f;
}

// The reference: MIM at grid 120, extrapolated (see above).
inline std::vector<ReferenceState> load_reference_set() {
  return extrapolated_reference_set("mim_grid120.csv", "mim_grid60.csv");
}

// Error of a model's force vector against the reference, over mu Fz.
inline double force_error(const contact::ContactForces& f, const ReferenceState& s) {
  return std::hypot(f.Fx - s.Fx, f.Fy - s.Fy) / s.muN();
}

struct SetError {
  double max = 0.0, mean = 0.0;
  std::string worst;
};

// Largest and mean force error of `model` over the states accepted by `keep`.
template <class Keep>
SetError set_error(const contact::TangentialModel& model, const std::vector<ReferenceState>& set, Keep keep) {
  SetError e;
  auto ws = model.make_workspace();
  int n = 0;
  for (const auto& s : set) {
    if (!keep(s)) continue;
    const double err = force_error(model.solve(s.in, ws.get()), s);
    if (err > e.max) {
      e.max = err;
      e.worst = s.id;
    }
    e.mean += err;
    ++n;
  }
  if (n > 0) e.mean /= n;
  return e;
}

}  // namespace railsim::test
