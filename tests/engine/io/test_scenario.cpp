// Scenario and vehicle files: bad input names file, line, key and range.
#include <catch2/catch.hpp>

#include "core/errors.hpp"
#include "engine/engine_test_support.hpp"

using namespace railsim;

namespace {
std::string error_of(const std::string& extra, const std::string& vehicle = "vehicles/single_wheelset.yaml") {
  try {
    test::single_wheelset(30.0, 1e7, vehicle, extra);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST_CASE("scenario errors name file, line and key", "[engine][scenario]") {
  CHECK(error_of("integrator: {method: euler}\n").find("unknown integrator 'euler'") != std::string::npos);
  CHECK(error_of("wheelset_model: rigid\n").find("key 'wheelset_model'") != std::string::npos);
  CHECK(error_of("initial: {ws9.lateral: 0.001}\n").find("unknown state 'ws9.lateral'") != std::string::npos);
  CHECK(error_of("colour: red\n").find("colour") != std::string::npos);
  const std::string msg = error_of("integrator: {rtol: -1}\n");
  CHECK(msg.find("test_scenario.yaml:") != std::string::npos);
  CHECK(msg.find("rtol") != std::string::npos);
}

TEST_CASE("vehicle errors name the vehicle file and key", "[engine][scenario]") {
  const std::string msg = error_of("", "tests/data/engine/bad_vehicle.yaml");
  CHECK(msg.find("bad_vehicle.yaml:") != std::string::npos);
  CHECK(msg.find("unknown body 'bogie9'") != std::string::npos);
}
