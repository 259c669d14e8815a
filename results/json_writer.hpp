// JSON documents railsim writes (summary.json, chart specifications), built as
// an ordered tree and serialised by nlohmann-json (Lohmann, "JSON for Modern
// C++", 3.x; Debian nlohmann-json3-dev): RFC 8259 escaping, numbers that read
// back exactly (shortest round-trip form; integers stay integers), keys in
// insertion order. Non-finite numbers are written as null (JSON has no NaN).
// Invalid UTF-8 in strings is replaced by U+FFFD rather than failing.
#pragma once

#include <cstdint>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace railsim::results {

class Json {
 public:
  using Object = std::vector<std::pair<std::string, Json>>;
  using Array = std::vector<Json>;

  Json() : value_(nullptr) {}
  Json(std::nullptr_t) : value_(nullptr) {}
  Json(double v) : value_(v) {}
  Json(int v) : value_(static_cast<std::int64_t>(v)) {}
  Json(long v) : value_(static_cast<std::int64_t>(v)) {}
  Json(long long v) : value_(static_cast<std::int64_t>(v)) {}
  Json(unsigned v) : value_(static_cast<std::int64_t>(v)) {}
  Json(unsigned long v) : value_(static_cast<std::uint64_t>(v)) {}
  Json(unsigned long long v) : value_(static_cast<std::uint64_t>(v)) {}
  Json(bool v) : value_(v) {}
  Json(const char* s) : value_(std::string(s)) {}
  Json(std::string s) : value_(std::move(s)) {}

  static Json object() { Json j; j.value_ = Object{}; return j; }
  static Json array() { Json j; j.value_ = Array{}; return j; }

  // Object: set (replace or append) a key and return the member.
  // Array: append and return the array (for chaining).
  Json& set(const std::string& key, Json v);
  Json& push(Json v);
  // Object member access (creates an empty object member when missing).
  Json& operator[](const std::string& key);

  // The document as an nlohmann ordered_json value.
  nlohmann::ordered_json to_nlohmann() const;
  // Serialised text and a final newline; indent <= 0: compact, on one line.
  std::string dump(int indent = 2) const;
  // Write to a file (atomic: temporary file then rename); throws InputError on failure.
  void write_file(const std::string& path, int indent = 2) const;

 private:
  std::variant<std::nullptr_t, double, std::int64_t, std::uint64_t, bool, std::string, Object, Array> value_;
};

}  // namespace railsim::results
