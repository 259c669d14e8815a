// Fuzzing the YAML readers with random mutations of the shipped files: every
// mutated scenario, vehicle and track either loads or throws railsim's
// InputError (exit 2 in the program); never a crash, another exception type
// (exit 1) or a hang.
//
// Mutations (fixed seed, so a failure replays): delete a line, duplicate a
// line, swap two neighbouring characters, replace a number by nan, inf, -inf,
// 1e300, -1, 0, 1e-300 or text, insert a YAML control character, truncate.
// RAILSIM_FUZZ_COUNT (mutations per file) and RAILSIM_FUZZ_SEED explore further.
// The mutated text is written to a temporary folder with the shipped files'
// relative references ("../vehicles/...") made absolute, so that a reference
// still resolves. Scenarios with a profiles geometry are left out: a mutated
// grid would build a new strip table (minutes), which its own tests cover.
#include <catch2/catch.hpp>
#include <spdlog/spdlog.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <regex>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "engine/model.hpp"
#include "engine/io/scenario.hpp"
#include "engine/io/vehicle_file.hpp"
#include "test_support.hpp"
#include "track/track_file.hpp"

using namespace railsim;

namespace {

enum class Kind { scenario, vehicle, track };

struct Mutation {
  std::string text, what;
};

std::vector<std::string> split_lines(const std::string& s) {
  std::vector<std::string> lines;
  std::size_t at = 0;
  while (at < s.size()) {
    const std::size_t nl = s.find('\n', at);
    const std::size_t end = nl == std::string::npos ? s.size() : nl;
    lines.push_back(s.substr(at, end - at));
    at = end + 1;
  }
  return lines;
}

std::string join_lines(const std::vector<std::string>& lines) {
  std::string s;
  for (const auto& l : lines) s += l + "\n";
  return s;
}

Mutation mutate(const std::string& text, std::mt19937& rng) {
  auto pick = [&](std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng); };
  std::vector<std::string> lines = split_lines(text);
  switch (pick(6)) {
    case 0: {  // delete a line
      const std::size_t i = pick(lines.size());
      const std::string what = "delete line " + std::to_string(i + 1);
      lines.erase(lines.begin() + static_cast<long>(i));
      return {join_lines(lines), what};
    }
    case 1: {  // duplicate a line
      const std::size_t i = pick(lines.size());
      lines.insert(lines.begin() + static_cast<long>(i), lines[i]);
      return {join_lines(lines), "duplicate line " + std::to_string(i + 1)};
    }
    case 2: {  // swap two neighbouring characters
      std::string s = text;
      const std::size_t i = pick(s.size() - 1);
      std::swap(s[i], s[i + 1]);
      return {s, "swap characters " + std::to_string(i) + ", " + std::to_string(i + 1)};
    }
    case 3: {  // replace a number
      static const std::regex number(R"([-+]?[0-9]+\.?[0-9]*([eE][-+]?[0-9]+)?)");
      std::vector<std::pair<std::size_t, std::size_t>> spans;
      for (auto it = std::sregex_iterator(text.begin(), text.end(), number); it != std::sregex_iterator(); ++it)
        spans.emplace_back(static_cast<std::size_t>(it->position()), static_cast<std::size_t>(it->length()));
      if (spans.empty()) break;
      static const char* const values[] = {"nan", "inf", "-inf", "1e300", "-1", "0", "1e-300", "text", ".nan", "~"};
      const auto [at, len] = spans[pick(spans.size())];
      const std::string v = values[pick(std::size(values))];
      std::string s = text;
      s.replace(at, len, v);
      return {s, "number at " + std::to_string(at) + " '" + text.substr(at, len) + "' -> " + v};
    }
    case 4: {  // insert a YAML control character
      static const char controls[] = {':', '-', '[', ']', '{', '}', '#', '&', '*', '!', '|', '>', '"', '\'', '\t', ','};
      std::string s = text;
      const std::size_t i = pick(s.size());
      const char c = controls[pick(sizeof controls)];
      s.insert(s.begin() + static_cast<long>(i), c);
      return {s, std::string("insert '") + c + "' at " + std::to_string(i)};
    }
    default:
      break;
  }
  const std::size_t cut = pick(text.size());  // truncate
  return {text.substr(0, cut), "truncate at " + std::to_string(cut)};
}

// The shipped file's text with its relative references made absolute.
std::string with_absolute_references(const std::string& text) {
  std::string s = text;
  for (const char* folder : {"vehicles/", "tracks/", "scenarios/"}) {
    const std::string rel = std::string("../") + folder, abs = test::source_path(folder);
    for (std::size_t at = s.find(rel); at != std::string::npos; at = s.find(rel, at + abs.size()))
      s.replace(at, rel.size(), abs);
  }
  return s;
}

void load(Kind kind, const std::string& path) {
  switch (kind) {
    case Kind::scenario:
      (void)engine::load_scenario(path);
      break;
    case Kind::vehicle: {
      engine::Model m;
      engine::load_vehicle(path, m);
      break;
    }
    case Kind::track:
      (void)track::load_track(path);
      break;
  }
}

}  // namespace

TEST_CASE("mutated scenario, vehicle and track files load or give InputError, never another failure",
          "[fuzz][bad_input]") {
  const std::vector<std::pair<Kind, std::string>> files = {
      {Kind::scenario, "scenarios/single_wheelset.yaml"},
      {Kind::scenario, "scenarios/bogie.yaml"},
      {Kind::scenario, "scenarios/manchester_coach.yaml"},
      {Kind::scenario, "scenarios/cooperrider_car.yaml"},
      {Kind::scenario, "scenarios/manchester_coach_derailment.yaml"},
      {Kind::vehicle, "vehicles/single_wheelset.yaml"},
      {Kind::vehicle, "vehicles/bogie.yaml"},
      {Kind::vehicle, "vehicles/manchester_coach.yaml"},
      {Kind::vehicle, "vehicles/cooperrider_car.yaml"},
      {Kind::track, "tracks/curve_R300.yaml"},
      {Kind::track, "tracks/curve_R1000.yaml"},
      {Kind::track, "tracks/curve_twist_R500.yaml"},
      {Kind::track, "tracks/curve_twist.yaml"},
      {Kind::track, "tracks/straight_lateral_defect.yaml"},
      {Kind::track, "tracks/straight_erri_low.yaml"},
  };
  // 900 mutations, about 5 s; RAILSIM_FUZZ_COUNT and RAILSIM_FUZZ_SEED for a longer exploration.
  const char* count_env = std::getenv("RAILSIM_FUZZ_COUNT");
  const char* seed_env = std::getenv("RAILSIM_FUZZ_SEED");
  const int kPerFile = count_env ? std::atoi(count_env) : 60;
  const auto level = spdlog::get_level();
  spdlog::set_level(spdlog::level::err);  // the readers' info lines, 900 times
  const std::string dir = test::temp_dir("input_fuzz");
  std::mt19937 rng(seed_env ? static_cast<unsigned>(std::strtoul(seed_env, nullptr, 10)) : 20261202u);
  int loaded = 0, refused = 0;
  double slowest = 0.0;
  std::string slowest_what;
  for (const auto& [kind, rel] : files) {
    const std::string original = with_absolute_references(test::read_text(test::source_path(rel)));
    REQUIRE_FALSE(original.empty());
    const std::string path = dir + "/" + std::filesystem::path(rel).filename().string();
    for (int k = 0; k < kPerFile; ++k) {
      const Mutation mu = mutate(original, rng);
      std::ofstream(path, std::ios::binary | std::ios::trunc) << mu.text;
      INFO(rel << ": mutation " << k << ": " << mu.what);
      const auto t0 = std::chrono::steady_clock::now();
      std::string other;
      try {
        load(kind, path);
        ++loaded;
      } catch (const InputError& e) {
        ++refused;
        const std::string m = e.what();
        CHECK(m.size() < 2000);  // a message, not an echo of the file
      } catch (const std::exception& e) {
        other = e.what();
      } catch (...) {
        other = "an exception not derived from std::exception";
      }
      CHECK(other == "");
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      if (s > slowest) slowest = s, slowest_what = rel + ": " + mu.what;
    }
  }
  INFO("slowest: " << slowest << " s (" << slowest_what << ")");
  CHECK(slowest < 10.0);  // no mutation may make a reader run away
  CHECK(loaded + refused == static_cast<int>(files.size()) * kPerFile);
  CHECK(refused > 0);
  CHECK(loaded > 0);  // some mutations are harmless (comments, a swapped digit): both paths are exercised
  spdlog::set_level(level);
  WARN("input fuzz: " << loaded << " loaded, " << refused << " refused; slowest " << slowest << " s ("
                      << slowest_what << ")");
}
