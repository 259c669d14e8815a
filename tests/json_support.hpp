// Reading the JSON files railsim writes (summary.json, chart specifications)
// in tests: parsed with nlohmann-json, never searched as text.
#pragma once

#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

namespace railsim::test {

// The parsed document; a missing file or a syntax error throws (the test fails
// with nlohmann's message naming the position).
inline nlohmann::json read_json(const std::string& path) {
  std::ifstream f(path);
  if (!f) throw std::runtime_error(path + ": cannot open");
  return nlohmann::json::parse(f);
}

// A number member (NaN for null or absent), e.g. json_number(j, "critical_speed_kmh").
inline double json_number(const nlohmann::json& j, const std::string& key) {
  const auto it = j.find(key);
  if (it == j.end() || it->is_null()) return std::numeric_limits<double>::quiet_NaN();
  return it->get<double>();
}

}  // namespace railsim::test
