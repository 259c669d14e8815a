// The contact audit (contact/contact_audit.hpp) on states of railsim's exact
// reference set (tests/data/contact/spin_reference): its MIM reference is the
// grid-60 solution of that set, its statistics are those of its own error
// table, and which models meet a tolerance follows from their measured errors
// (fastrip within 10.3 % of mu Fz on the whole set; the saturation laws with
// spin 61 - 94 % off).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include "contact/contact_audit.hpp"
#include "contact/registry.hpp"
#include "core/errors.hpp"
#include "reference_set.hpp"

using namespace railsim::contact;
using railsim::test::load_reference_set;
using railsim::test::ReferenceState;

namespace {
// Every 25th state of the set (31 states: all families, patches and signs).
std::vector<ReferenceState> sample() {
  const auto all = railsim::test::extrapolated_reference_set("mim_grid60.csv", "mim_grid30.csv");
  std::vector<ReferenceState> v;
  for (std::size_t i = 0; i < all.size(); i += 25) v.push_back(all[i]);
  return v;
}
}  // namespace

TEST_CASE("contact audit: MIM reference, error statistics and models meeting a tolerance", "[contact][audit]") {
  const auto set = sample();
  std::vector<ContactInput> states;
  for (const auto& s : set) states.push_back(s.in);
  ContactInput unloaded = states[0];
  unloaded.patch.Fz = 0.0;  // a lost contact: skipped
  states.push_back(unloaded);

  ContactAuditOptions o;
  o.mim_grid = 60;
  o.mim_tolerance = 1e-8;
  o.tolerance = 0.12;
  o.models = {"chopaya", "fastsim", "fastrip"};
  const ContactAuditResult r = audit_contacts(states, o);
  REQUIRE(r.models.size() == 3);
  REQUIRE(r.reference.size() == states.size());
  CHECK_FALSE(r.audited.back());
  CHECK(std::isnan(r.errors[0].back()));

  // The reference is the exact solution at grid 60 (the registered mim:
  // extrapolated from the set's mim_grid60.csv and mim_grid30.csv).
  for (std::size_t s = 0; s < set.size(); ++s) {
    INFO(set[s].id);
    CHECK(r.audited[s]);
    CHECK(std::abs(r.reference[s].Fx - set[s].Fx) <= 1e-6 * set[s].muN());
    CHECK(std::abs(r.reference[s].Fy - set[s].Fy) <= 1e-6 * set[s].muN());
  }
  for (std::size_t m = 0; m < r.models.size(); ++m) {
    const ModelAudit& a = r.models[m];
    WARN(a.model << ": max " << 100 * a.max_error << " %, mean " << 100 * a.mean_error << " %, p95 "
                 << 100 * a.p95_error << " % of mu Fz, " << a.flagged_invalid << " flagged, " << a.mean_cost_ns
                 << " ns per call");
    // Statistics are those of the error table.
    double mx = 0.0, sum = 0.0;
    std::size_t worst = 0;
    std::vector<double> e;
    for (std::size_t s = 0; s < set.size(); ++s) {
      // Each error is |F - F_MIM| / (mu Fz) of the model's own solve.
      const auto model = make_tangential_model(a.model);
      const ContactForces f = model->solve(set[s].in, model->make_workspace().get());
      const double expect = std::hypot(f.Fx - set[s].Fx, f.Fy - set[s].Fy) / set[s].muN();
      CHECK(r.errors[m][s] == Approx(expect).margin(1e-5));
      if (r.errors[m][s] > mx) {
        mx = r.errors[m][s];
        worst = s;
      }
      sum += r.errors[m][s];
      e.push_back(r.errors[m][s]);
    }
    std::sort(e.begin(), e.end());
    CHECK(a.max_error == mx);
    CHECK(a.worst_state == worst);
    CHECK(a.mean_error == Approx(sum / set.size()).epsilon(1e-12));
    CHECK(a.p95_error == e[static_cast<std::size_t>(std::ceil(0.95 * e.size())) - 1]);
    CHECK(a.p95_error <= a.max_error);
    CHECK(a.failed == 0);
    CHECK(a.mean_cost_ns > 0.0);
    CHECK(a.meets_tolerance == (a.max_error <= 0.12));
  }
  // FaStrip meets 12 % of mu Fz here (10.3 % on the whole set); CHOPAYA, whose
  // |Fy| does not fall with spin, does not, and says so on the spin states.
  CHECK(r.models[2].meets_tolerance);
  CHECK(r.models[2].max_error < 0.105);
  CHECK_FALSE(r.models[0].meets_tolerance);
  CHECK(r.models[0].max_error > 0.5);
  CHECK(r.models[0].flagged_invalid > 0);
  const auto ok = r.meeting_tolerance();
  CHECK(std::find(ok.begin(), ok.end(), "fastrip") != ok.end());
  CHECK(std::find(ok.begin(), ok.end(), "chopaya") == ok.end());
}

TEST_CASE("contact audit: every registered model by default, bad input named", "[contact][audit][input]") {
  const auto set = sample();
  const std::vector<ContactInput> one{set[3].in};
  ContactAuditOptions o;
  o.mim_grid = 16;
  const auto r = audit_contacts(one, o);
  std::size_t expected = 0;
  for (const auto& e : tangential_models()) expected += e.compared_by_default() ? 1 : 0;
  CHECK(r.models.size() == expected);
  CHECK_THROWS_AS(audit_contacts({}, o), railsim::InputError);
  ContactAuditOptions bad = o;
  bad.models = {"fastrip", "no_such_model"};
  CHECK_THROWS_WITH(audit_contacts(one, bad), Catch::Contains("no_such_model"));
  bad = o;
  bad.tolerance = 0.0;
  CHECK_THROWS_WITH(audit_contacts(one, bad), Catch::Contains("tolerance"));
  bad = o;
  bad.mim_grid = 4;
  CHECK_THROWS_WITH(audit_contacts(one, bad), Catch::Contains("[8, 400]"));
}

TEST_CASE("contact audit: threads, given forces, and the verdict read from the table", "[contact][audit]") {
  const auto set = sample();
  std::vector<ContactInput> states;
  for (const auto& s : set) states.push_back(s.in);
  ContactAuditOptions o;
  o.mim_grid = 20;
  o.tolerance = 0.12;
  o.models = {"linear_sat", "chopaya", "fastsim", "fastrip", "polach"};
  const ContactAuditResult one = audit_contacts(states, o);
  o.threads = 2;
  const ContactAuditResult two = audit_contacts(states, o);
  for (std::size_t s = 0; s < states.size(); ++s) {
    CHECK(two.reference[s].Fx == one.reference[s].Fx);
    CHECK(two.reference[s].Fy == one.reference[s].Fy);
    for (std::size_t m = 0; m < one.models.size(); ++m) CHECK(two.errors[m][s] == one.errors[m][s]);
  }

  // Forces given from elsewhere: the reference itself has no error; a model's own forces its statistics.
  ContactAuditResult r = one;
  audit_given_forces(r, "reference", states, r.reference);
  const ModelAudit& ref = r.models.back();
  CHECK(ref.max_error == 0.0);
  CHECK(std::isnan(ref.mean_cost_ns));
  CHECK(std::isnan(ref.median_cost_ns));
  for (const auto& m : one.models) {  // the median of the per-state costs
    std::vector<double> c = one.cost_ns[static_cast<std::size_t>(one.find(m.model))];
    std::sort(c.begin(), c.end());
    const std::size_t h = c.size() / 2;
    CHECK(m.median_cost_ns == (c.size() % 2 ? c[h] : 0.5 * (c[h - 1] + c[h])));
  }
  CHECK(ref.meets_tolerance);
  audit_given_forces(r, "fastrip (given)", states, r.forces[3]);
  CHECK(r.models.back().max_error == r.models[3].max_error);
  CHECK(r.models.back().p95_error == r.models[3].p95_error);
  CHECK(r.models.back().worst_state == r.models[3].worst_state);
  CHECK(r.models.back().flagged_invalid == r.models[3].flagged_invalid);
  CHECK_THROWS_AS(audit_given_forces(r, "fastrip", states, r.reference), railsim::InputError);
  CHECK_THROWS_AS(audit_given_forces(r, "short", {states[0]}, {r.reference[0]}), railsim::InputError);

  // The verdict follows from the table: recompute it from the errors and costs.
  for (const auto& run : {"chopaya", "fastrip", "polach", "reference"}) {
    INFO(run);
    const AuditVerdict v = audit_verdict(r, run);
    const ModelAudit& rm = r.models[static_cast<std::size_t>(r.find(run))];
    std::string cheapest, best;
    double cheapest_cost = INFINITY, best_error = INFINITY;
    std::vector<std::string> cheaper;
    for (std::size_t m = 0; m < r.models.size(); ++m) {
      double mx = 0.0;
      for (double e : r.errors[m]) mx = std::max(mx, e);
      const bool meets = mx <= o.tolerance;
      CHECK(r.models[m].meets_tolerance == meets);
      const double cost = std::isnan(r.models[m].median_cost_ns) ? INFINITY : r.models[m].median_cost_ns;
      if (meets && (cheapest.empty() || cost < cheapest_cost)) cheapest = r.models[m].model, cheapest_cost = cost;
      if (meets && r.models[m].model != run && r.models[m].median_cost_ns < rm.median_cost_ns)
        cheaper.push_back(r.models[m].model);
      if (mx < best_error) best_error = mx, best = r.models[m].model;
    }
    CHECK(v.run_meets == rm.meets_tolerance);
    CHECK(v.cheapest_meeting == cheapest);
    CHECK(cheapest_within(r, o.tolerance) == cheapest);
    CHECK(v.most_accurate == best);
    std::vector<std::string> got = v.cheaper_meeting;
    std::sort(got.begin(), got.end());
    std::sort(cheaper.begin(), cheaper.end());
    CHECK(got == cheaper);
  }
  // The given reference (no cost measured) is the most accurate, never "cheaper"; FaStrip meets 12 % here,
  // CHOPAYA does not (spin states of the set).
  CHECK(audit_verdict(r, "chopaya").most_accurate == "reference");
  CHECK_FALSE(audit_verdict(r, "chopaya").run_meets);
  CHECK(audit_verdict(r, "fastrip").run_meets);
  CHECK_THROWS_WITH(audit_verdict(r, "no_such_model"), Catch::Contains("no_such_model"));
}

TEST_CASE("contact audit: verdict edge cases on a hand-made table", "[contact][audit]") {
  ContactAuditResult r;
  r.tolerance = 0.02;
  const auto entry = [](const char* name, double mx, double cost, bool meets) {
    ModelAudit a;
    a.model = name;
    a.max_error = mx;
    a.median_cost_ns = a.mean_cost_ns = cost;
    a.meets_tolerance = meets;
    return a;
  };
  r.models = {entry("slow_exact", 0.001, 5e6, true), entry("fast_ok", 0.015, 400, true),
              entry("cheap_bad", 0.30, 80, false), entry("as_run", 0.019, std::nan(""), true),
              entry("fast_ok_too", 0.015, 400, true)};
  CHECK(r.meeting_tolerance() == std::vector<std::string>{"fast_ok", "fast_ok_too", "slow_exact", "as_run"});
  AuditVerdict v = audit_verdict(r, "cheap_bad");
  CHECK_FALSE(v.run_meets);
  CHECK(v.cheapest_meeting == "fast_ok");
  CHECK(v.cheaper_meeting.empty());  // nothing meeting it is cheaper than 80 ns
  CHECK(v.most_accurate == "slow_exact");
  v = audit_verdict(r, "slow_exact");
  CHECK(v.run_meets);
  CHECK(v.cheaper_meeting == std::vector<std::string>{"fast_ok", "fast_ok_too"});  // as_run: cost unknown
  v = audit_verdict(r, "as_run");
  CHECK(v.cheaper_meeting.empty());  // its own cost is unknown: nothing is known to be cheaper
  CHECK(v.cheapest_meeting == "fast_ok");
  r.models[0].meets_tolerance = r.models[1].meets_tolerance = r.models[3].meets_tolerance =
      r.models[4].meets_tolerance = false;
  CHECK(audit_verdict(r, "cheap_bad").cheapest_meeting.empty());
  // Other tolerances read from the same table (max error and cost only).
  CHECK(cheapest_within(r, 0.5) == "cheap_bad");
  CHECK(cheapest_within(r, 0.016) == "fast_ok");
  CHECK(cheapest_within(r, 0.005) == "slow_exact");
  CHECK(cheapest_within(r, 0.0005).empty());
  r.models[2].failed = 1;
  CHECK(cheapest_within(r, 0.5) == "fast_ok");
}
