// `railsim demo`: every registered tangential model appears in the table and in
// demo.csv; the saturated case reaches mu Fz for the saturating models.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "contact/registry.hpp"
#include "results/csv_writer.hpp"
#include "test_support.hpp"

TEST_CASE("railsim demo runs every registered model", "[cli][demo]") {
  const std::string dir = railsim::test::temp_dir("cli_demo");
  const auto r = railsim::test::run_railsim("demo --out '" + dir + "'");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const auto t = railsim::results::read_csv(dir + "/demo.csv");
  for (const auto& m : railsim::contact::tangential_models()) {
    if (!m.compared_by_default()) continue;  // built on first use: not in the demo
    INFO(m.name);
    CHECK(r.output.find(m.name) != std::string::npos);
    int rows = 0;
    for (std::size_t i = 0; i < t.rows.size(); ++i) {
      if (t.rows[i][t.column("model")] != m.name) continue;
      ++rows;
      // Creep forces never exceed the friction bound, except the unsaturated linear theory.
      if (std::string(m.name) != "linear" && t.rows[i][0] == "saturated")
        CHECK(std::hypot(t.number(i, "Fx"), t.number(i, "Fy")) / (0.3 * t.number(i, "Fz")) ==
              Approx(1.0).epsilon(0.01));
    }
    CHECK(rows == 5);
  }
}
