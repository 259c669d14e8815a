// JSON writer: escaping, ordering, non-finite numbers as null.
#include <catch2/catch.hpp>

#include <cmath>

#include "results/json_writer.hpp"

using railsim::results::Json;

TEST_CASE("JSON output is escaped, ordered and finite", "[results]") {
  Json j = Json::object();
  j.set("name", "a \"b\"\n");
  j.set("speed_kmh", 212.5);
  j.set("bad", std::nan(""));
  j.set("ok", true);
  j["nested"].set("n", 3);
  j["list"] = Json::array();
  j["list"].push(1.0).push(2.0);
  const std::string s = j.dump(0);
  CHECK(s == "{\"name\":\"a \\\"b\\\"\\n\",\"speed_kmh\":212.5,\"bad\":null,\"ok\":true,\"nested\":{\"n\":3},\"list\":[1,2]}\n");
}
