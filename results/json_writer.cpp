// JSON documents through nlohmann-json; see json_writer.hpp.
#include "results/json_writer.hpp"

#include <cmath>
#include <nlohmann/json.hpp>

#include "core/atomic_file.hpp"

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

nlohmann::ordered_json Json::to_nlohmann() const {
  using nlohmann::ordered_json;
  return std::visit(
      [](const auto& v) -> ordered_json {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, std::nullptr_t>) {
          return nullptr;
        } else if constexpr (std::is_same_v<T, double>) {
          return std::isfinite(v) ? ordered_json(v) : ordered_json(nullptr);
        } else if constexpr (std::is_same_v<T, Object>) {
          ordered_json o = ordered_json::object();
          for (const auto& kv : v) o[kv.first] = kv.second.to_nlohmann();
          return o;
        } else if constexpr (std::is_same_v<T, Array>) {
          ordered_json a = ordered_json::array();
          for (const auto& e : v) a.push_back(e.to_nlohmann());
          return a;
        } else {
          return ordered_json(v);
        }
      },
      value_);
}

std::string Json::dump(int indent) const {
  return to_nlohmann().dump(indent > 0 ? indent : -1, ' ', false, nlohmann::ordered_json::error_handler_t::replace) +
         "\n";
}

void Json::write_file(const std::string& path, int indent) const { write_file_atomically(path, dump(indent)); }

}  // namespace railsim::results
