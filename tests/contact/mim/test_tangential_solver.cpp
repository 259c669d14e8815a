// Tests of contact/mim/tangential_solver.cpp through the MimSolver facade:
// Cattaneo-Mindlin shift, Kalker's linear theory (C11, C22, C23), CONTACT's
// exact creep-force curves, full slip and large spin, non-convergence report.
#include <catch2/catch.hpp>

#include <cmath>
#include <initializer_list>
#include <numbers>
#include <string>
#include <tuple>
#include <vector>

#include "contact/kalker_coefficients.hpp"
#include "contact/mim/mim_model.hpp"
#include "core/errors.hpp"
#include "results/csv_writer.hpp"
#include "test_support.hpp"

using namespace railsim::contact;
using namespace railsim::contact::mim;

namespace {

Material steel(double mu) { return Material{210e9, 0.28, mu}; }

// Hertzian patch of a reference case (mm -> m).
HertzPatch patch_of(const railsim::results::CsvTable& t, std::size_t row) {
  HertzPatch p;
  p.A = t.number(row, "A1_per_mm") * 1e3;
  p.B = t.number(row, "B1_per_mm") * 1e3;
  p.a = t.number(row, "a_mm") * 1e-3;
  p.b = t.number(row, "b_mm") * 1e-3;
  p.Fz = t.number(row, "FN_N");
  return p;
}

std::size_t find_row(const railsim::results::CsvTable& t, const std::string& id) {
  for (std::size_t r = 0; r < t.rows.size(); ++r)
    if (t.rows[r][t.column("case_id")] == id) return r;
  FAIL("case " << id << " not in " << t.file);
  return 0;
}

}  // namespace

TEST_CASE("Cattaneo-Mindlin: stick radius and force versus shift within 1 %", "[mim][tangential]") {
  // Circular Hertz contact a = 6.1 mm, P = 75 kN, mu = 0.3. Identical bodies
  // (Johnson 1985, eqs. 7.33 and 7.46): shift of full sliding
  // d_s = 3 mu P (2 - nu)/(8 G a); Q = mu P [1 - (1 - d/d_s)^{3/2}];
  // stick radius c = a (1 - Q/(mu P))^{1/3} = a (1 - d/d_s)^{1/2}.
  const auto tab = railsim::results::read_csv(railsim::test::reference_path("contact/hertz_normal_analytic.csv"));
  const HertzPatch patch = patch_of(tab, find_row(tab, "ellipse_aob1"));
  const Material m = steel(0.3);
  const double G = m.shear_modulus(), mu = m.mu, P = patch.Fz, a = patch.a;
  const double ds = 3.0 * mu * P * (2.0 - m.nu) / (8.0 * G * a);
  MimOptions o;
  o.grid = 60;
  MimSolver solver(o);
  for (double f : {0.1, 0.3, 0.5, 0.7, 0.9}) {
    const MimSolution& s = solver.solve_shift_hertz(patch, f * ds, 0.0, m);
    const double Q = mu * P * (1.0 - std::pow(1.0 - f, 1.5));
    const double c = a * std::sqrt(1.0 - f);
    const double c_num = std::sqrt(s.n_adhesion * s.grid.element_area() / std::numbers::pi);
    INFO("shift " << f << " d_s: Q error " << (-s.Fx) / Q - 1 << ", stick radius error " << c_num / c - 1
                  << ", iterations " << s.tangential.iterations);
    CHECK(s.converged());
    CHECK(-s.Fx == Approx(Q).epsilon(0.01));
    CHECK(c_num == Approx(c).epsilon(0.01));
    CHECK(std::abs(s.Fy) < 1e-6 * Q);
  }
  // Beyond d_s the whole patch slides: Q = mu P.
  const MimSolution& s = solver.solve_shift_hertz(patch, 1.5 * ds, 0.0, m);
  CHECK(s.n_adhesion == 0);
  CHECK(-s.Fx == Approx(mu * P).epsilon(1e-3));  // slip turns slightly off x (nu coupling)
}

namespace {
void check_linear_theory(std::initializer_list<const char*> cases) {
  const auto ana = railsim::results::read_csv(railsim::test::reference_path("contact/hertz_normal_analytic.csv"));
  const auto lin = railsim::results::read_csv(railsim::test::reference_path("contact/linear_theory_creep_coefficients.csv"));
  const Material m = steel(100.0);
  const double G = m.shear_modulus();
  const int N = 60;
  for (const char* id : cases) {
    const HertzPatch patch = patch_of(ana, find_row(ana, id));
    const double ab = patch.a * patch.b, c = std::sqrt(ab);
    MimOptions o;
    o.grid = N;
    MimSolver solver(o);
    const double xi = 1e-5, phi = 1e-3;  // phi in 1/m (1e-6 rad/mm)
    const double C11 = -solver.solve_hertz(patch, {xi, 0, 0}, m).Fx / (G * ab * xi);
    const MimSolution& lat = solver.solve_hertz(patch, {0, xi, 0}, m);
    CHECK(lat.n_slip == 0);
    const double C22 = -lat.Fy / (G * ab * xi);
    const double C23_lat = lat.Mz / (G * ab * c * xi);
    const double C23_spin = -solver.solve_hertz(patch, {0, 0, phi}, m).Fy / (G * ab * c * phi);
    const KalkerCoefficients k = kalker_coefficients(patch.a / patch.b, m.nu);
    // CONTACT, same discretisation (N elements across the minor axis).
    std::size_t r = 0;
    while (!(lin.rows[r][lin.column("case_id")] == id && lin.number(r, "N_minor") == N)) ++r;
    INFO(id << ": C11 " << C11 << " (table " << k.C11 << ", CONTACT " << lin.number(r, "C11") << "), C22 " << C22
            << " (" << k.C22 << ", " << lin.number(r, "C22") << "), C23 from Mz(eta) " << C23_lat << " ("
            << k.C23 << ", " << lin.number(r, "C23_from_Mz_lat") << "), C23 from Fy(phi) " << C23_spin << " ("
            << lin.number(r, "C23_from_Fy_spin") << ")");
    CHECK(C11 == Approx(k.C11).epsilon(0.02));
    CHECK(C22 == Approx(k.C22).epsilon(0.02));
    CHECK(C23_lat == Approx(k.C23).epsilon(0.02));
    CHECK(C23_spin == Approx(k.C23).epsilon(0.02));
    // Same discretised problem as CONTACT for xi and eta: agreement to its tolerance.
    CHECK(C11 == Approx(lin.number(r, "C11")).epsilon(1e-4));
    CHECK(C22 == Approx(lin.number(r, "C22")).epsilon(1e-4));
    CHECK(C23_lat == Approx(lin.number(r, "C23_from_Mz_lat")).epsilon(1e-3));
    // Spin: the rigid spin slip is sampled at x_i + dx/6 as in CONTACT
    // (mim_model.hpp), so C23 from Fy(phi) is CONTACT's discretised value; it
    // differs from C23 from Mz(eta) by O(dx) (C22 dx / (6 c), about 1.4 % at
    // N = 60), which vanishes with the grid as in CONTACT's table.
    CHECK(C23_spin == Approx(lin.number(r, "C23_from_Fy_spin")).epsilon(1e-4));
    CHECK(C23_spin == Approx(C23_lat).epsilon(0.02));
  }
}
}  // namespace

TEST_CASE("linear theory: C11, C22, C23 within 2 % of Kalker's table and of CONTACT (a/b <= 1)", "[mim][tangential]") {
  check_linear_theory({"ellipse_aob0.2", "ellipse_aob0.5", "ellipse_aob1"});
}

TEST_CASE("linear theory: C11, C22, C23 within 2 % of Kalker's table and of CONTACT (a/b > 1)", "[mim][tangential]") {
  check_linear_theory({"ellipse_aob2", "ellipse_aob5", "thesis_Rw460_Rr300"});
}

namespace {
// Compare one creepage family of CONTACT's exact circular creep curves.
void check_creep_family(const std::string& family, int stride) {
  const auto t = railsim::results::read_csv(railsim::test::reference_path("contact/creep_curves_circ_exact.csv"));
  HertzPatch patch;
  patch.A = t.number(0, "A1_per_mm") * 1e3;
  patch.B = t.number(0, "B1_per_mm") * 1e3;
  patch.a = t.number(0, "a_mm") * 1e-3;
  patch.b = t.number(0, "b_mm") * 1e-3;
  patch.Fz = t.number(0, "FN_N");
  const Material m = steel(t.number(0, "mu"));
  MimOptions o;
  o.grid = 60;  // 64 x 64 elements, as the reference
  MimSolver solver(o);
  const double muF = m.mu * patch.Fz;
  double worst_rel = 0.0, worst_norm = 0.0;
  int n = 0, k = 0;
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    if (t.rows[r][t.column("family")] != family) continue;
    if (k++ % stride != 0) continue;
    const Creepages c{t.number(r, "cksi"), t.number(r, "ceta"), t.number(r, "cphi_per_mm") * 1e3};
    const MimSolution& s = solver.solve_hertz(patch, c, m);
    REQUIRE(s.grid.mx == static_cast<int>(t.number(r, "mx")));
    CHECK(s.converged());
    // Forces are compared on the scale of the curves (mu Fz; mu Fz a for Mz):
    // within 2 % of that scale. The relative differences are reported.
    for (auto [ours, ref, scale] : {std::tuple{s.Fx, t.number(r, "Fx_N"), muF},
                                    std::tuple{s.Fy, t.number(r, "Fy_N"), muF},
                                    std::tuple{s.Mz * 1e3, t.number(r, "Mz_Nmm"), muF * patch.a * 1e3}}) {
      const double err = std::abs(ours - ref);
      if (std::abs(ref) > 0.02 * scale) worst_rel = std::max(worst_rel, err / std::abs(ref));
      worst_norm = std::max(worst_norm, err / scale);
      INFO(family << " row " << r << ": ours " << ours << ", CONTACT " << ref);
      CHECK(err <= 0.02 * scale);
      // The same discretised problem as CONTACT's (spin too, since the rigid
      // spin slip is sampled as in CONTACT, mim_model.hpp), so the forces
      // agree far more closely.
      CHECK(err <= 1e-4 * std::max(std::abs(ref), 0.01 * scale));
    }
    ++n;
  }
  WARN(family << ": " << n << " points, largest relative difference " << worst_rel
              << ", largest difference / (mu Fz [a]) " << worst_norm);
  CHECK(n > 5);
}
}  // namespace

TEST_CASE("creep-force curves versus CONTACT: longitudinal", "[mim][tangential]") { check_creep_family("long", 2); }
TEST_CASE("creep-force curves versus CONTACT: lateral", "[mim][tangential]") { check_creep_family("lat", 2); }
TEST_CASE("creep-force curves versus CONTACT: spin", "[mim][tangential]") { check_creep_family("spin", 2); }
TEST_CASE("creep-force curves versus CONTACT: every point", "[mim][tangential][.slow]") {
  for (const char* f : {"long", "lat", "spin"}) check_creep_family(f, 1);
}

TEST_CASE("spin discretisation: CONTACT's grid-convergence series (phi = 1 1/m, circular patch)", "[mim][tangential]") {
  // CONTACT's Fy/(mu Fz) at 30 / 60 / 120 elements across the patch
  // (contact_spin_grid_series.csv, 4 digits); with the rigid spin slip at the
  // element centre ours was -0.5459 / -0.5528 / -0.5559 (issue 15), with the
  // offset dx/6 of mim_model.hpp it is CONTACT's to the printed digits.
  const auto series = railsim::results::read_csv(railsim::test::data_path("contact/spin_reference/contact_spin_grid_series.csv"));
  const auto t = railsim::results::read_csv(railsim::test::reference_path("contact/creep_curves_circ_exact.csv"));
  HertzPatch patch;
  patch.A = t.number(0, "A1_per_mm") * 1e3;
  patch.B = t.number(0, "B1_per_mm") * 1e3;
  patch.a = t.number(0, "a_mm") * 1e-3;
  patch.b = t.number(0, "b_mm") * 1e-3;
  patch.Fz = t.number(0, "FN_N");
  const Material m = steel(t.number(0, "mu"));
  REQUIRE(series.rows.size() == 3);
  double F[3];
  for (std::size_t r = 0; r < series.rows.size(); ++r) {
    MimOptions o;
    o.grid = static_cast<int>(series.number(r, "N"));
    o.tolerance = 1e-9;
    MimSolver solver(o);
    const MimSolution& s = solver.solve_hertz(patch, {0.0, 0.0, series.number(r, "phi_per_m")}, m);
    F[r] = s.Fy / (m.mu * s.Fz);
    // Mirror images: (xi, -eta, -phi) -> (Fx, -Fy, -Mz) exactly.
    const MimSolution& mirror = solver.solve_hertz(patch, {0.0, 0.0, -series.number(r, "phi_per_m")}, m);
    CHECK(mirror.Fy / (m.mu * mirror.Fz) == Approx(-F[r]).epsilon(1e-9));
    WARN("grid " << o.grid << ": Fy/(mu Fz) " << F[r] << " (CONTACT " << series.number(r, "Fy_over_muFn") << ")");
    CHECK(F[r] == Approx(series.number(r, "Fy_over_muFn")).margin(6e-5));
  }
  // Acceptance of issue 15: grid 60 within 0.3 % of mu Fz of grid 120.
  CHECK(std::abs(F[1] - F[2]) < 0.003);
}

TEST_CASE("full slip and large spin converge to mu Fz", "[mim][tangential]") {
  HertzPatch patch{1.086956521739, 3.089949247458, 7.14345734e-3, 3.57172867e-3, 0, 0, 75000};
  const Material m = steel(0.3);
  MimOptions o;
  o.grid = 30;
  MimSolver solver(o);
  for (Creepages c : {Creepages{0.05, 0.0, 0.0}, Creepages{0.0, 0.0, 40.0}, Creepages{0.003, -0.004, 25.0},
                      Creepages{-0.02, 0.02, -60.0}}) {
    const MimSolution& s = solver.solve_hertz(patch, c, m);
    INFO("xi " << c.xi << " eta " << c.eta << " phi " << c.phi << ": iterations " << s.tangential.iterations);
    CHECK(s.converged());
    CHECK(std::hypot(s.Fx, s.Fy) <= m.mu * s.Fz * (1 + 1e-9));
    if (c.phi == 0.0) {
      // Full slip; the elastic xy-coupling turns the slip a little off x.
      CHECK(s.n_adhesion == 0);
      CHECK(-s.Fx == Approx(m.mu * s.Fz).epsilon(1e-4));
    }
    // Traction bound respected element by element.
    for (int q = 0; q < s.grid.size(); ++q) CHECK(std::hypot(s.px[q], s.py[q]) <= m.mu * s.pn[q] * (1 + 1e-12) + 1e-9);
  }
  // Odd symmetry: reversing all creepages reverses the forces.
  const MimSolution a = solver.solve_hertz(patch, {0.001, 0.0005, 2.0}, m);
  const MimSolution& b = solver.solve_hertz(patch, {-0.001, -0.0005, -2.0}, m);
  CHECK(b.Fx == Approx(-a.Fx).epsilon(1e-6));
  CHECK(b.Fy == Approx(-a.Fy).epsilon(1e-6));
  CHECK(b.Mz == Approx(-a.Mz).epsilon(1e-6));
}

TEST_CASE("non-convergence is reported, never silent", "[mim][tangential]") {
  HertzPatch patch{1.086956521739, 1.086956521739, 6.10114259e-3, 6.10114259e-3, 0, 0, 75000};
  MimOptions o;
  o.grid = 20;
  o.max_iterations = 3;
  MimSolver solver(o);
  CHECK_THROWS_AS(solver.solve_hertz(patch, {0.0005, 0, 0}, steel(0.3)), railsim::NumericalError);
  o.throw_on_failure = false;
  MimSolver quiet(o);
  const MimSolution& s = quiet.solve_hertz(patch, {0.0005, 0, 0}, steel(0.3));
  CHECK_FALSE(s.converged());
  CHECK(s.tangential.iterations == 3);
  CHECK(s.tangential.residual > o.tolerance);
}

TEST_CASE("mim solver rejects bad input", "[mim][tangential]") {
  HertzPatch patch{1.0, 1.0, 6e-3, 6e-3, 0, 0, 75000};
  MimSolver solver;
  CHECK_THROWS_AS(solver.solve_hertz(patch, {std::nan(""), 0, 0}, steel(0.3)), railsim::InputError);
  CHECK_THROWS_AS(solver.solve_hertz(patch, {0, 0, 0}, Material{210e9, 0.7, 0.3}), railsim::InputError);
  CHECK_THROWS_AS(solver.solve_hertz(patch, {0, 0, 0}, Material{210e9, 0.28, -0.1}), railsim::InputError);
  HertzPatch bad = patch;
  bad.Fz = -1;
  CHECK_THROWS_AS(solver.solve_hertz(bad, {0, 0, 0}, steel(0.3)), railsim::InputError);
  MimOptions o;
  o.grid = 2;
  CHECK_THROWS_AS(MimSolver(o), railsim::InputError);
  o.grid = 20;
  o.tolerance = 0.0;
  CHECK_THROWS_AS(MimSolver(o), railsim::InputError);
  const ContactGrid g = centred_grid(10, 10, 1e-3, 1e-3);
  CHECK_THROWS_AS(solver.solve_gap(g, std::vector<double>(5, 0.0), 1000, {}, steel(0.3)), railsim::InputError);
}
