// `railsim contact --model mim` through the railsim binary: one point of
// CONTACT's exact circular creep curve (same grid, 60 elements across), and
// the bad --grid / --tolerance paths (exit code 2).
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <string>

#include "results/csv_writer.hpp"
#include "test_support.hpp"

using railsim::test::run_railsim;

TEST_CASE("railsim contact --model mim reproduces CONTACT's creep curve point", "[mim][cli]") {
  const std::string dir = railsim::test::temp_dir("cli_mim");
  const auto ref = railsim::results::read_csv(railsim::test::reference_path("contact/creep_curves_circ_exact.csv"));
  std::size_t k = 0;
  while (!(ref.rows[k][ref.column("family")] == "long" && ref.number(k, "cksi") == 0.0008)) ++k;
  const std::string cases = dir + "/cases.yaml";
  std::ofstream(cases) << "material: {E: 2.1e11, nu: 0.28, mu: 0.3}\n"
                          "cases:\n"
                          "  - {id: circ, A: 1.0869565217391304, B: 1.0869565217391304, Fz: 75000, xi: 0.0008, eta: 0.0, phi: 0.0}\n";
  const std::string out = dir + "/out.csv";
  // CONTACT's discretisation at CONTACT's grid: no extrapolation.
  const auto r = run_railsim("contact '" + cases + "' --model mim --grid 60 --extrapolation none --out '" + out + "'");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const auto t = railsim::results::read_csv(out);
  REQUIRE(t.rows.size() == 1);
  CHECK(t.number(0, "Fx") == Approx(ref.number(k, "Fx_N")).epsilon(1e-5));
  CHECK(std::abs(t.number(0, "Fy")) < 1e-3);
  // The default (Richardson from grid 60 and 30) moves the point towards the
  // grid limit: at most the first-order grid error away (0.4 % of mu Fz here).
  const auto e = run_railsim("contact '" + cases + "' --model mim --grid 60 --out '" + out + "'");
  REQUIRE(e.exit_code == 0);
  const auto te = railsim::results::read_csv(out);
  CHECK(std::abs(te.number(0, "Fx") - ref.number(k, "Fx_N")) < 0.01 * 0.3 * 75000);
  CHECK(std::abs(te.number(0, "Fx") - ref.number(k, "Fx_N")) > 1e-5 * std::abs(ref.number(k, "Fx_N")));
  CHECK(run_railsim("contact '" + cases + "' --model mim --grid 2 --out '" + out + "'").exit_code == 2);
  CHECK(run_railsim("contact '" + cases + "' --model mim --extrapolation linear --out '" + out + "'").exit_code == 2);
  // The half grid of 6 would have 3 elements: refused naming both ways out; without extrapolation it runs.
  const auto small = run_railsim("contact '" + cases + "' --model mim --grid 6 --out '" + out + "'");
  CHECK(small.exit_code == 2);
  CHECK(small.output.find("--grid") != std::string::npos);
  CHECK(small.output.find("--extrapolation none") != std::string::npos);
  CHECK(run_railsim("contact '" + cases + "' --model mim --grid 6 --extrapolation none --out '" + out + "'").exit_code == 0);
  CHECK(run_railsim("contact '" + cases + "' --model mim --tolerance 0.5 --out '" + out + "'").exit_code == 2);
}
