// The Coulomb bound of the model interface (contact/coulomb_bound.cpp): the
// limit itself, and every registered model at creepages and spin far beyond
// saturation, both signs, every patch shape of the tables.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "contact/coulomb_bound.hpp"
#include "contact/hertz.hpp"
#include "contact/polach.hpp"
#include "contact/registry.hpp"

using namespace railsim::contact;

TEST_CASE("Coulomb bound: limits |F| to mu Fz along its direction, flags a real excess", "[contact][coulomb]") {
  ContactForces f;
  f.Fx = 300.0;
  f.Fy = -400.0;  // |F| = 500
  f.Mz = 2.0;
  CHECK_FALSE(apply_coulomb_bound(f, 600.0));  // within the bound: untouched
  CHECK(f.Fx == 300.0);
  CHECK(f.valid);
  CHECK(apply_coulomb_bound(f, 250.0));  // twice the bound
  CHECK(std::hypot(f.Fx, f.Fy) == Approx(250.0).epsilon(1e-14));
  CHECK(f.Fx / f.Fy == Approx(300.0 / -400.0).epsilon(1e-14));  // direction kept
  CHECK(f.Mz == Approx(1.0).epsilon(1e-14));                     // moment scaled alike
  CHECK_FALSE(f.valid);
  CHECK(std::string(f.reason).find("limited to mu Fz") != std::string::npos);
  // Round-off above the bound (< 0.1 %) is limited silently.
  ContactForces g;
  g.Fx = 1000.5;
  CHECK(apply_coulomb_bound(g, 1000.0));
  CHECK(g.Fx == Approx(1000.0).epsilon(1e-15));
  CHECK(g.valid);
  // A model's own reason is kept.
  ContactForces h;
  h.Fy = 2000.0;
  h.valid = false;
  h.reason = "own reason";
  apply_coulomb_bound(h, 1000.0);
  CHECK(std::string(h.reason) == "own reason");
}

TEST_CASE("Coulomb bound: no registered model exceeds mu Fz far into saturation", "[contact][coulomb]") {
  const Material m{210.0e9, 0.28, 0.3};
  int states = 0, models = 0;
  for (const auto& e : tangential_models()) {
    const std::string name = e.name;
    if (!e.compared_by_default()) continue;  // mim_table: test_reference_set / test_mim_table; coefficients: own test
    if (name != "linear") ++models;
    TangentialModelOptions o;
    if (name == "mim") o.grid = 12;
    const auto model = e.make(o);
    auto ws = model->make_workspace();
    for (const double aob : {0.2, 1.0, 5.0}) {
      ContactInput in;
      in.patch = hertz_from_semi_axes(6e-3 * std::sqrt(aob), 6e-3 / std::sqrt(aob), 60e3, m);
      in.material = m;
      for (const double xi : {-0.05, 0.0, 0.003})
        for (const double eta : {-0.003, 0.0, 0.05})
          for (const double phi : {-20.0, -1.0, 0.0, 3.0}) {
            in.creep = {xi, eta, phi};
            const ContactForces f = model->solve(in, ws.get());
            INFO(name << " a/b " << aob << " creep " << xi << " " << eta << " " << phi << ": |F|/(mu Fz) "
                      << std::hypot(f.Fx, f.Fy) / (m.mu * in.patch.Fz));
            if (name == "linear") continue;  // unsaturated theory by definition (flags |F| > 0.3 mu Fz)
            CHECK(std::hypot(f.Fx, f.Fy) <= m.mu * in.patch.Fz * (1.0 + 1e-12));
            ++states;
          }
    }
  }
  CHECK(models >= 8);
  CHECK(states == models * 3 * 3 * 3 * 4);  // every state of every bounded model was checked
}

TEST_CASE("deep full slip: huge creepages give mu Fz along the creepages' direction, never 0 or NaN", "[contact][coulomb][bad_input]") {
  // Before: |xi| = 1e154 (its square overflows) gave Fx = 0 from every strip
  // model and NaN from Polach, flagged valid (exit 0 from `railsim contact`).
  // Reference: the same creepage direction at size 1e5 (|xi|, |eta|, |phi| c up
  // to 1e5, solved as given: 1e7 times saturation, the force's limit there);
  // sizes 1e10, 1e154, 1e300 must give the same within 1 % of mu Fz.
  const Material m{210.0e9, 0.28, 0.3};
  int checked = 0;
  for (const auto& e : tangential_models()) {
    const std::string name = e.name;
    if (!e.compared_by_default() || name == "linear") continue;
    TangentialModelOptions o;
    if (name == "mim") o.grid = 12;
    const auto model = e.make(o);
    auto ws = model->make_workspace();
    ContactInput in;
    in.patch = hertz_from_semi_axes(6e-3, 4e-3, 60e3, m);
    in.material = m;
    const double c = std::sqrt(in.patch.a * in.patch.b), muN = m.mu * in.patch.Fz;
    for (const double sx : {-1.0, 0.0, 1.0})
      for (const double sy : {-1.0, 0.0, 0.5})
        for (const double sp : {-0.3, 0.0, 1.0}) {
          if (sx == 0.0 && sy == 0.0 && sp == 0.0) continue;
          in.creep = {sx * 1e5, sy * 1e5, sp / c * 1e5};
          const ContactForces ref = model->solve(in, ws.get());
          for (const double size : {1e10, 1e154, 1e300}) {
            in.creep = {sx * size, sy * size, sp / c * size};
            const ContactForces f = model->solve(in, ws.get());
            INFO(name << " direction (" << sx << ", " << sy << ", " << sp << "/c) x " << size << ": F (" << f.Fx << ", "
                      << f.Fy << "), at 1e5: (" << ref.Fx << ", " << ref.Fy << ")");
            REQUIRE(std::isfinite(f.Fx));
            REQUIRE(std::isfinite(f.Fy));
            CHECK(std::hypot(f.Fx, f.Fy) <= muN * (1.0 + 1e-12));
            CHECK(std::hypot(f.Fx - ref.Fx, f.Fy - ref.Fy) <= 0.01 * muN);
            ++checked;
          }
        }
  }
  CHECK(checked >= 8 * 26 * 3);
}

TEST_CASE("Coulomb bound: Polach's own friction law bounds Polach's force", "[contact][coulomb][polach]") {
  // mu(w) = mu0 [(1 - A) exp(-B w) + A]: at slip velocity w the bound is mu(w) Fz.
  const Material m{210.0e9, 0.28, 0.3};
  const auto model = make_polach_model(PolachParameters::dry());
  ContactInput in;
  in.patch = hertz_from_semi_axes(6e-3, 5e-3, 60e3, m);
  in.material = m;
  in.rolling_speed = 30.0;
  in.creep = {0.02, 0.01, 2.0};
  const PolachParameters p = PolachParameters::dry();
  const double w = std::hypot(0.02, 0.01) * 30.0;
  const double mu = p.mu0 * ((1.0 - p.A) * std::exp(-p.B * w) + p.A);
  CHECK(model->friction_coefficient(in) == Approx(mu).epsilon(1e-14));
  const ContactForces f = model->solve(in);
  CHECK(std::hypot(f.Fx, f.Fy) <= mu * in.patch.Fz * (1.0 + 1e-12));
}
