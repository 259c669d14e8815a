// Contact audit of a list of contact states; see contact_audit.hpp.
#include "contact/contact_audit.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>

#include "contact/registry.hpp"
#include "core/errors.hpp"

namespace railsim::contact {

std::vector<std::string> ContactAuditResult::meeting_tolerance() const {
  std::vector<const ModelAudit*> ok;
  for (const auto& m : models)
    if (m.meets_tolerance) ok.push_back(&m);
  std::stable_sort(ok.begin(), ok.end(),
                   [](const ModelAudit* a, const ModelAudit* b) { return a->mean_cost_ns < b->mean_cost_ns; });
  std::vector<std::string> names;
  for (const auto* m : ok) names.push_back(m->model);
  return names;
}

ContactAuditResult audit_contacts(const std::vector<ContactInput>& states, const ContactAuditOptions& o) {
  if (states.empty()) throw InputError("contact audit: no contact states given (need at least one)");
  if (o.mim_grid < 8 || o.mim_grid > 400)
    throw InputError("contact audit: mim_grid " + std::to_string(o.mim_grid) + " outside [8, 400]");
  if (!(o.mim_tolerance > 0.0 && o.mim_tolerance <= 1e-2))
    throw InputError("contact audit: mim_tolerance must lie in (0, 1e-2]");
  if (!(o.tolerance > 0.0 && o.tolerance <= 1.0)) throw InputError("contact audit: tolerance must lie in (0, 1]");

  std::vector<std::string> names = o.models;
  if (names.empty())
    for (const auto& e : tangential_models())
      if (!e.tabulated) names.emplace_back(e.name);
  // Build every model first: an unknown name fails before any solve.
  std::vector<std::unique_ptr<TangentialModel>> models;
  for (const auto& n : names) {
    TangentialModelOptions mo;
    mo.cache_dir = o.cache_dir;
    models.push_back(make_tangential_model(n, mo));
  }
  const auto mim = make_tangential_model("mim", {o.mim_grid, o.mim_tolerance, ""});
  auto mim_ws = mim->make_workspace();

  ContactAuditResult r;
  r.tolerance = o.tolerance;
  r.reference.resize(states.size());
  r.audited.assign(states.size(), false);
  for (std::size_t s = 0; s < states.size(); ++s) {
    if (!(states[s].patch.Fz > 0.0)) continue;
    try {
      r.reference[s] = mim->solve(states[s], mim_ws.get());
    } catch (const NumericalError& e) {
      throw NumericalError("contact audit: the MIM reference failed on state " + std::to_string(s) + ": " + e.what());
    }
    r.audited[s] = true;
  }

  const double nan = std::numeric_limits<double>::quiet_NaN();
  r.errors.assign(models.size(), std::vector<double>(states.size(), nan));
  for (std::size_t m = 0; m < models.size(); ++m) {
    ModelAudit a;
    a.model = names[m];
    auto ws = models[m]->make_workspace();
    std::vector<double> errs;
    double ns = 0.0;
    for (std::size_t s = 0; s < states.size(); ++s) {
      if (!r.audited[s]) continue;
      const ContactInput& in = states[s];
      double e = std::numeric_limits<double>::infinity();
      try {
        const auto t0 = std::chrono::steady_clock::now();
        const ContactForces f = models[m]->solve(in, ws.get());
        ns += std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count();
        if (!f.valid) ++a.flagged_invalid;
        const ContactForces& ref = r.reference[s];
        e = std::hypot(f.Fx - ref.Fx, f.Fy - ref.Fy) / (in.material.mu * in.patch.Fz);
      } catch (const NumericalError&) {
        ++a.failed;
      }
      r.errors[m][s] = e;
      if (e > a.max_error || errs.empty()) {
        a.max_error = e;
        a.worst_state = s;
      }
      errs.push_back(e);
    }
    if (!errs.empty()) {
      double sum = 0.0;
      for (const double e : errs) sum += e;
      a.mean_error = sum / static_cast<double>(errs.size());
      std::vector<double> sorted = errs;
      std::sort(sorted.begin(), sorted.end());
      // Nearest-rank 95th percentile.
      const auto k = static_cast<std::size_t>(std::ceil(0.95 * static_cast<double>(sorted.size()))) - 1;
      a.p95_error = sorted[std::min(k, sorted.size() - 1)];
      const std::size_t solved = errs.size() - static_cast<std::size_t>(a.failed);
      a.mean_cost_ns = solved > 0 ? ns / static_cast<double>(solved) : 0.0;
    }
    a.meets_tolerance = !errs.empty() && a.failed == 0 && a.max_error <= o.tolerance;
    r.models.push_back(a);
  }
  return r;
}

}  // namespace railsim::contact
