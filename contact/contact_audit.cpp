// Contact audit of a list of contact states; see contact_audit.hpp.
#include "contact/contact_audit.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <mutex>
#include <string>
#include <thread>

#include "contact/registry.hpp"
#include "core/errors.hpp"

namespace railsim::contact {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double ns_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count();
}

// Cost of one call [ns]: the mean over repeated calls until 20 us have passed
// (at most 64 calls; a slow model is timed once).
double time_call(const TangentialModel& model, const ContactInput& in, TangentialWorkspace* ws) {
  const auto t0 = std::chrono::steady_clock::now();
  int calls = 0;
  double ns = 0.0;
  double sink = 0.0;
  do {
    sink += model.solve(in, ws).Fx;
    ++calls;
    ns = ns_since(t0);
  } while (ns < 2e4 && calls < 64);
  volatile double keep = sink;  // the calls are not optimised away
  (void)keep;
  return ns / calls;
}

// Statistics of one model's error row (errors[s] for audited states).
ModelAudit statistics(const std::string& name, const std::vector<double>& errors, const std::vector<bool>& audited,
                      const std::vector<ContactForces>& forces, const std::vector<double>& cost, bool cost_measured,
                      double tolerance) {
  ModelAudit a;
  a.model = name;
  std::vector<double> errs, costs;
  double ns = 0.0;
  for (std::size_t s = 0; s < errors.size(); ++s) {
    if (!audited[s]) continue;
    const double e = errors[s];
    if (std::isinf(e)) ++a.failed;
    else {
      if (!forces[s].valid) ++a.flagged_invalid;
      ns += cost[s];
      costs.push_back(cost[s]);
    }
    if (errs.empty() || e > a.max_error) {
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
    a.mean_cost_ns = !cost_measured ? kNaN : solved > 0 ? ns / static_cast<double>(solved) : 0.0;
    a.median_cost_ns = 0.0;
    if (!cost_measured) a.median_cost_ns = kNaN;
    else if (!costs.empty()) {
      std::sort(costs.begin(), costs.end());
      const std::size_t h = costs.size() / 2;
      a.median_cost_ns = costs.size() % 2 ? costs[h] : 0.5 * (costs[h - 1] + costs[h]);
    }
  }
  a.meets_tolerance = !errs.empty() && a.failed == 0 && a.max_error <= tolerance;
  return a;
}
}  // namespace

std::vector<std::string> ContactAuditResult::meeting_tolerance() const {
  std::vector<const ModelAudit*> ok;
  for (const auto& m : models)
    if (m.meets_tolerance) ok.push_back(&m);
  // Unmeasured costs (NaN) last.
  const auto key = [](const ModelAudit* m) {
    return std::isnan(m->median_cost_ns) ? std::numeric_limits<double>::infinity() : m->median_cost_ns;
  };
  std::stable_sort(ok.begin(), ok.end(), [&](const ModelAudit* a, const ModelAudit* b) { return key(a) < key(b); });
  std::vector<std::string> names;
  for (const auto* m : ok) names.push_back(m->model);
  return names;
}

int ContactAuditResult::find(const std::string& model) const {
  for (std::size_t m = 0; m < models.size(); ++m)
    if (models[m].model == model) return static_cast<int>(m);
  return -1;
}

ContactAuditResult audit_contacts(const std::vector<ContactInput>& states, const ContactAuditOptions& o) {
  if (states.empty()) throw InputError("contact audit: no contact states given (need at least one)");
  if (o.mim_grid < 8 || o.mim_grid > 400)
    throw InputError("contact audit: mim_grid " + std::to_string(o.mim_grid) + " outside [8, 400]");
  if (!(o.mim_tolerance > 0.0 && o.mim_tolerance <= 1e-2))
    throw InputError("contact audit: mim_tolerance must lie in (0, 1e-2]");
  if (!(o.tolerance > 0.0 && o.tolerance <= 1.0)) throw InputError("contact audit: tolerance must lie in (0, 1]");
  if (o.threads < 1 || o.threads > 64)
    throw InputError("contact audit: threads " + std::to_string(o.threads) + " outside [1, 64]");

  std::vector<std::string> names = o.models;
  if (names.empty())
    for (const auto& e : tangential_models())
      if (e.compared_by_default()) names.emplace_back(e.name);
  // Build every model first: an unknown name fails before any solve.
  std::vector<std::unique_ptr<TangentialModel>> models;
  for (const auto& n : names) {
    TangentialModelOptions mo;
    mo.cache_dir = o.cache_dir;
    mo.saturation = o.saturation;
    models.push_back(make_tangential_model(n, mo));
  }
  const auto mim = make_tangential_model("mim", {o.mim_grid, o.mim_tolerance, ""});

  const std::size_t S = states.size(), M = models.size();
  ContactAuditResult r;
  r.tolerance = o.tolerance;
  r.mim_grid = o.mim_grid;
  r.reference.assign(S, ContactForces{});
  r.reference_cost_ns.assign(S, kNaN);
  r.audited.assign(S, false);
  r.errors.assign(M, std::vector<double>(S, kNaN));
  r.forces.assign(M, std::vector<ContactForces>(S, ContactForces{}));
  r.cost_ns.assign(M, std::vector<double>(S, kNaN));
  std::vector<char> audited(S, 0);  // written by the workers (std::vector<bool> is not thread-safe per element)

  // Workers take states in turn; each solves its state with MIM and every model.
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  const auto work = [&] {
    auto mim_ws = mim->make_workspace();
    std::vector<std::unique_ptr<TangentialWorkspace>> ws;
    for (const auto& m : models) ws.push_back(m->make_workspace());
    for (std::size_t s = next++; s < S; s = next++) {
      if (o.stop.requested()) {
        const std::lock_guard<std::mutex> lock(failure_mutex);
        if (!failure)
          failure = std::make_exception_ptr(InterruptedError("contact audit interrupted before state " +
                                                             std::to_string(s + 1) + " of " + std::to_string(S)));
        next = S;
        return;
      }
      const ContactInput& in = states[s];
      if (!(in.patch.Fz > 0.0 && in.patch.a > 0.0 && in.patch.b > 0.0)) continue;  // no load or no patch
      try {
        const auto t0 = std::chrono::steady_clock::now();
        r.reference[s] = mim->solve(in, mim_ws.get());
        r.reference_cost_ns[s] = ns_since(t0);  // one call: the reference is slow enough
      } catch (const NumericalError& e) {
        const std::lock_guard<std::mutex> lock(failure_mutex);
        if (!failure)
          failure = std::make_exception_ptr(NumericalError("contact audit: the MIM reference failed on state " +
                                                           std::to_string(s) + ": " + e.what()));
        next = S;
        return;
      }
      audited[s] = 1;
      const ContactForces& ref = r.reference[s];
      const double muN = in.material.mu * in.patch.Fz;
      for (std::size_t m = 0; m < M; ++m) {
        double e = std::numeric_limits<double>::infinity();
        try {
          const ContactForces f = models[m]->solve(in, ws[m].get());
          r.cost_ns[m][s] = time_call(*models[m], in, ws[m].get());
          r.forces[m][s] = f;
          e = std::hypot(f.Fx - ref.Fx, f.Fy - ref.Fy) / muN;
        } catch (const NumericalError&) {
        }
        r.errors[m][s] = e;
      }
    }
  };
  const int nt = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(o.threads), S));
  if (nt <= 1) work();
  else {
    std::vector<std::thread> pool;
    for (int t = 0; t < nt; ++t) pool.emplace_back(work);
    for (auto& t : pool) t.join();
  }
  if (failure) std::rethrow_exception(failure);
  for (std::size_t s = 0; s < S; ++s) r.audited[s] = audited[s] != 0;
  for (std::size_t m = 0; m < M; ++m)
    r.models.push_back(statistics(names[m], r.errors[m], r.audited, r.forces[m], r.cost_ns[m], true, o.tolerance));
  return r;
}

void audit_given_forces(ContactAuditResult& r, const std::string& name, const std::vector<ContactInput>& states,
                        const std::vector<ContactForces>& forces) {
  if (states.size() != r.audited.size() || forces.size() != states.size())
    throw InputError("contact audit: " + std::to_string(forces.size()) + " given forces for " +
                     std::to_string(r.audited.size()) + " audited states");
  if (r.find(name) >= 0) throw InputError("contact audit: model '" + name + "' is already audited");
  std::vector<double> e(states.size(), kNaN), cost(states.size(), kNaN);
  for (std::size_t s = 0; s < states.size(); ++s)
    if (r.audited[s])
      e[s] = std::hypot(forces[s].Fx - r.reference[s].Fx, forces[s].Fy - r.reference[s].Fy) /
             (states[s].material.mu * states[s].patch.Fz);
  r.models.push_back(statistics(name, e, r.audited, forces, cost, false, r.tolerance));
  r.errors.push_back(e);
  r.forces.push_back(forces);
  r.cost_ns.push_back(cost);
}

std::string cheapest_within(const ContactAuditResult& r, double tolerance) {
  const ModelAudit* best = nullptr;
  const auto key = [](const ModelAudit& m) {
    return std::isnan(m.median_cost_ns) ? std::numeric_limits<double>::infinity() : m.median_cost_ns;
  };
  for (const auto& m : r.models)
    if (m.failed == 0 && m.max_error <= tolerance && (!best || key(m) < key(*best))) best = &m;
  return best ? best->model : std::string();
}

AuditVerdict audit_verdict(const ContactAuditResult& r, const std::string& run_model) {
  AuditVerdict v;
  v.run_model = run_model;
  v.run_index = r.find(run_model);
  if (v.run_index < 0) throw InputError("contact audit: the run's model '" + run_model + "' was not audited");
  const ModelAudit& run = r.models[static_cast<std::size_t>(v.run_index)];
  v.run_meets = run.meets_tolerance;
  const auto ok = r.meeting_tolerance();
  if (!ok.empty()) v.cheapest_meeting = ok.front();
  for (const auto& n : ok) {
    const ModelAudit& m = r.models[static_cast<std::size_t>(r.find(n))];
    if (n != run_model && m.median_cost_ns < run.median_cost_ns) v.cheaper_meeting.push_back(n);  // NaN: never
  }
  const ModelAudit* best = nullptr;
  for (const auto& m : r.models)
    if (!best || m.max_error < best->max_error ||
        (m.max_error == best->max_error && m.median_cost_ns < best->median_cost_ns))
      best = &m;
  if (best) v.most_accurate = best->model;
  return v;
}

}  // namespace railsim::contact
