// Minimal JSON document builder; see json_writer.hpp.
#include "results/json_writer.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "core/errors.hpp"

namespace railsim::results {

Json& Json::set(const std::string& key, Json v) {
  if (!std::holds_alternative<Object>(value_)) value_ = Object{};
  auto& obj = std::get<Object>(value_);
  for (auto& kv : obj)
    if (kv.first == key) {
      kv.second = std::move(v);
      return kv.second;
    }
  obj.emplace_back(key, std::move(v));
  return obj.back().second;
}

Json& Json::push(Json v) {
  if (!std::holds_alternative<Array>(value_)) value_ = Array{};
  std::get<Array>(value_).push_back(std::move(v));
  return *this;
}

Json& Json::operator[](const std::string& key) {
  if (std::holds_alternative<Object>(value_))
    for (auto& kv : std::get<Object>(value_))
      if (kv.first == key) return kv.second;
  return set(key, Json::object());
}

namespace {

void escape(std::string& out, const std::string& s) {
  out += '"';
  for (unsigned char c : s) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      case '\r': out += "\\r"; break;
      default:
        if (c < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", c);
          out += buf;
        } else {
          out += static_cast<char>(c);
        }
    }
  }
  out += '"';
}

void newline(std::string& out, int indent, int level) {
  if (indent <= 0) return;
  out += '\n';
  out.append(static_cast<std::size_t>(indent * level), ' ');
}

}  // namespace

void Json::dump_to(std::string& out, int indent, int level) const {
  if (std::holds_alternative<std::nullptr_t>(value_)) {
    out += "null";
  } else if (const double* d = std::get_if<double>(&value_)) {
    if (!std::isfinite(*d)) {
      out += "null";
    } else {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%.12g", *d);
      out += buf;
    }
  } else if (const bool* b = std::get_if<bool>(&value_)) {
    out += *b ? "true" : "false";
  } else if (const std::string* s = std::get_if<std::string>(&value_)) {
    escape(out, *s);
  } else if (const Object* o = std::get_if<Object>(&value_)) {
    out += '{';
    bool first = true;
    for (const auto& kv : *o) {
      if (!first) out += ',';
      first = false;
      newline(out, indent, level + 1);
      escape(out, kv.first);
      out += indent > 0 ? ": " : ":";
      kv.second.dump_to(out, indent, level + 1);
    }
    if (!o->empty()) newline(out, indent, level);
    out += '}';
  } else if (const Array* a = std::get_if<Array>(&value_)) {
    out += '[';
    bool first = true;
    for (const auto& v : *a) {
      if (!first) out += ',';
      first = false;
      newline(out, indent, level + 1);
      v.dump_to(out, indent, level + 1);
    }
    if (!a->empty()) newline(out, indent, level);
    out += ']';
  }
}

std::string Json::dump(int indent) const {
  std::string out;
  dump_to(out, indent, 0);
  out += '\n';
  return out;
}

void Json::write_file(const std::string& path, int indent) const {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream f(tmp, std::ios::binary);
    if (!f) throw InputError(path + ": cannot open for writing");
    f << dump(indent);
    if (!f) throw InputError(path + ": write failed");
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) throw InputError(path + ": cannot rename temporary file: " + ec.message());
}

}  // namespace railsim::results
