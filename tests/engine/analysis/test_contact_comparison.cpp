// Contact-model comparison (engine/analysis/contact_comparison.cpp) without the
// program: the failure-map axes against Kalker's tabulated coefficients, the
// exact solver compared with itself (zero error, nothing fails), linear theory
// at vanishing creepage against the exact solver (Kalker's theorem: both tend to
// the same creep coefficients), the statistics and the Pareto front against
// their definitions recomputed from the per-case rows.
#include <catch2/catch.hpp>

#include <cmath>

#include "contact/hertz.hpp"
#include "contact/registry.hpp"
#include "core/errors.hpp"
#include "engine/analysis/contact_comparison.hpp"

using namespace railsim;
using namespace railsim::engine;

namespace {

contact::ContactInput circular_patch(double xi, double eta, double phi) {
  contact::ContactInput in;
  in.material.nu = 0.25;
  in.material.mu = 0.3;
  in.patch = contact::hertz_from_semi_axes(0.006, 0.006, 80e3, in.material);
  in.creep = {xi, eta, phi};
  return in;
}

}  // namespace

TEST_CASE("failure map axes: full slip and spin unit from Kalker's coefficients, log-spaced creepage",
          "[contact_comparison]") {
  const contact::ContactInput in = circular_patch(0, 0, 0);
  // Kalker (1967) table, a/b = 1, nu = 0.25: C11 = 4.12, C22 = 3.67, C23 = 1.47 (two-figure table: 1 %).
  const double G = in.material.shear_modulus(), c = 0.006, muFz = 0.3 * 80e3;
  const FailureMapAxes lat = failure_map_axes(in, CreepDirection::lateral, 5);
  CHECK(lat.creepage_full_slip == Approx(3.0 * muFz / (G * c * c * 3.67)).epsilon(0.01));
  CHECK(lat.spin_unit == Approx(muFz / (G * c * c * c * 1.47)).epsilon(0.01));
  const FailureMapAxes lon = failure_map_axes(in, CreepDirection::longitudinal, 5);
  CHECK(lon.creepage_full_slip == Approx(3.0 * muFz / (G * c * c * 4.12)).epsilon(0.01));
  const FailureMapAxes dia = failure_map_axes(in, CreepDirection::diagonal, 5);
  CHECK(dia.dir_x == Approx(std::sqrt(0.5)));
  CHECK(std::hypot(dia.dir_x, dia.dir_y) == Approx(1.0));
  REQUIRE(lat.creepage.size() == 5);
  CHECK(lat.creepage.front() == Approx(0.03 * lat.creepage_full_slip));
  CHECK(lat.creepage.back() == Approx(3.0 * lat.creepage_full_slip));
  for (std::size_t i = 1; i + 1 < lat.creepage.size(); ++i)
    CHECK(lat.creepage[i] * lat.creepage[i] == Approx(lat.creepage[i - 1] * lat.creepage[i + 1]));
  CHECK(lat.spin.front() == 0.0);
  CHECK(lat.spin.back() == Approx(2.0 * lat.spin_unit));
  CHECK(parse_creep_direction("diagonal", "--x") == CreepDirection::diagonal);
  CHECK_THROWS_AS(parse_creep_direction("vertical", "--x"), InputError);
}

TEST_CASE("contact comparison: the exact solver against itself, linear theory at small creepage",
          "[contact_comparison]") {
  ContactComparisonOptions o;
  o.reference_grid = 12;
  o.reference_tolerance = 1e-9;
  o.map_points = 3;
  contact::TangentialModelOptions same;
  same.grid = o.reference_grid;
  same.tolerance = o.reference_tolerance;
  const auto mim = contact::make_tangential_model("mim", same);
  const auto mim_ws = mim->make_workspace();
  const auto lin = contact::make_tangential_model("linear");
  const auto lin_ws = lin->make_workspace();
  const std::vector<ComparisonCase> cases = {{"small_lat", circular_patch(0, 1e-6, 0)},
                                             {"small_lon", circular_patch(1e-6, 0, 0)},
                                             {"saturated", circular_patch(0, 5e-3, 0)}};
  const std::vector<ComparedModel> models = {{"mim", "same grid", mim.get(), mim_ws.get()},
                                             {"linear", "Kalker linear", lin.get(), lin_ws.get()}};
  const ContactComparison r = compare_contact_models(cases, models, o);
  REQUIRE(r.reference.size() == 3);
  REQUIRE(r.results.size() == 2);
  REQUIRE(r.stats.size() == 2);

  // The same deterministic solver on the same grid: no error anywhere, no map failure.
  CHECK(r.stats[0].max_F < 1e-9);
  CHECK(r.stats[0].map_failures == 0);
  CHECK(r.stats[0].map_points == 9);
  // Linear theory: within the discretisation error of the coarse grid at 1e-6 creepage
  // (both tend to Kalker's C11, C22), far off once the patch slides (it does not saturate).
  CHECK(r.results[1][0].error.F < 0.05);
  CHECK(r.results[1][1].error.F < 0.05);
  CHECK(r.results[1][2].error.F > 1.0);
  CHECK(r.results[1][0].forces.Fy * r.reference[0].Fy > 0.0);  // same sign convention

  // Statistics recomputed from the rows.
  for (std::size_t m = 0; m < models.size(); ++m) {
    double max_F = 0, sum = 0, sum2 = 0, cost = 0;
    for (const auto& row : r.results[m]) {
      max_F = std::max(max_F, row.error.F);
      sum += row.error.F;
      sum2 += row.error.F * row.error.F;
      cost += row.cost_us;
      CHECK(row.cost_us > 0.0);
    }
    CHECK(r.stats[m].cases == 3);
    CHECK(r.stats[m].max_F == Approx(max_F));
    CHECK(r.stats[m].mean_F() == Approx(sum / 3));
    CHECK(r.stats[m].rms_F() == Approx(std::sqrt(sum2 / 3)));
    CHECK(r.stats[m].mean_cost_us() == Approx(cost / 3));
  }
  // Pareto front by its definition: not dominated in (cost, max error).
  for (std::size_t m = 0; m < models.size(); ++m) {
    bool dominated = false;
    for (std::size_t k = 0; k < models.size(); ++k)
      dominated = dominated || (k != m && r.stats[k].mean_cost_us() <= r.stats[m].mean_cost_us() &&
                                r.stats[k].max_F <= r.stats[m].max_F &&
                                (r.stats[k].mean_cost_us() < r.stats[m].mean_cost_us() ||
                                 r.stats[k].max_F < r.stats[m].max_F));
    CHECK(r.pareto_front[m] == !dominated);
  }
  // The map: 3 x 3 points per model, in spin-major order, the creepage along the lateral direction.
  REQUIRE(r.has_map);
  REQUIRE(r.map.points.size() == 18);
  CHECK(r.map.points[0].creep.xi == 0.0);
  CHECK(r.map.points[2].creepage == Approx(r.map.axes.creepage[1]));
  CHECK(r.map.points[17].creep.phi == Approx(r.map.axes.spin[2]));
  // Median of three reference costs is one of them.
  CHECK((r.reference_median_cost_us == r.reference_cost_us[0] || r.reference_median_cost_us == r.reference_cost_us[1] ||
         r.reference_median_cost_us == r.reference_cost_us[2]));

  ContactComparisonOptions bad = o;
  bad.map_case = 3;
  CHECK_THROWS_AS(compare_contact_models(cases, models, bad), InputError);
  CHECK_THROWS_AS(compare_contact_models({}, models, o), InputError);
}
