// Checked reading of YAML input files.
//
// Every value the program reads from a user's file goes through InputNode, so
// that every mistake is reported the same way, with the file, the line (1-based)
// and the key path:
//
//   cases.yaml:12: key 'cases[2].Fz': expected a positive number (got -3)
//
// Unknown keys are errors (allow_only), never silently ignored; a key given
// twice in one mapping is an error naming both lines. Numbers must be
// finite. All failures throw railsim::InputError.
#pragma once

#include <yaml-cpp/yaml.h>

#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/errors.hpp"

namespace railsim::config {

class InputNode {
 public:
  // Parse a file; a syntax error becomes InputError with file:line.
  static InputNode load_file(const std::string& path);
  // Parse text held in memory (embedded scenarios, tests); `name` stands for the file name.
  static InputNode load_string(const std::string& text, const std::string& name);

  InputNode(YAML::Node node, std::string file, std::string path);

  // --- structure -----------------------------------------------------------
  bool is_map() const { return node_.IsMap(); }
  bool is_sequence() const { return node_.IsSequence(); }
  bool is_scalar() const { return node_.IsScalar(); }
  bool has(std::string_view key) const;
  // Child of a map; missing key -> InputError "missing required key".
  InputNode at(std::string_view key) const;
  std::optional<InputNode> find(std::string_view key) const;
  // Elements of a sequence (error if this is not a sequence).
  std::vector<InputNode> elements() const;
  // Keys of a map in file order (error if this is not a map).
  std::vector<std::string> keys() const;
  // Every key of this map must be one of `allowed`; otherwise InputError
  // listing the allowed keys.
  void allow_only(std::initializer_list<std::string_view> allowed) const;
  void allow_only(const std::vector<std::string>& allowed) const;

  // --- this node's own value -------------------------------------------------
  double as_number() const;                    // finite number
  double as_positive() const;                  // > 0
  double as_non_negative() const;              // >= 0
  // lo <= v <= hi; lo_open / hi_open make that bound strict.
  double as_in_range(double lo, double hi, bool lo_open = false, bool hi_open = false) const;
  long as_integer() const;
  // A whole number with lo <= v <= hi ("expected a whole number in [lo, hi]").
  long as_integer_in_range(long lo, long hi) const;
  bool as_bool() const;
  std::string as_string() const;
  std::vector<double> as_numbers() const;      // a sequence of finite numbers

  // --- shorthands on a child key -----------------------------------------------
  double number(std::string_view key) const { return at(key).as_number(); }
  double positive(std::string_view key) const { return at(key).as_positive(); }
  double non_negative(std::string_view key) const { return at(key).as_non_negative(); }
  double in_range(std::string_view key, double lo, double hi, bool lo_open = false,
                  bool hi_open = false) const {
    return at(key).as_in_range(lo, hi, lo_open, hi_open);
  }
  long integer_in_range(std::string_view key, long lo, long hi) const { return at(key).as_integer_in_range(lo, hi); }
  std::string string(std::string_view key) const { return at(key).as_string(); }
  double number_or(std::string_view key, double fallback) const;
  std::string string_or(std::string_view key, const std::string& fallback) const;
  // One of `choices` (fails with "expected 'a', 'b' or 'c' (got 'x')").
  std::string as_choice(std::initializer_list<std::string_view> choices) const;
  std::string choice_or(std::string_view key, const std::string& fallback,
                        std::initializer_list<std::string_view> choices) const;
  // The scalar as the path of an existing regular file, relative paths taken
  // from `base_dir` (the folder of the file being read); fails naming the
  // value and the path looked for.
  std::string as_existing_file(const std::string& base_dir) const;

  // --- reporting ---------------------------------------------------------------
  // "file:line" of this node.
  std::string where() const;
  int line() const;  // 1-based; 0 when unknown
  const std::string& file() const { return file_; }
  const std::string& path() const { return path_; }
  // Throw InputError "file:line: key 'path': <what>".
  [[noreturn]] void fail(std::string_view what) const;
  // Raw scalar text, for messages.
  std::string text() const;
  const YAML::Node& raw() const { return node_; }

 private:
  std::string child_path(std::string_view key) const;
  YAML::Node node_;
  std::string file_;
  std::string path_;
  int parent_line_ = 0;
  friend class InputNodeAccess;
};

// Format a number for messages the way a user typed it (shortest round trip).
std::string format_number(double v);

}  // namespace railsim::config
