// Checked reading of YAML input files; see yaml_input.hpp.
#include "config/yaml_input.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <vector>

#include <yaml-cpp/depthguard.h>

#include "core/input_file.hpp"

namespace railsim::config {

namespace {

int mark_line(const YAML::Node& n) {
  if (!n.IsDefined()) return 0;
  const YAML::Mark m = n.Mark();
  return m.line >= 0 ? m.line + 1 : 0;
}

// Largest number of nodes walked by the duplicate-key check (aliases can make
// a small file a huge tree: "billion laughs").
constexpr std::size_t kMaxNodes = 2000000;

// A key given twice in one mapping is an error: yaml-cpp keeps both pairs and
// lookups find the first one, silently ignoring the second.
void refuse_duplicate_keys(const YAML::Node& root, const std::string& name) {
  std::vector<std::pair<YAML::Node, std::string>> todo{{root, ""}};
  std::size_t seen = 0;
  while (!todo.empty()) {
    auto [n, path] = todo.back();
    todo.pop_back();
    if (++seen > kMaxNodes)
      throw InputError(name + ": more than " + std::to_string(kMaxNodes) +
                       " YAML nodes (aliases expanding without bound?)");
    if (n.IsSequence()) {
      for (std::size_t i = 0; i < n.size(); ++i) todo.emplace_back(n[i], path + "[" + std::to_string(i) + "]");
    } else if (n.IsMap()) {
      std::map<std::string, int> lines;
      for (const auto& kv : n) {
        const std::string k = kv.first.IsScalar() ? kv.first.Scalar() : std::string("(complex key)");
        const int line = mark_line(kv.first);
        const std::string key = path.empty() ? k : path + "." + k;
        const auto [it, fresh] = lines.emplace(k, line);
        if (!fresh)
          throw InputError(name + ":" + std::to_string(line) + ": key '" + quote_input(key) +
                           "': given twice (first on line " + std::to_string(it->second) +
                           "); give each key once");
        todo.emplace_back(kv.second, key);
      }
    }
  }
}

}  // namespace

std::string format_number(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.15g", v);
  return buf;
}

InputNode::InputNode(YAML::Node node, std::string file, std::string path)
    : node_(std::move(node)), file_(std::move(file)), path_(std::move(path)) {}

InputNode InputNode::load_file(const std::string& path) {
  return load_string(read_input_file(path, "YAML input"), path);
}

InputNode InputNode::load_string(const std::string& text, const std::string& name) {
  try {
    // One document per file: a second one ("---" then more) would be ignored silently.
    const std::vector<YAML::Node> docs = YAML::LoadAll(text);
    if (docs.size() > 1) {
      const int l = docs[1].Mark().line;
      throw InputError(name + ":" + std::to_string(l >= 0 ? l + 1 : 1) + ": a second YAML document ('---'): a " +
                       "railsim input file holds one; remove it or merge its keys into the first");
    }
    YAML::Node root = docs.empty() ? YAML::Node() : docs[0];
    if (!root.IsDefined() || root.IsNull())
      throw InputError(name + ":1: the file is empty (expected a YAML mapping)");
    refuse_duplicate_keys(root, name);
    return InputNode(root, name, "");
  } catch (const YAML::DeepRecursion& e) {
    throw InputError(name + ":" + std::to_string(e.mark.line + 1) +
                     ": YAML nested too deeply (" + std::to_string(e.depth()) + " levels; yaml-cpp accepts fewer)");
  } catch (const YAML::Exception& e) {
    throw InputError(name + ":" + std::to_string(e.mark.line + 1) + ": YAML syntax error: " + quote_input(e.msg));
  }
}

int InputNode::line() const {
  const int l = mark_line(node_);
  return l > 0 ? l : parent_line_;
}

std::string InputNode::where() const { return file_ + ":" + std::to_string(line()); }

void InputNode::fail(std::string_view what) const {
  std::string msg = where() + ": ";
  if (!path_.empty()) msg += "key '" + path_ + "': ";
  msg += what;
  throw InputError(msg);
}

std::string InputNode::text() const {
  if (node_.IsScalar()) return quote_input(node_.Scalar());
  if (node_.IsSequence()) return "a list";
  if (node_.IsMap()) return "a mapping";
  return "nothing";
}

std::string InputNode::child_path(std::string_view key) const {
  if (path_.empty()) return std::string(key);
  return path_ + "." + std::string(key);
}

bool InputNode::has(std::string_view key) const {
  return node_.IsMap() && node_[std::string(key)].IsDefined();
}

std::optional<InputNode> InputNode::find(std::string_view key) const {
  if (!node_.IsMap()) {
    if (node_.IsNull() || !node_.IsDefined()) return std::nullopt;
    fail("expected a mapping with key '" + std::string(key) + "' (got " + text() + ")");
  }
  YAML::Node child = node_[std::string(key)];
  if (!child.IsDefined()) return std::nullopt;
  InputNode out(child, file_, child_path(key));
  out.parent_line_ = line();
  return out;
}

InputNode InputNode::at(std::string_view key) const {
  auto child = find(key);
  if (!child) fail("missing required key '" + std::string(key) + "'");
  if (child->node_.IsNull()) child->fail("has no value");
  return *child;
}

std::vector<InputNode> InputNode::elements() const {
  if (!node_.IsSequence()) fail("expected a list (got " + text() + ")");
  std::vector<InputNode> out;
  out.reserve(node_.size());
  for (std::size_t i = 0; i < node_.size(); ++i) {
    InputNode child(node_[i], file_, path_ + "[" + std::to_string(i) + "]");
    child.parent_line_ = line();
    out.push_back(std::move(child));
  }
  return out;
}

std::vector<std::string> InputNode::keys() const {
  if (!node_.IsMap()) fail("expected a mapping (got " + text() + ")");
  std::vector<std::string> out;
  for (const auto& kv : node_) out.push_back(kv.first.as<std::string>());
  return out;
}

void InputNode::allow_only(const std::vector<std::string>& allowed) const {
  if (!node_.IsMap()) fail("expected a mapping (got " + text() + ")");
  for (const auto& kv : node_) {
    const std::string k = kv.first.IsScalar() ? kv.first.Scalar() : std::string("(complex key)");
    bool ok = false;
    for (const auto& a : allowed) ok = ok || (a == k);
    if (!ok) {
      std::string list;
      for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
      InputNode bad(kv.second, file_, child_path(quote_input(k)));
      bad.parent_line_ = mark_line(kv.first);
      if (bad.line() == 0) bad.parent_line_ = line();
      bad.fail("unknown key (allowed here: " + list + ")");
    }
  }
}

void InputNode::allow_only(std::initializer_list<std::string_view> allowed) const {
  std::vector<std::string> v;
  for (auto a : allowed) v.emplace_back(a);
  allow_only(v);
}

double InputNode::as_number() const {
  if (!node_.IsScalar()) fail("expected a number (got " + text() + ")");
  const std::string& s = node_.Scalar();
  double v = 0.0;
  std::size_t used = 0;
  try {
    v = std::stod(s, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  // YAML spellings of NaN and infinity are refused too: inputs must be finite.
  if (used == 0 || used != s.size() || !std::isfinite(v))
    fail("expected a finite number (got '" + quote_input(s) + "')");
  return v;
}

double InputNode::as_positive() const {
  const double v = as_number();
  if (!(v > 0.0)) fail("expected a positive number (got " + format_number(v) + ")");
  return v;
}

double InputNode::as_non_negative() const {
  const double v = as_number();
  if (!(v >= 0.0)) fail("expected a non-negative number (got " + format_number(v) + ")");
  return v;
}

double InputNode::as_in_range(double lo, double hi, bool lo_open, bool hi_open) const {
  const double v = as_number();
  const bool ok = (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
  if (!ok) {
    const std::string range = std::string(lo_open ? "(" : "[") + format_number(lo) + ", " +
                              format_number(hi) + (hi_open ? ")" : "]");
    fail("expected a number in " + range + " (got " + format_number(v) + ")");
  }
  return v;
}

long InputNode::as_integer() const {
  const double v = as_number();
  if (std::floor(v) != v || std::fabs(v) > 9.0e15) fail("expected a whole number (got " + text() + ")");
  return static_cast<long>(v);
}

long InputNode::as_integer_in_range(long lo, long hi) const {
  const double v = as_number();
  if (std::floor(v) != v || v < static_cast<double>(lo) || v > static_cast<double>(hi))
    fail("expected a whole number in [" + std::to_string(lo) + ", " + std::to_string(hi) + "] (got " + text() + ")");
  return static_cast<long>(v);
}

bool InputNode::as_bool() const {
  if (node_.IsScalar()) {
    const std::string& s = node_.Scalar();
    if (s == "true" || s == "yes" || s == "on") return true;
    if (s == "false" || s == "no" || s == "off") return false;
  }
  fail("expected true or false (got " + text() + ")");
}

std::string InputNode::as_string() const {
  if (!node_.IsScalar()) fail("expected a text value (got " + text() + ")");
  return node_.Scalar();
}

std::vector<double> InputNode::as_numbers() const {
  std::vector<double> out;
  for (const auto& e : elements()) out.push_back(e.as_number());
  return out;
}

double InputNode::number_or(std::string_view key, double fallback) const {
  auto c = find(key);
  return c ? c->as_number() : fallback;
}

std::string InputNode::string_or(std::string_view key, const std::string& fallback) const {
  auto c = find(key);
  return c ? c->as_string() : fallback;
}

std::string InputNode::as_choice(std::initializer_list<std::string_view> choices) const {
  const std::string v = as_string();
  std::string list;
  std::size_t i = 0;
  for (const auto c : choices) {
    if (v == c) return v;
    list += (i == 0 ? "" : (i + 1 == choices.size() ? " or " : ", ")) + ("'" + std::string(c) + "'");
    ++i;
  }
  fail("expected " + list + " (got '" + v + "')");
}

std::string InputNode::choice_or(std::string_view key, const std::string& fallback,
                                 std::initializer_list<std::string_view> choices) const {
  auto c = find(key);
  return c ? c->as_choice(choices) : fallback;
}

std::string InputNode::as_existing_file(const std::string& base_dir) const {
  const std::string v = as_string();
  std::string path = v;
  if (!v.empty() && !std::filesystem::path(v).is_absolute() && !base_dir.empty())
    path = (std::filesystem::path(base_dir) / v).lexically_normal().string();
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    fail("'" + v + "' is a folder; expected a file" +
         (path != v ? " (" + path + ", relative to the folder of " + file_ + ")" : std::string()));
  if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
    fail("'" + v + "' is not a regular file (a device or a pipe); expected a file");
  if (!std::filesystem::is_regular_file(path, ec))
    fail("file '" + v + "' not found" +
         (path != v ? " (looked for " + path + ", relative to the folder of " + file_ + ")" : std::string()));
  return path;
}

}  // namespace railsim::config
