// A file named in a scenario that does not exist is an InputError naming the
// scenario file, the line and the key (vehicle, track, contact table, profile).
#include <catch2/catch.hpp>

#include <fstream>
#include <string>

#include "core/errors.hpp"
#include "engine/io/scenario.hpp"
#include "test_support.hpp"

using namespace railsim;

namespace {

// The shipped coach curve scenario with one file reference replaced by a
// missing one (relative to the scenario's folder, a temporary one), the other
// references made absolute so that they still resolve.
std::string error_of(const std::string& from, const std::string& to, int* line) {
  std::string text = test::read_text(test::source_path("scenarios/manchester_coach_curve_R300.yaml"));
  const auto at = text.find(from);
  REQUIRE(at != std::string::npos);
  text.replace(at, from.size(), to);
  *line = 1;
  for (std::size_t i = 0; i < at; ++i) *line += text[i] == '\n' ? 1 : 0;
  for (std::size_t p; (p = text.find(" ../")) != std::string::npos;) text.replace(p + 1, 2, test::source_path(""));
  const std::string path = test::temp_dir("scenario_files") + "/s.yaml";
  { std::ofstream(path) << text; }
  try {
    engine::load_scenario(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("missing files named in a scenario: file, line and key", "[engine][scenario]") {
  int line = 0;
  std::string m = error_of("../vehicles/manchester_coach.yaml", "no_coach.yaml", &line);
  CHECK(m.find(".yaml:" + std::to_string(line) + ": key 'vehicle': file 'no_coach.yaml' not found") !=
        std::string::npos);
  m = error_of("track: ../tracks/curve_R300.yaml", "track: no_curve.yaml", &line);
  CHECK(m.find(".yaml:" + std::to_string(line) + ": key 'track': file 'no_curve.yaml' not found") !=
        std::string::npos);
  m = error_of("{type: profiles, wheel: S1002, rail: UIC60, inclination: 1/40, r0: 0.46}",
               "{type: table, file: no_table.dat}", &line);
  CHECK(m.find(".yaml:" + std::to_string(line) + ": key 'contact.geometry.file': file 'no_table.dat' not found") !=
        std::string::npos);
  m = error_of("rail: UIC60,", "rail: my_rail.prr,", &line);
  INFO(m);
  CHECK(m.find(".yaml:" + std::to_string(line) + ": key 'contact.geometry.rail': file 'my_rail.prr' not found") !=
        std::string::npos);
  CHECK(m.find("not a shipped profile name") != std::string::npos);
}
