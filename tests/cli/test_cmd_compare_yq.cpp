// The shipped derailment case (scenarios/manchester_coach_derailment*.yaml)
// through `railsim run` and `railsim compare-yq`, with both wheelset models:
// the leading wheel flanges in the curve, and the peak Y/Q with k = 0.5 stays
// below the peak with k = 1 (Toumi's trend: 1.27 -> 1.08).
#include <catch2/catch.hpp>
#include <cstdio>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "json_support.hpp"
#include "results/csv_writer.hpp"
#include "test_support.hpp"

using railsim::test::run_railsim;

namespace {

// The lines of a text without its comments.
std::vector<std::string> keys(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream ss(text);
  for (std::string l; std::getline(ss, l);)
    if (!l.empty() && l[0] != '#') out.push_back(l);
  return out;
}

}  // namespace

TEST_CASE("derailment case: k = 0.5 lowers the peak Y/Q of the leading wheels, both wheelset models",
          "[cli][compare_yq][derailment]") {
  const std::string k1 = railsim::test::source_path("scenarios/manchester_coach_derailment.yaml");
  const std::string k05 = railsim::test::source_path("scenarios/manchester_coach_derailment_k05.yaml");
  // The two files differ only in the name and the reduction.
  const auto a = keys(railsim::test::read_text(k1)), b = keys(railsim::test::read_text(k05));
  REQUIRE(a.size() == b.size());
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i] != b[i]) {
      INFO(a[i] << " | " << b[i]);
      CHECK((a[i].rfind("name:", 0) == 0 || a[i].find("reduction:") != std::string::npos));
    }
  const std::string dir = railsim::test::temp_dir("cli_derail");
  for (const char* model : {"lateral", "full"}) {
    INFO("wheelset model " << model);
    std::vector<std::string> runs;
    for (const auto& file : {k1, k05}) {
      std::string text = railsim::test::read_text(file);
      text.replace(text.find("wheelset_model: lateral"), 23, std::string("wheelset_model: ") + model);
      std::size_t p = 0;
      while ((p = text.find("../", p)) != std::string::npos) text.replace(p, 3, railsim::test::source_path(""));
      const std::string name = std::string(model) + (file == k1 ? "_k1" : "_k05");
      std::ofstream(dir + "/" + name + ".yaml") << text;
      const auto r = run_railsim("run '" + dir + "/" + name + ".yaml' --out '" + dir + "/" + name + "'");
      INFO(r.output);
      REQUIRE(r.exit_code == 0);
      runs.push_back(dir + "/" + name);
    }
    const auto c = run_railsim("compare-yq '" + dir + "/" + model + "_k1.yaml' '" + runs[0] + "' '" + runs[1] +
                               "' --labels 'k = 1,k = 0.5' --out '" + dir + "/" + model + "_cmp'");
    INFO(c.output);
    REQUIRE(c.exit_code == 0);
    // Nadal's limit from the geometry's largest flange angle and mu 0.3:
    // (tan d - mu) / (1 + mu tan d) (the smoothed RSGEO table: 69.9 deg, 1.34).
    const auto js = railsim::test::read_json(dir + "/" + model + "_cmp/summary.json");
    const double delta = railsim::test::json_number(js, "flange_angle_deg") * std::acos(-1.0) / 180.0;
    const double mu = railsim::test::json_number(js, "mu");
    CHECK(mu == Approx(0.3));
    CHECK(delta * 180.0 / std::acos(-1.0) > 69.0);
    CHECK(delta * 180.0 / std::acos(-1.0) < 71.0);
    const double nadal = (std::tan(delta) - mu) / (1.0 + mu * std::tan(delta));
    CHECK(railsim::test::json_number(js, "nadal_limit") == Approx(nadal).epsilon(1e-9));
    char limit[64];
    std::snprintf(limit, sizeof limit, "Nadal limit %.2f", nadal);
    CHECK(c.output.find(limit) != std::string::npos);
    const auto t = railsim::results::read_csv(dir + "/" + model + "_cmp/yq_comparison.csv");
    REQUIRE(t.rows.size() == 4);  // two runs x two wheels
    const double peak_k1 = std::max(t.number(0, "max_abs_yq"), t.number(1, "max_abs_yq"));
    const double peak_k05 = std::max(t.number(2, "max_abs_yq"), t.number(3, "max_abs_yq"));
    // Measured: lateral 0.338 -> 0.289 (-15 %), full 0.328 -> 0.270 (-18 %), flanging right wheel.
    CHECK(peak_k05 < peak_k1);
    CHECK(peak_k05 < 0.95 * peak_k1);
    // The flanging wheel is the outer (right) one of the left curve, at its peak in the curve or exit transition.
    CHECK(t.number(1, "max_abs_yq") > t.number(0, "max_abs_yq"));
    CHECK(t.number(1, "distance_m") > 80.0);
    CHECK(t.number(1, "distance_m") < 170.0);
    CHECK(std::filesystem::exists(dir + "/" + model + "_cmp/yq_comparison.png"));
    // The leading wheelset runs in flange contact in the curve (RSGEO flange root at ~8 mm).
    const auto ch = railsim::results::read_csv(runs[0] + "/channels.csv");
    double ymax = 0.0;
    for (std::size_t i = 0; i < ch.rows.size(); ++i) ymax = std::max(ymax, std::fabs(ch.number(i, "ws1.y")));
    CHECK(ymax > 8.0e-3);
  }
}
