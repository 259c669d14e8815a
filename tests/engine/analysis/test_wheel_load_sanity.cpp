// Wheel loads above ten times static: one warning per wheel at its largest
// load, with the value, the ratio to Q0, time, place and the usual range;
// none at or below the bound; left and right alike.
#include <catch2/catch.hpp>

#include <string>

#include "engine/analysis/wheel_load_sanity.hpp"

using namespace railsim::engine;

namespace {
RunHistory history(const std::vector<double>& left, const std::vector<double>& right) {
  RunHistory h;
  h.time = {0.0, 0.1, 0.2, 0.3};
  h.distance = {100.0, 104.0, 108.0, 112.0};
  WheelsetHistory ws;
  ws.name = "ws2";
  ws.offset = -2.5;
  ws.static_wheel_load = 50e3;
  ws.wheel[0].Q = left;
  ws.wheel[1].Q = right;
  h.wheelsets.push_back(ws);
  return h;
}
bool has(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }
}  // namespace

TEST_CASE("wheel loads above ten times static are warned about, with value, ratio, place and range",
          "[analysis][sanity]") {
  const std::vector<double> high = {50e3, 520e3, 530e3, 60e3};  // 10.6 Q0 at t = 0.2 s
  const std::vector<double> below = {50e3, 499e3, 500e3, 40e3};  // at most exactly 10 Q0: no warning
  for (int mirrored = 0; mirrored < 2; ++mirrored) {
    const RunHistory h = mirrored ? history(below, high) : history(high, below);
    const auto w = wheel_load_warnings(h);
    REQUIRE(w.size() == 1);
    INFO(w[0]);
    CHECK(has(w[0], mirrored ? "ws2 right wheel" : "ws2 left wheel"));
    CHECK(has(w[0], "Q = 530.0 kN at t = 0.2 s, track distance 105.5 m"));  // 108 m - 2.5 m
    CHECK(has(w[0], "10.6 times the static load Q0 = 50.0 kN"));
    CHECK(has(w[0], "usual dynamic loads below about 3 Q0"));
  }
  CHECK(wheel_load_warnings(history(below, below)).empty());
  CHECK(wheel_load_warnings(history(high, high)).size() == 2);
  // No static load known: nothing to compare with.
  RunHistory none = history(high, high);
  none.wheelsets[0].static_wheel_load = 0.0;
  CHECK(wheel_load_warnings(none).empty());
}
