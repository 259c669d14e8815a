// FaStrip-type model (contact/fastrip.cpp): linear-theory slopes on any grid,
// the strip theory's analytic limit, saturation, reduction factors and the
// error against CONTACT's exact creep curves compared with FASTSIM's.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "contact/fastrip.hpp"
#include "contact/fastsim.hpp"
#include "contact/hertz.hpp"
#include "contact/mim/mim_model.hpp"
#include "contact/kalker_coefficients.hpp"
#include "contact/registry.hpp"
#include "core/errors.hpp"
#include "creep_reference.hpp"

using namespace railsim::contact;
using railsim::test::family_error;
using railsim::test::load_circular_creep_curves;

namespace {
ContactInput strip_input(double a, double b, double Fz = 75000.0, double mu = 0.3) {
  ContactInput in;
  in.patch.a = a;
  in.patch.b = b;
  in.patch.Fz = Fz;
  in.material = Material{210.0e9, 0.28, mu};
  return in;
}

// Strip theory for pure creepage integrated in closed form over the strips
// (derivation in fastrip.hpp): with S = |w| / (mu p0) and t = sqrt(1 - Y^2),
// a strip carries mu (pi/2) p0 a (2 S t - S^2) if t > S, else its full
// sliding force mu (pi/2) p0 a t^2; integrated over Y in [-1, 1] and divided
// by mu N = mu (2 pi/3) p0 a b:
//   F / (mu N) = (3/4) [ 2 S (Ys sqrt(1-Ys^2) + asin Ys) - 2 S^2 Ys + 2 (1 - Ys) - (2/3)(1 - Ys^3) ]
// with Ys = sqrt(1 - S^2) (S < 1), and 1 for S >= 1. Written independently of
// the marching code, which must reproduce it on a strip grid.
double strip_theory_force(double S) {
  if (S >= 1.0) return 1.0;
  const double Ys = std::sqrt(1.0 - S * S);
  const double inner = 2.0 * S * (Ys * std::sqrt(1.0 - Ys * Ys) + std::asin(Ys)) - 2.0 * S * S * Ys;
  const double outer = 2.0 * (1.0 - Ys) - (2.0 / 3.0) * (1.0 - Ys * Ys * Ys);
  return 0.75 * (inner + outer);
}
}  // namespace

TEST_CASE("FaStrip keeps the linear-theory slopes exactly on any grid", "[fastrip]") {
  for (const int n : {4, 10, 25}) {
    const Fastrip model({n, n});
    for (const double aob : {0.25, 1.0, 3.0}) {
      const double c = 6.0e-3;
      ContactInput in = strip_input(c * std::sqrt(aob), c / std::sqrt(aob));
      const double G = in.material.shear_modulus();
      const double c2 = in.patch.a * in.patch.b;
      const KalkerCoefficients C = kalker_coefficients(aob, 0.28);
      INFO("grid " << n << ", a/b = " << aob);
      in.creep = {1e-8, 0.0, 0.0};
      CHECK(model.solve(in).Fx == Approx(-G * c2 * C.C11 * 1e-8).epsilon(1e-4));
      in.creep = {0.0, 1e-8, 0.0};
      CHECK(model.solve(in).Fy == Approx(-G * c2 * C.C22 * 1e-8).epsilon(1e-4));
      in.creep = {0.0, 0.0, 1e-6};
      CHECK(model.solve(in).Fy == Approx(-G * c2 * std::sqrt(c2) * C.C23 * 1e-6).epsilon(1e-4));
    }
  }
}

TEST_CASE("FaStrip reproduces the closed-form strip-theory creep curve", "[fastrip]") {
  // Pure longitudinal creepage on a fine strip grid: the marching code with its
  // analytic element integrals must match the closed form above (the only
  // error left is the midpoint rule across strips).
  const Fastrip model({8, 400});
  ContactInput in = strip_input(5e-3, 7e-3, 60000.0, 0.25);
  const double G = in.material.shear_modulus();
  const KalkerCoefficients C = kalker_coefficients(5.0 / 7.0, 0.28);
  const double Kx = std::numbers::pi * std::numbers::pi / (2.0 * G * C.C11);
  const double p0 = 3.0 * 60000.0 / (2.0 * std::numbers::pi * 5e-3 * 7e-3);
  for (const double S : {0.05, 0.2, 0.5, 0.8, 0.99, 1.5}) {
    in.creep = {S * 0.25 * p0 * Kx, 0.0, 0.0};
    INFO("S = " << S);
    CHECK(-model.solve(in).Fx / (0.25 * 60000.0) == Approx(strip_theory_force(S)).epsilon(2e-4));
  }
}

TEST_CASE("FaStrip saturates at mu Fz and scales with the reduction factors", "[fastrip]") {
  const Fastrip model;
  ContactInput in = strip_input(6e-3, 4e-3, 50000.0, 0.35);
  in.creep = {0.3, -0.4, 2.0};
  const ContactForces f = model.solve(in);
  CHECK(std::hypot(f.Fx, f.Fy) <= 0.35 * 50000.0 * (1.0 + 1e-9));
  in.creep = {0.3, -0.4, 0.0};
  const ContactForces g = model.solve(in);
  CHECK(std::hypot(g.Fx, g.Fy) == Approx(0.35 * 50000.0).epsilon(1e-9));
  CHECK(g.stick_fraction == Approx(0.0).margin(1e-12));

  ContactInput r = strip_input(7e-3, 5e-3);
  ContactInput k = r;
  k.reduction = {0.6, 0.45, 0.3};
  r.creep = k.creep = {1e-8, 0.0, 0.0};
  CHECK(model.solve(k).Fx / model.solve(r).Fx == Approx(0.6).epsilon(1e-6));
  r.creep = k.creep = {0.0, 1e-8, 0.0};
  CHECK(model.solve(k).Fy / model.solve(r).Fy == Approx(0.45).epsilon(1e-6));
  r.creep = k.creep = {0.0, 0.0, 1e-6};
  CHECK(model.solve(k).Fy / model.solve(r).Fy == Approx(0.3).epsilon(1e-6));
}

TEST_CASE("FaStrip signs follow the Kalker convention", "[fastrip]") {
  const Fastrip model;
  ContactInput in = strip_input(6e-3, 5e-3);
  in.creep = {2e-3, 0.0, 0.0};
  const ContactForces p = model.solve(in);
  in.creep = {-2e-3, 0.0, 0.0};
  CHECK(p.Fx < 0.0);
  CHECK(model.solve(in).Fx == Approx(-p.Fx).epsilon(1e-12));
  in.creep = {0.0, 1e-4, 0.0};
  const ContactForces lat = model.solve(in);
  CHECK(lat.Fy < 0.0);
  CHECK(lat.Mz > 0.0);
  in.creep = {0.0, 0.0, 0.5};
  const ContactForces spin = model.solve(in);
  CHECK(spin.Fy < 0.0);
  CHECK(spin.Mz < 0.0);
}

TEST_CASE("FaStrip vs FASTSIM against the CONTACT exact creep curves (circular patch)", "[fastrip]") {
  // Measured (max relative error of the driven force over each family):
  //   FaStrip 10x10: long 1.0 %, lat 1.5 %, spin 8.8 %; 20x20: 1.0 %, 1.6 %, 6.3 %
  //   FASTSIM 10x10: long 6.7 %, lat 6.8 %, spin 29 %; 20x20: 5.9 %, 5.9 %, 11.5 %
  // FaStrip is much closer for pure creepage; for pure spin it is FASTSIM-like
  // with the elliptic bound, closer since its per-strip lateral spin
  // flexibility and sliding substeps (fastrip.hpp 4b, 4c; before: 31 %, 12 %).
  // Its eta -> Mz moment is worse near saturation (20 % of max |Mz| vs 13 %).
  const auto cases = load_circular_creep_curves();
  for (const int n : {10, 20}) {
    const Fastrip strip({n, n});
    const Fastsim sim({n, n});
    for (const char* fam : {"long", "lat", "spin"}) {
      const auto es = family_error(strip, cases, fam);
      const auto ef = family_error(sim, cases, fam);
      WARN("fastrip " << n << "x" << n << " " << fam << ": force " << es.force << " (of mu Fz " << es.force_muN
                      << "), Mz " << es.moment << "  | fastsim force " << ef.force << ", Mz " << ef.moment);
      if (std::string(fam) != "spin") {
        CHECK(es.force < 0.03);
        CHECK(es.force < 0.5 * ef.force);
        CHECK(es.moment < 0.25);
      } else if (n == 20) {
        CHECK(es.force < 0.25);
        CHECK(es.force < 1.1 * ef.force);
        CHECK(es.moment < 0.10);
      }
    }
  }
}

TEST_CASE("FaStrip rejects bad input and is registered as fastrip", "[fastrip][input][registry]") {
  const Fastrip model;
  ContactInput in = strip_input(6e-3, 5e-3);
  ContactInput bad = in;
  bad.patch.b = 0.0;
  CHECK_THROWS_AS(model.solve(bad), railsim::InputError);
  bad = in;
  bad.creep.phi = INFINITY;
  CHECK_THROWS_AS(model.solve(bad), railsim::InputError);
  in.patch.Fz = -5.0;  // lost contact
  CHECK(model.solve(in).Fx == 0.0);
  auto m = make_tangential_model("fastrip");
  CHECK(m->name() == "fastrip");
  TangentialModelOptions o;
  o.grid = 0;
  CHECK(dynamic_cast<const Fastrip&>(*make_tangential_model("fastrip", o)).options().nx == 20);
  o.grid = -3;
  CHECK_THROWS_AS(make_tangential_model("fastrip", o), railsim::InputError);
}

TEST_CASE("FaStrip and FASTSIM with creepage combined with spin against the live MIM solver", "[fastrip]") {
  // Creepage combined with spin, with every sign image of each case:
  // (xi, eta, phi), its mirror (xi, -eta, -phi) (exactly the same errors) and
  // the opposing images (xi, eta, -phi), (xi, -eta, phi), where lateral
  // creepage works against spin. Reference: the exact MIM solver, 30 elements
  // across the patch. Error |dF| / |F_MIM|, measured (fastsim = blended):
  //   case                        same sign            opposing
  //   xi 1e-3, phi 1 1/m          fs 6.3 %, fr 3.7 %   (the same: Fx unchanged, Fy mirrored)
  //   xi 2e-3, eta 1e-3, phi 1.5  fs 5.7 %, fr 3.0 %   fs 5.9 %, fr 7.2 %
  //   eta 1e-3, phi 1             fs 6.5 %, fr 1.9 %   fs 3.4 %, fr 4.4 %
  //   eta 0.01, phi 1             fs 0.30 %, fr 0.48 % fs 1.8 %, fr 4.2 %  (issue 15: fastrip had 79 %)
  // (fastrip before fastrip.hpp steps 4b and 4c: 2.9; 3.4, 7.5; 1.2, 3.1; 0.31, 4.5 %.)
  // Issue 5 acceptance: fastrip closer than fastsim with creepage and spin of
  // the same sign; with opposing signs FaStrip is not closer point by point
  // (its largest error over the reference set is, test_reference_set.cpp).
  railsim::contact::mim::MimOptions o;
  o.grid = 30;
  o.tolerance = 1e-6;
  railsim::contact::mim::MimSolver mim(o);
  const Material m{210.0e9, 0.28, 0.3};
  const HertzPatch p = hertz_from_semi_axes(6e-3, 6e-3, 75e3, m);
  const Fastsim fs;
  const Fastrip fr;
  for (const Creepages& c0 : {Creepages{1e-3, 0.0, 1.0}, Creepages{2e-3, 1e-3, 1.5}, Creepages{0.0, 1e-3, 1.0},
                              Creepages{0.0, 0.01, 1.0}}) {
    for (const auto& [se, sp] : {std::pair{1.0, 1.0}, std::pair{-1.0, -1.0}, std::pair{1.0, -1.0}, std::pair{-1.0, 1.0}}) {
      const Creepages c{c0.xi, se * c0.eta, sp * c0.phi};
      const auto& r = mim.solve_hertz(p, c, m);
      ContactInput in;
      in.patch = p;
      in.material = m;
      in.creep = c;
      const ContactForces a = fs.solve(in), b = fr.solve(in);
      const double F = std::hypot(r.Fx, r.Fy);
      const double ea = std::hypot(a.Fx - r.Fx, a.Fy - r.Fy) / F, eb = std::hypot(b.Fx - r.Fx, b.Fy - r.Fy) / F;
      WARN("xi " << c.xi << " eta " << c.eta << " phi " << c.phi << ": fastsim " << ea << ", fastrip " << eb);
      const bool same_sign = c.eta * c.phi >= 0.0;
      CHECK(ea < 0.08);
      // The cases of issue 5 (same sign, small creepage) keep their bound of 6 %.
      CHECK(eb < ((same_sign && c0.eta < 0.005) ? 0.06 : 0.08));
      if (same_sign && c0.eta < 0.005) CHECK(eb < ea);
    }
  }
}

TEST_CASE("FaStrip in saturated combined creepage: the force turns to the creepage direction as the exact theory's",
          "[fastrip][saturation]") {
  // Combined longitudinal and lateral creepage at 1, 2, 5 and 30 times the
  // saturation creepage (|(xi, eta)| against |(xi*, eta*)|, xi* = mu Fz /
  // (G c^2 C11)), every sign quadrant, patches a/b 0.2 - 5; reference: the
  // live MIM (grid 40, extrapolated). In full slip the exact force lies along
  // the creepage; Carter's strip solution alone puts it along (xi / Kx,
  // eta / Ky), the linear theory's direction, 7 degrees off on a/b 0.33
  // (12 % of mu Fz). Blending the compliances toward one (fastrip.hpp, step
  // 2b) turns it. Measured: fastrip max 2.4 % of mu Fz over these states
  // (before the blend 13.9 %), fastsim (blended) 4.9 %, fastsim_kalker 13.9 %.
  railsim::contact::mim::MimOptions o;
  o.grid = 40;
  railsim::contact::mim::MimSolver mim(o);
  const Material m{210.0e9, 0.28, 0.3};
  const Fastrip fr;
  const auto kalker = make_tangential_model("fastsim_kalker");
  const auto blended = make_tangential_model("fastsim");
  double worst = 0.0, worst_kalker = 0.0, worst_blended = 0.0;
  for (const double aob : {0.2, 0.33, 1.0, 3.0, 5.0}) {
    const double c = 6.0e-3;
    const HertzPatch p = hertz_from_semi_axes(c * std::sqrt(aob), c / std::sqrt(aob), 75e3, m);
    const KalkerCoefficients C = kalker_coefficients(aob, m.nu);
    const double G = m.shear_modulus(), c2 = p.a * p.b;
    const double xs = m.mu * p.Fz / (G * c2 * C.C11), es = m.mu * p.Fz / (G * c2 * C.C22);
    for (const double level : {1.0, 2.0, 5.0, 30.0})
      for (const auto& [sx, sy] : {std::pair{1.0, 1.0}, std::pair{1.0, -1.0}, std::pair{-1.0, 1.0}, std::pair{-1.0, -1.0}}) {
        // Equal longitudinal and lateral creepage, |(xi, eta)| = level |(xi*, eta*)|.
        const double s = level * std::hypot(xs, es) / std::sqrt(2.0);
        const Creepages cr{sx * s, sy * s, 0.0};
        const auto& r = mim.solve_hertz(p, cr, m);
        ContactInput in;
        in.patch = p;
        in.material = m;
        in.creep = cr;
        const ContactForces b = fr.solve(in), k = kalker->solve(in);
        const double muN = m.mu * p.Fz;
        const double e = std::hypot(b.Fx - r.Fx, b.Fy - r.Fy) / muN;
        const double ek = std::hypot(k.Fx - r.Fx, k.Fy - r.Fy) / muN;
        INFO("a/b " << aob << ", level " << level << ", xi " << cr.xi << ", eta " << cr.eta << ": fastrip " << e
                    << ", fastsim_kalker " << ek);
        CHECK(e < 0.03);
        worst = std::max(worst, e);
        worst_kalker = std::max(worst_kalker, ek);
        const ContactForces fb = blended->solve(in);
        worst_blended = std::max(worst_blended, std::hypot(fb.Fx - r.Fx, fb.Fy - r.Fy) / muN);
        if (level >= 5.0) {  // deep in full slip: along the creepage, within a quarter degree
          const double angle = std::atan2(b.Fy, b.Fx) - std::atan2(-cr.eta, -cr.xi);
          CHECK(std::abs(std::remainder(angle, 2.0 * std::numbers::pi)) < 0.25 * std::numbers::pi / 180.0);
        }
      }
  }
  WARN("saturated combined creepage: fastrip max " << 100 * worst << " % of mu Fz, fastsim_kalker "
                                                   << 100 * worst_kalker << " %, fastsim " << 100 * worst_blended
                                                   << " %");
  CHECK(worst_kalker > 0.05);  // the skew this test is about
}
