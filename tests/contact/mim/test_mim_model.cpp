// Tests of contact/mim/mim_model.cpp (registered model "mim", gap-on-grid
// entry point) and contact/mim/third_body.cpp.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "contact/hertz.hpp"
#include "contact/mim/mim_model.hpp"
#include "contact/registry.hpp"
#include "core/errors.hpp"

using namespace railsim::contact;
using namespace railsim::contact::mim;

TEST_CASE("model 'mim' is registered and matches the library call", "[mim][model]") {
  TangentialModelOptions opt;
  opt.grid = 24;
  auto model = make_tangential_model("mim", opt);
  REQUIRE(model->name() == "mim");
  auto ws = model->make_workspace();
  ContactInput in;
  in.material = Material{210e9, 0.28, 0.3};
  in.patch = hertz_from_load(1.0869565, 1.6666667, 75000, in.material);
  in.creep = {0.0008, -0.0003, 0.0};
  const ContactForces f = model->solve(in, ws.get());
  MimOptions mo;
  mo.grid = 24;
  MimSolver s(mo);
  const MimSolution r = s.solve_hertz(in.patch, in.creep, in.material);
  mo.grid = 12;
  MimSolver half(mo);
  const MimSolution& h = half.solve_hertz(in.patch, in.creep, in.material);
  // Default: Richardson extrapolation 2 F_24 - F_12 (the fine grid's normal
  // and tangential iterations start from the half grid's solution: equal to
  // the solver tolerance).
  CHECK(f.valid);
  CHECK(f.Fx == Approx(2.0 * r.Fx - h.Fx).epsilon(1e-6));
  CHECK(f.Fy == Approx(2.0 * r.Fy - h.Fy).epsilon(1e-6));
  CHECK(f.Mz == Approx(2.0 * r.Mz - h.Mz).epsilon(1e-6));
  CHECK(std::abs(f.Fx - r.Fx) > 1e-4 * std::abs(r.Fx));  // it does extrapolate
  // extrapolation None: the library call itself.
  TangentialModelOptions plain = opt;
  plain.extrapolation = GridExtrapolation::None;
  const ContactForces p = make_tangential_model("mim", plain)->solve(in);
  CHECK(p.Fx == Approx(r.Fx).epsilon(1e-12));
  CHECK(p.Fy == Approx(r.Fy).epsilon(1e-12));
  CHECK(p.Mz == Approx(r.Mz).epsilon(1e-12));
  CHECK(f.Fx < 0.0);  // positive creepage -> negative force
  CHECK(f.Fy > 0.0);  // negative lateral creepage -> positive force
  CHECK(f.stick_fraction > 0.0);
  CHECK(f.stick_fraction < 1.0);
  // Without a workspace the model still works (allocating its own).
  CHECK(model->solve(in, nullptr).Fx == Approx(f.Fx).epsilon(1e-12));
  opt.grid = 1;
  CHECK_THROWS_AS(make_tangential_model("mim", opt), railsim::InputError);
  opt.grid = 6;  // the half grid would have 3 elements
  CHECK_THROWS_AS(make_tangential_model("mim", opt), railsim::InputError);
  plain.grid = 6;
  CHECK(make_tangential_model("mim", plain)->solve(in).valid);
}

// A patch outside a/b [0.01, 100] is solved at the domain's edge with its sqrt(ab) and load (the grid's long
// side grows with a/b: a 1 N flange patch of a/b 385 in wheelset-contact took 63 s and 1.5 GB) and flagged.
TEST_CASE("model 'mim': a/b outside 0.01 to 100 is held at the edge and flagged", "[mim][model]") {
  TangentialModelOptions opt;
  opt.grid = 8;
  opt.extrapolation = GridExtrapolation::None;
  const auto model = make_tangential_model("mim", opt);
  const Material m{210e9, 0.28, 0.3};
  const double size = 1e-4;  // sqrt(ab) [m]
  auto force = [&](double aspect) {
    ContactInput in;
    in.material = m;
    in.patch = hertz_from_semi_axes(size * std::sqrt(aspect), size / std::sqrt(aspect), 1.0, m);
    in.creep = {0.001, 0.002, 0.5};
    return model->solve(in);
  };
  for (const auto& [outside, edge] : {std::pair{400.0, 100.0}, {1.0 / 385.0, 0.01}}) {
    INFO("a/b " << outside);
    const ContactForces held = force(outside), at_edge = force(edge);
    CHECK_FALSE(held.valid);
    CHECK(std::string(held.reason).find("a/b outside [0.01, 100]") != std::string::npos);
    CHECK(at_edge.valid);
    CHECK(held.Fx == Approx(at_edge.Fx).epsilon(1e-9));
    CHECK(held.Fy == Approx(at_edge.Fy).epsilon(1e-9));
  }
}

TEST_CASE("gap on a grid: a Hertzian gap reproduces the Hertzian call", "[mim][model]") {
  const Material m{210e9, 0.28, 0.3};
  const HertzPatch p = hertz_from_load(1.0869565, 1.6666667, 75000, m);
  MimOptions o;
  o.grid = 20;
  MimSolver s(o);
  const MimSolution a = s.solve_hertz(p, {0.0005, 0.0002, 1.0}, m);
  const ContactGrid g = grid_for_patch(p.a, p.b, 20);
  const MimSolution& b = s.solve_gap(g, quadratic_gap(g, p.A, p.B), p.Fz, {0.0005, 0.0002, 1.0}, m);
  CHECK(b.Fx == Approx(a.Fx).epsilon(1e-9));
  CHECK(b.Mz == Approx(a.Mz).epsilon(1e-9));
  CHECK(b.approach == Approx(a.approach).epsilon(1e-12));
}

TEST_CASE("gap on a grid: two distant lobes act like two half-load Hertz contacts", "[mim][model]") {
  // Two identical spherical lobes (radius 0.46 m) 40 mm apart laterally; each
  // carries half the load. Their elastic interaction is of order a/d, so the
  // creep forces are close to twice those of one Hertz contact with Fz/2.
  const Material m{210e9, 0.28, 0.3};
  const double A = 1.0 / 0.92, d = 20e-3, Fz = 40000;
  const HertzPatch half = hertz_from_load(A, A, Fz / 2, m);
  const double dx = 2 * 1.1 * half.a / 24;
  ContactGrid g;
  g.mx = 24;
  g.my = static_cast<int>(std::lround(2 * (d + 1.1 * half.a) / dx));
  g.dx = g.dy = dx;
  g.x0 = -0.5 * g.mx * dx;
  g.y0 = -0.5 * g.my * dx;
  std::vector<double> h(g.size());
  for (int j = 0; j < g.my; ++j)
    for (int i = 0; i < g.mx; ++i) {
      const double x = g.x(i), y = std::abs(g.y(j)) - d;
      h[g.index(i, j)] = A * (x * x + y * y);
    }
  MimOptions o;
  MimSolver s(o);
  const Creepages c{0.0006, 0.0, 0.0};
  const MimSolution& two = s.solve_gap(g, h, Fz, c, m);
  CHECK(two.converged());
  // Two separate patches of equal load.
  double upper = 0, lower = 0;
  for (int j = 0; j < g.my; ++j)
    for (int i = 0; i < g.mx; ++i) (g.y(j) > 0 ? upper : lower) += two.pn[g.index(i, j)] * g.element_area();
  CHECK(upper == Approx(Fz / 2).epsilon(1e-6));
  CHECK(lower == Approx(Fz / 2).epsilon(1e-6));
  o.grid = 20;
  MimSolver single(o);
  const MimSolution& one = single.solve_hertz(half, c, m);
  CHECK(two.Fx == Approx(2 * one.Fx).epsilon(0.03));
  CHECK(std::abs(two.Fy) < 1e-6 * std::abs(two.Fx));
  // The two lobes yaw the patch pair: spin about the origin gives lateral lever arms.
  const MimSolution& sp = s.solve_gap(g, h, Fz, {0.0, 0.0, 0.2}, m);
  CHECK(sp.converged());
  CHECK(sp.Mz < 0.0);
}

TEST_CASE("third-body layer lowers the initial creep slope", "[mim][third_body]") {
  const Material m{210e9, 0.28, 0.3};
  const HertzPatch p = hertz_from_load(1.0 / 0.92, 1.0 / 0.6, 75000, m);
  const int N = 16;
  const ReductionFactors ref = third_body_reduction(p, m, {125e-6, 820e6, 0.0}, N);
  const ReductionFactors thick = third_body_reduction(p, m, {250e-6, 820e6, 0.0}, N);
  const ReductionFactors soft = third_body_reduction(p, m, {125e-6, 410e6, 0.0}, N);
  const ReductionFactors thin = third_body_reduction(p, m, {30e-6, 820e6, 0.0}, N);
  WARN("third-body layer h = 125 um, G3 = 820 MPa: k11 = " << ref.k11 << ", k22 = " << ref.k22 << ", k23 = " << ref.k23);
  for (double k : {ref.k11, ref.k22, ref.k23}) {
    CHECK(k > 0.0);
    CHECK(k < 1.0);
  }
  CHECK(thick.k11 < ref.k11);
  CHECK(soft.k11 < ref.k11);
  CHECK(thin.k11 > ref.k11);
  CHECK(thick.k22 < ref.k22);
  CHECK(soft.k23 < ref.k23);
  // Limiting shear stress: the saturated force is capped by tau_c times the contact area.
  MimOptions o;
  o.grid = N;
  o.layer = {125e-6, 820e6, 50e6};
  MimSolver s(o);
  const MimSolution& r = s.solve_hertz(p, {0.05, 0, 0}, m);
  double cap = 0.0;
  for (int q = 0; q < r.grid.size(); ++q) cap += std::min(m.mu * r.pn[q], 50e6) * r.grid.element_area();
  CHECK(cap < 0.25 * m.mu * r.Fz);  // the limiting stress governs
  CHECK(-r.Fx == Approx(cap).epsilon(1e-3));
  CHECK_THROWS_AS(third_body_reduction(p, m, {125e-6, -1.0, 0.0}, N), railsim::InputError);
}

TEST_CASE("solvers in parallel threads give the serial results", "[mim][model]") {
  // FFTW planning is serialised inside Convolution; solves run concurrently.
  const Material m{210e9, 0.28, 0.3};
  const Creepages c{0.0006, 0.0002, 0.3};
  std::vector<HertzPatch> patches;
  for (double B : {0.5, 1.0, 2.0, 4.0}) patches.push_back(hertz_from_load(1.0869565, B, 50000, m));
  std::vector<double> serial(patches.size()), parallel(patches.size());
  MimOptions o;
  o.grid = 16;
  for (std::size_t k = 0; k < patches.size(); ++k) serial[k] = MimSolver(o).solve_hertz(patches[k], c, m).Fx;
  std::vector<std::thread> threads;
  for (std::size_t k = 0; k < patches.size(); ++k)
    threads.emplace_back([&, k] {
      for (int rep = 0; rep < 3; ++rep) parallel[k] = MimSolver(o).solve_hertz(patches[k], c, m).Fx;
    });
  for (auto& t : threads) t.join();
  for (std::size_t k = 0; k < patches.size(); ++k) CHECK(parallel[k] == Approx(serial[k]).epsilon(1e-12));
}

TEST_CASE("warm start in a creepage sweep: same forces, fewer iterations", "[mim][model]") {
  const Material m{210e9, 0.28, 0.3};
  const HertzPatch p = hertz_from_load(1.0869565, 1.6666667, 75000, m);
  MimOptions cold, warm;
  cold.grid = warm.grid = 24;
  warm.warm_start = true;
  MimSolver a(cold), b(warm);
  int it_cold = 0, it_warm = 0;
  for (int k = 1; k <= 8; ++k) {
    const Creepages c{0.0002 * k, 0.0, 0.1 * k};
    const MimSolution& sa = a.solve_hertz(p, c, m);
    const MimSolution& sb = b.solve_hertz(p, c, m);
    CHECK(sb.Fx == Approx(sa.Fx).epsilon(1e-5));
    CHECK(sb.Fy == Approx(sa.Fy).epsilon(1e-5));
    CHECK(sb.Mz == Approx(sa.Mz).epsilon(1e-5));
    it_cold += sa.tangential.iterations;
    it_warm += sb.tangential.iterations;
  }
  WARN("tangential iterations over the sweep: cold " << it_cold << ", warm " << it_warm);
  CHECK(it_warm < it_cold);
}
