// railsim's exact reference set for the tangential models with spin
// (tests/data/contact/spin_reference/, README.md there): 764 contact states on
// four Hertzian patches (a/b 0.2, 1, 1.33, 5; Fz 75 kN, mu 0.3) solved with the
// MIM at 120 elements across the minor axis. Shared by the tests that hold the
// models to it.
#pragma once

#include <cmath>
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

// The reference solution of `file` (mim_grid120.csv or mim_grid60.csv).
inline std::vector<ReferenceState> load_reference_set(const std::string& file = "mim_grid120.csv") {
  const auto t = results::read_csv(data_path("contact/spin_reference/" + file));
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
