// Tangential contact models against the exact solver; see contact_comparison.hpp.
#include "engine/analysis/contact_comparison.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "contact/kalker_coefficients.hpp"
#include "contact/registry.hpp"
#include "core/errors.hpp"
#include "engine/analysis/timed_solve.hpp"
#include "results/pareto_front.hpp"

namespace railsim::engine {

double ModelStats::mean_F() const { return cases ? sum_F / cases : NAN; }
double ModelStats::rms_F() const { return cases ? std::sqrt(sum_F2 / cases) : NAN; }
double ModelStats::mean_cost_us() const { return cases ? sum_cost_us / cases : NAN; }

CreepDirection parse_creep_direction(const std::string& name, const std::string& where) {
  if (name == "longitudinal") return CreepDirection::longitudinal;
  if (name == "lateral") return CreepDirection::lateral;
  if (name == "diagonal") return CreepDirection::diagonal;
  throw InputError(where + ": unknown creepage direction '" + name + "' (longitudinal, lateral or diagonal)");
}

const char* creep_direction_name(CreepDirection d) {
  switch (d) {
    case CreepDirection::longitudinal: return "longitudinal";
    case CreepDirection::lateral: return "lateral";
    case CreepDirection::diagonal: return "diagonal";
  }
  return "lateral";
}

FailureMapAxes failure_map_axes(const contact::ContactInput& in, CreepDirection direction, int points) {
  FailureMapAxes m;
  if (direction == CreepDirection::longitudinal) m.dir_x = 1.0, m.dir_y = 0.0;
  if (direction == CreepDirection::diagonal) m.dir_x = m.dir_y = std::sqrt(0.5);
  const auto& p = in.patch;
  const double c = std::sqrt(p.a * p.b);
  const double G = in.material.shear_modulus();
  const auto C = contact::kalker_coefficients(p.a / p.b, in.material.nu);
  const double C_dir = std::hypot(m.dir_x * C.C11, m.dir_y * C.C22);
  const double muFz = in.material.mu * p.Fz;
  m.creepage_full_slip = 3.0 * muFz / (G * c * c * C_dir);
  m.spin_unit = muFz / (G * c * c * c * C.C23);
  // Creepage from 3 % to 3x the full-slip creepage; spin up to normalised spin 2.
  const double lo = 0.03 * m.creepage_full_slip, hi = 3.0 * m.creepage_full_slip;
  for (int i = 0; i < points; ++i) {
    const double t = points > 1 ? static_cast<double>(i) / (points - 1) : 0.0;
    m.creepage.push_back(lo * std::pow(hi / lo, t));
    m.spin.push_back(2.0 * m.spin_unit * t);
  }
  return m;
}

namespace {

// One reference solve, timed once (the reference is slow; a single call suffices).
TimedForces reference_solve(const contact::TangentialModel& ref, const contact::ContactInput& in,
                            contact::TangentialWorkspace* ws, const std::string& what) {
  const TimedForces r = solve_once_timed(ref, in, ws);
  if (!r.forces.valid) spdlog::warn("reference for {}: {}", what, r.forces.reason);
  return r;
}

void add_case(ModelStats& st, const contact::ForceError& e, bool valid, double us) {
  ++st.cases;
  st.invalid += valid ? 0 : 1;
  st.max_F = std::max(st.max_F, e.F);
  st.sum_F += e.F;
  st.sum_F2 += e.F * e.F;
  st.max_Fx = std::max(st.max_Fx, e.Fx);
  st.max_Fy = std::max(st.max_Fy, e.Fy);
  st.max_Mz = std::max(st.max_Mz, e.Mz);
  st.sum_cost_us += us;
  st.max_cost_us = std::max(st.max_cost_us, us);
}

FailureMap failure_map(const ComparisonCase& base, const std::vector<ComparedModel>& models,
                       const contact::TangentialModel& ref, contact::TangentialWorkspace* ref_ws,
                       const ContactComparisonOptions& o, std::vector<ModelStats>& stats) {
  FailureMap map;
  map.axes = failure_map_axes(base.input, o.map_direction, o.map_points);
  const auto t0 = std::chrono::steady_clock::now();
  for (const double phi : map.axes.spin) {
    for (const double s : map.axes.creepage) {
      contact::ContactInput in = base.input;
      in.creep = {s * map.axes.dir_x, s * map.axes.dir_y, phi};
      const contact::ContactForces r = reference_solve(ref, in, ref_ws, "failure map").forces;
      for (std::size_t m = 0; m < models.size(); ++m) {
        FailureMapPoint p;
        p.model = m;
        p.creepage = s;
        p.creep = in.creep;
        p.error = contact::force_error(models[m].model->solve(in, models[m].ws), r, in);
        p.failed = !(p.error.F <= o.failure_threshold);
        ++stats[m].map_points;
        stats[m].map_failures += p.failed ? 1 : 0;
        map.points.push_back(p);
      }
    }
  }
  map.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return map;
}

}  // namespace

ContactComparison compare_contact_models(const std::vector<ComparisonCase>& cases,
                                         const std::vector<ComparedModel>& models,
                                         const ContactComparisonOptions& o) {
  if (cases.empty()) throw InputError("contact comparison: no cases");
  if (models.empty()) throw InputError("contact comparison: no model to compare");
  if (o.map_points > 0 && o.map_case >= cases.size())
    throw InputError("contact comparison: map case index " + std::to_string(o.map_case) + " beyond the " +
                     std::to_string(cases.size()) + " cases");
  contact::TangentialModelOptions ro;
  ro.grid = o.reference_grid;
  ro.tolerance = o.reference_tolerance;
  const auto ref = contact::make_tangential_model("mim", ro);
  const auto ref_ws = ref->make_workspace();

  ContactComparison out;
  spdlog::info("compare-contact: {} cases, reference MIM grid {} (tolerance {:g})", cases.size(), o.reference_grid,
               o.reference_tolerance);
  for (const auto& c : cases) {
    const TimedForces r = reference_solve(*ref, c.input, ref_ws.get(), "case '" + c.id + "'");
    out.reference.push_back(r.forces);
    out.reference_cost_us.push_back(r.time_ns * 1e-3);
  }
  // Median: the first solve on a new grid also sets up the solver.
  std::vector<double> sorted_us = out.reference_cost_us;
  std::sort(sorted_us.begin(), sorted_us.end());
  out.reference_median_cost_us = sorted_us[sorted_us.size() / 2];

  out.stats.resize(models.size());
  out.results.resize(models.size());
  for (std::size_t m = 0; m < models.size(); ++m) {
    spdlog::info("compare-contact: {} ({}/{})", models[m].name, m + 1, models.size());
    for (std::size_t i = 0; i < cases.size(); ++i) {
      const TimedForces r = solve_timed(*models[m].model, cases[i].input, models[m].ws);
      ModelCaseResult row;
      row.forces = r.forces;
      row.error = contact::force_error(r.forces, out.reference[i], cases[i].input);
      row.cost_us = r.time_ns * 1e-3;
      add_case(out.stats[m], row.error, r.forces.valid, row.cost_us);
      out.results[m].push_back(row);
    }
  }
  if (o.map_points > 0) {
    out.has_map = true;
    out.map = failure_map(cases[o.map_case], models, *ref, ref_ws.get(), o, out.stats);
  }
  std::vector<double> cost, err;
  for (const auto& s : out.stats) cost.push_back(s.mean_cost_us()), err.push_back(s.max_F);
  out.pareto_front = results::pareto_front(cost, err);
  return out;
}

}  // namespace railsim::engine
