// Scenario overrides from the command line; see support_scenario_overrides.hpp.
#include "cli/support_scenario_overrides.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "core/errors.hpp"

namespace railsim::cli {

namespace {

bool is_index(const std::string& c) { return c.size() >= 3 && c.front() == '[' && c.back() == ']'; }

std::vector<std::string> split_path(const std::string& option, const std::string& key) {
  std::vector<std::string> out;
  std::string cur;
  std::size_t i = 0;
  auto bad = [&](const std::string& why) { throw InputError(option + ": " + why); };
  while (i < key.size()) {
    const char c = key[i];
    if (c == '.') {
      if (cur.empty() && (out.empty() || !is_index(out.back()))) bad("empty key component in '" + key + "'");
      if (!cur.empty()) out.push_back(cur);
      cur.clear();
      ++i;
    } else if (c == '[') {
      if (!cur.empty()) out.push_back(cur);
      cur.clear();
      const std::size_t j = key.find(']', i);
      if (j == std::string::npos) bad("unclosed '[' in '" + key + "'");
      const std::string inner = key.substr(i + 1, j - i - 1);
      if (inner.empty()) bad("empty [] in '" + key + "'");
      bool digits = true;
      for (char d : inner) digits = digits && std::isdigit(static_cast<unsigned char>(d));
      out.push_back(digits ? "[" + inner + "]" : inner);
      i = j + 1;
    } else {
      cur += c;
      ++i;
    }
  }
  if (!cur.empty()) out.push_back(cur);
  if (out.empty()) bad("empty key");
  return out;
}

std::string reader_path(const std::vector<std::string>& path) {
  std::string p;
  for (const auto& c : path) {
    if (is_index(c)) p += c;
    else p += (p.empty() ? "" : ".") + c;
  }
  return p;
}

std::string prefix_text(const std::vector<std::string>& path, std::size_t n) {
  return reader_path(std::vector<std::string>(path.begin(), path.begin() + static_cast<std::ptrdiff_t>(n)));
}

// How many times `node` (by identity) appears in the tree under `root`: more
// than once when the file shares it through a YAML anchor and aliases.
int occurrences(const YAML::Node& root, const YAML::Node& node) {
  if (root.is(node)) return 1;
  int n = 0;
  if (root.IsMap())
    for (const auto& kv : root) n += occurrences(kv.second, node);
  else if (root.IsSequence())
    for (const auto& v : root) n += occurrences(v, node);
  return n;
}

// Whether a node on the override's path (or the node it replaces) is shared
// through an alias: editing it in place would edit every alias of the anchor.
bool path_is_shared(const YAML::Node& root, const std::vector<std::string>& path) {
  YAML::Node cur;
  cur.reset(root);
  for (const std::string& c : path) {
    YAML::Node next;
    if (is_index(c) && cur.IsSequence()) {
      const std::size_t idx = std::stoul(c.substr(1, c.size() - 2));
      if (idx >= cur.size()) return false;
      next.reset(cur[idx]);
    } else if (!is_index(c) && cur.IsMap() && cur[c].IsDefined()) {
      next.reset(cur[c]);
    } else {
      return false;
    }
    if (occurrences(root, next) > 1) return true;
    cur.reset(next);
  }
  return false;
}

// The tree with the path's containers copied (one level each, children
// shared) and the copies linked: the same tree for the reader, but the path
// no longer runs through a node an alias shares. yaml-cpp's assignment to an
// existing node rebinds that node everywhere it appears, so the copies are
// built fresh and filled key by key. The copies lose their own positions;
// every other node keeps its.
YAML::Node unshare_path(const YAML::Node& node, const std::vector<std::string>& path, std::size_t k) {
  if (k == path.size() || !(node.IsMap() || node.IsSequence())) return node;
  const std::string& c = path[k];
  if (node.IsSequence()) {
    if (!is_index(c)) return node;
    const std::size_t idx = std::stoul(c.substr(1, c.size() - 2));
    YAML::Node copy(YAML::NodeType::Sequence);
    for (std::size_t i = 0; i < node.size(); ++i) {
      if (i != idx) {
        copy.push_back(node[i]);
        continue;
      }
      // A node of the copy's own (assigning to a handle would move the handle
      // onto the shared node): assigning through the sequence rebinds only it,
      // and so does the edit later.
      copy.push_back(YAML::Node(YAML::NodeType::Null));
      copy[copy.size() - 1] = unshare_path(node[i], path, k + 1);
    }
    return copy;
  }
  YAML::Node copy(YAML::NodeType::Map);
  for (const auto& kv : node) {
    const bool on_path = kv.first.IsScalar() && kv.first.Scalar() == c;
    copy[kv.first] = on_path ? unshare_path(kv.second, path, k + 1) : kv.second;
  }
  return copy;
}

void edit(YAML::Node root, const ScenarioOverride& o);

// The override applied to the tree `root` (edited in place, or, when its
// path runs through an aliased node, rebuilt along the path first).
YAML::Node apply(YAML::Node root, const ScenarioOverride& o) {
  if (path_is_shared(root, o.path)) root = unshare_path(root, o.path, 0);
  edit(root, o);
  return root;
}

void edit(YAML::Node root, const ScenarioOverride& o) {
  YAML::Node value;
  try {
    value = YAML::Load(o.value);
  } catch (const YAML::Exception& e) {
    throw InputError(o.option + ": the value is not valid YAML (" + e.msg + ")");
  }
  if (!value.IsDefined() || value.IsNull()) throw InputError(o.option + ": no value after '='");
  YAML::Node cur;
  cur.reset(root);
  for (std::size_t k = 0; k < o.path.size(); ++k) {
    const std::string& c = o.path[k];
    const bool last = k + 1 == o.path.size();
    if (is_index(c)) {
      if (!cur.IsSequence())
        throw InputError(o.option + ": '" + prefix_text(o.path, k) + "' is not a list, [" + c + "] does not apply");
      const std::size_t idx = std::stoul(c.substr(1, c.size() - 2));
      if (idx >= cur.size())
        throw InputError(o.option + ": '" + prefix_text(o.path, k) + "' has " + std::to_string(cur.size()) +
                         " elements (index 0.." + std::to_string(cur.size() == 0 ? 0 : cur.size() - 1) + ")");
      if (last) {
        cur[idx] = value;
        return;
      }
      YAML::Node next = cur[idx];
      cur.reset(next);
      continue;
    }
    if (!cur.IsMap()) {
      const std::string where = k == 0 ? std::string("the scenario") : "'" + prefix_text(o.path, k) + "'";
      throw InputError(o.option + ": " + where + " is " + (cur.IsScalar() ? "a value ('" + cur.Scalar() + "')" : "a list") +
                       ", not a mapping: set the whole key instead");
    }
    if (last) {
      cur[c] = value;
      if (k == 0 && c == "speed") cur.remove("speed_kmh");
      if (k == 0 && c == "speed_kmh") cur.remove("speed");
      return;
    }
    if (!cur[c].IsDefined() || cur[c].IsNull()) cur[c] = YAML::Node(YAML::NodeType::Map);
    YAML::Node next = cur[c];
    cur.reset(next);
  }
}

}  // namespace

ScenarioOverride parse_set_option(const std::string& text) {
  ScenarioOverride o;
  o.option = "--set " + text;
  const std::size_t eq = text.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError(o.option + ": expected key=value (e.g. --set contact.material.mu=0.2)");
  o.path = split_path(o.option, text.substr(0, eq));
  o.key = reader_path(o.path);
  o.value = text.substr(eq + 1);
  return o;
}

ScenarioOverride speed_kmh_override(double v) {
  ScenarioOverride o;
  o.option = "--speed-kmh " + config::format_number(v);
  o.path = {"speed_kmh"};
  o.key = "speed_kmh";
  o.value = config::format_number(v);
  return o;
}

void rethrow_for_overrides(const InputError& e, const std::vector<ScenarioOverride>& overrides) {
  const std::string msg = e.what();
  for (auto it = overrides.rbegin(); it != overrides.rend(); ++it) {
    const std::string k = "key '" + it->key;
    const std::size_t p = msg.find(k);
    if (p == std::string::npos) continue;
    const char next = p + k.size() < msg.size() ? msg[p + k.size()] : '\0';
    if (next == '\'' || next == '.' || next == '[') throw InputError(it->option + ": " + msg);
  }
  throw e;
}

namespace {

bool is_speed_key(const ScenarioOverride& o) {
  return o.path.size() == 1 && (o.path[0] == "speed" || o.path[0] == "speed_kmh");
}

// Whether path `inner` lies inside (or is) path `outer`.
bool path_within(const std::vector<std::string>& inner, const std::vector<std::string>& outer) {
  return inner.size() >= outer.size() && std::equal(outer.begin(), outer.end(), inner.begin());
}

}  // namespace

void check_overrides_agree(const std::vector<ScenarioOverride>& overrides) {
  for (std::size_t i = 0; i < overrides.size(); ++i) {
    for (std::size_t j = i + 1; j < overrides.size(); ++j) {
      const ScenarioOverride& a = overrides[i];
      const ScenarioOverride& b = overrides[j];
      if (is_speed_key(a) && is_speed_key(b)) {
        if (a.path == b.path && a.value == b.value) continue;
        throw InputError(b.option + ": the speed is already set by " + a.option + " (give the speed once)");
      }
      if (a.path == b.path) {
        if (a.value == b.value) continue;
        throw InputError(b.option + ": key '" + b.key + "' is already set to a different value by " + a.option +
                         " (give each key once)");
      }
      if (path_within(b.path, a.path) || path_within(a.path, b.path)) {
        const ScenarioOverride& outer = path_within(b.path, a.path) ? a : b;
        const ScenarioOverride& inner = &outer == &a ? b : a;
        throw InputError(b.option + ": key '" + inner.key + "' lies inside key '" + outer.key + "' set by " +
                         (&outer == &a ? a.option : std::string("this option")) +
                         "; the result would depend on their order (set the inner key in the outer value, or only the "
                         "inner key)");
      }
    }
  }
}

LoadedScenario load_scenario_with_overrides(const std::string& path, const std::vector<ScenarioOverride>& overrides) {
  check_overrides_agree(overrides);
  const config::InputNode original = config::InputNode::load_file(path);
  // The overrides edit the parsed tree in place (no YAML::Clone: a clone loses
  // the nodes' file positions, and every message would say line 1).
  YAML::Node root = original.raw();
  for (const auto& o : overrides) root = apply(root, o);
  config::InputNode node(root, path, "");
  try {
    engine::Scenario sc = engine::load_scenario(node, std::filesystem::path(path).parent_path().string());
    sc.file = path;
    if (sc.name.empty()) sc.name = std::filesystem::path(path).stem().string();
    return {std::move(sc), node};
  } catch (const InputError& e) {
    rethrow_for_overrides(e, overrides);
  }
}

}  // namespace railsim::cli
