// JSON writer: the text parses back (nlohmann) to the same tree, in insertion
// order, with exact numbers, escaped strings and non-finite numbers as null.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

#include "core/errors.hpp"
#include "json_support.hpp"
#include "results/json_writer.hpp"
#include "test_support.hpp"

using railsim::results::Json;

TEST_CASE("JSON output parses back to the same values, in order", "[results]") {
  Json j = Json::object();
  j.set("name", "a \"b\"\n\t\\ \x01 end");
  j.set("speed_kmh", 212.5);
  j.set("third", 0.1 + 0.2);  // not representable in 12 digits: must read back exactly
  j.set("tiny", -1.25e-300);
  j.set("bad", std::nan(""));
  j.set("inf", std::numeric_limits<double>::infinity());
  j.set("ok", true);
  j.set("count", 21);
  j.set("big", static_cast<unsigned long>(1) << 60);
  j["nested"].set("n", 3);
  j["list"] = Json::array();
  j["list"].push(1.0).push(-2.5).push("x");
  j.set("speed_kmh", 213.0);  // replaces, keeps the position
  for (const int indent : {0, 2}) {
    const std::string text = j.dump(indent);
    CHECK(text.back() == '\n');
    CHECK((text.find('\n') == text.size() - 1) == (indent == 0));  // compact: one line
    const auto p = nlohmann::ordered_json::parse(text);
    std::vector<std::string> keys;
    for (const auto& [k, v] : p.items()) keys.push_back(k);
    CHECK(keys == std::vector<std::string>{"name", "speed_kmh", "third", "tiny", "bad", "inf", "ok", "count", "big",
                                           "nested", "list"});
    CHECK(p["name"] == "a \"b\"\n\t\\ \x01 end");
    CHECK(p["speed_kmh"].get<double>() == 213.0);
    CHECK(p["third"].get<double>() == 0.1 + 0.2);
    CHECK(p["tiny"].get<double>() == -1.25e-300);
    CHECK(p["bad"].is_null());
    CHECK(p["inf"].is_null());
    CHECK(p["ok"] == true);
    CHECK(p["count"].is_number_integer());
    CHECK(p["count"] == 21);
    CHECK(p["big"].get<unsigned long>() == (static_cast<unsigned long>(1) << 60));
    CHECK(p["nested"]["n"] == 3);
    CHECK(p["list"] == nlohmann::ordered_json::parse("[1.0, -2.5, \"x\"]"));
  }
}

TEST_CASE("JSON: invalid UTF-8 is replaced, not fatal, and write_file is atomic", "[results]") {
  Json j = Json::object();
  j.set("path", std::string("caf\xe9.yaml"));  // Latin-1 byte, not UTF-8
  const auto p = nlohmann::json::parse(j.dump());
  CHECK(p["path"].get<std::string>() == "caf\xef\xbf\xbd.yaml");  // U+FFFD
  const std::string dir = railsim::test::temp_dir("json_writer");
  j.write_file(dir + "/s.json");
  CHECK(railsim::test::read_json(dir + "/s.json")["path"] == p["path"]);
  CHECK_THROWS_AS(j.write_file(dir + "/missing_folder/s.json"), railsim::InputError);
}
