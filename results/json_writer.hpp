// Minimal JSON document builder for run summaries (summary.json).
//
// Builds an ordered tree of objects, arrays, numbers, strings and booleans and
// writes it with proper string escaping. Non-finite numbers are written as null
// (JSON has no NaN). Kept deliberately small: railsim only writes JSON.
#pragma once

#include <map>
#include <memory>
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
  Json(int v) : value_(static_cast<double>(v)) {}
  Json(long v) : value_(static_cast<double>(v)) {}
  Json(long long v) : value_(static_cast<double>(v)) {}
  Json(unsigned long v) : value_(static_cast<double>(v)) {}
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

  std::string dump(int indent = 2) const;
  // Write to a file (atomic: temp file then rename); throws InputError on failure.
  void write_file(const std::string& path, int indent = 2) const;

 private:
  void dump_to(std::string& out, int indent, int level) const;
  std::variant<std::nullptr_t, double, bool, std::string, Object, Array> value_;
};

}  // namespace railsim::results
