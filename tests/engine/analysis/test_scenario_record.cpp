// What summaries record of a scenario (engine/analysis/scenario_record.cpp)
// and the equivalent conicity of its geometry (equivalent_conicity.cpp).
#include <catch2/catch.hpp>

#include <cmath>

#include "engine/analysis/critical_speed.hpp"
#include "engine/analysis/equivalent_conicity.hpp"
#include "engine/analysis/scenario_record.hpp"
#include "test_support.hpp"

using namespace railsim::engine;

TEST_CASE("equivalent conicity: the cone's conicity for conical wheels, rising toward the flange for S1002",
          "[conicity]") {
  const Scenario cone = load_scenario(railsim::test::data_path("scenarios/single_wheelset_flange.yaml"));
  const auto c = conicity_curve(*cone.model.wheelsets.front().geometry);
  REQUIRE(c.size() == 6);
  for (const auto& p : c) CHECK(p.conicity == Approx(0.2).epsilon(1e-9));  // below the 9 mm flange clearance
  CHECK(std::isnan(equivalent_conicity(*cone.model.wheelsets.front().geometry, 0.0)));
  const Scenario s1002 = load_scenario(railsim::test::data_path("scenarios/single_wheelset_s1002.yaml"));
  const auto t = conicity_curve(*s1002.model.wheelsets.front().geometry);
  REQUIRE(t.size() == 6);
  for (const auto& p : t) {
    CHECK(p.conicity > 0.0);
    CHECK(p.conicity < 1.0);
  }
  CHECK(t.back().conicity > t.front().conicity);  // the flange root raises it
}

TEST_CASE("scenario record: mu, geometry, conicity, wheelset model, saturation law, reduction as given",
          "[scenario_record]") {
  const Scenario sc = load_scenario(railsim::test::data_path("scenarios/single_wheelset_s1002.yaml"));
  const std::string r = scenario_record(sc).dump();
  for (const char* key : {"\"wheelset_model\": \"lateral\"", "\"geometry\"", "\"equivalent_conicity\"",
                          "\"amplitude_mm\": 3", "\"saturation_law\": \"Shen-Hedrick-Elkins", "\"mu\": 0.3",
                          "\"reduction\"", "\"form\": \"unset\"", "\"label\": \"uniform 1\""})
    CHECK(r.find(key) != std::string::npos);
  // A preset name only when the preset was chosen.
  const railsim::contact::ReductionFactors half{0.5, 0.5, 0.5};
  const std::string numbers = reduction_record(with_contact(sc, "", &half)).dump();
  CHECK(numbers.find("third_body") == std::string::npos);
  CHECK(numbers.find("\"label\": \"uniform 0.5\"") != std::string::npos);
  const auto preset = railsim::contact::parse_reduction_spec("third_body", "test");
  const std::string named = reduction_record(with_reduction(sc, preset, "test")).dump();
  CHECK(named.find("\"label\": \"third_body\"") != std::string::npos);
  CHECK(named.find("\"given\": \"third_body\"") != std::string::npos);
  CHECK(named.find("\"k22\": 0.5") != std::string::npos);
}
