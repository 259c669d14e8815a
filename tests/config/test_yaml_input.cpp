// Checked YAML input: every error names file, line and key and the allowed range.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "config/yaml_input.hpp"

using railsim::InputError;
using railsim::config::InputNode;

namespace {
std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST_CASE("negative load names file, line, key and range", "[config]") {
  const auto doc = InputNode::load_string("material:\n  E: 2.1e11\ncases:\n  - id: c1\n    Fz: -3\n", "cases.yaml");
  const auto cases = doc.at("cases").elements();
  const std::string msg = error_of([&] { cases[0].positive("Fz"); });
  CHECK(msg == "cases.yaml:5: key 'cases[0].Fz': expected a positive number (got -3)");
}

TEST_CASE("missing key and unknown key are errors", "[config]") {
  const auto doc = InputNode::load_string("material:\n  E: 2.1e11\n  nuu: 0.3\n", "m.yaml");
  const auto mat = doc.at("material");
  CHECK(error_of([&] { mat.number("nu"); }) == "m.yaml:2: key 'material': missing required key 'nu'");
  const std::string unknown = error_of([&] { mat.allow_only({"E", "nu", "mu"}); });
  CHECK(unknown.find("m.yaml:3: key 'material.nuu': unknown key (allowed here: E, nu, mu)") == 0);
}

TEST_CASE("ranges, NaN and non-numbers are refused", "[config]") {
  const auto doc = InputNode::load_string("nu: 0.7\nxi: .nan\nphi: abc\nk: 0.5\n", "x.yaml");
  CHECK(error_of([&] { doc.in_range("nu", 0.0, 0.5, true, false); }) ==
        "x.yaml:1: key 'nu': expected a number in (0, 0.5] (got 0.7)");
  CHECK(error_of([&] { doc.number("xi"); }) == "x.yaml:2: key 'xi': expected a finite number (got '.nan')");
  CHECK(error_of([&] { doc.number("phi"); }) == "x.yaml:3: key 'phi': expected a finite number (got 'abc')");
  CHECK(doc.in_range("k", 0.0, 1.0) == Approx(0.5));
}

TEST_CASE("YAML syntax errors carry the line", "[config]") {
  const std::string msg = error_of([] { InputNode::load_string("a: 1\nb: [1, 2\n", "bad.yaml"); });
  CHECK(msg.rfind("bad.yaml:", 0) == 0);
  CHECK(msg.find("YAML syntax error") != std::string::npos);
}

TEST_CASE("a second YAML document is an error naming its line, not ignored", "[config]") {
  const std::string msg = error_of([] { InputNode::load_string("a: 1\nb: 2\n---\nc: 3\n", "two.yaml"); });
  CHECK(msg.rfind("two.yaml:4: a second YAML document", 0) == 0);
  // One document, with or without its markers, is fine.
  CHECK(InputNode::load_string("---\na: 1\n...\n", "one.yaml").number("a") == 1.0);
  CHECK(InputNode::load_string("a: 1\n", "one.yaml").number("a") == 1.0);
}

TEST_CASE("missing file is an input error", "[config]") {
  CHECK(error_of([] { InputNode::load_file("/nonexistent/file.yaml"); }).find("cannot open") != std::string::npos);
}

TEST_CASE("a key given twice is an error naming both lines, in maps at any depth", "[config]") {
  CHECK(error_of([] { InputNode::load_string("a: 1\nb: 2\na: 3\n", "d.yaml"); }) ==
        "d.yaml:3: key 'a': given twice (first on line 1); give each key once");
  CHECK(error_of([] { InputNode::load_string("m:\n  x: 1\n  y: 2\n  x: 1\n", "d.yaml"); }) ==
        "d.yaml:4: key 'm.x': given twice (first on line 2); give each key once");
  CHECK(error_of([] { InputNode::load_string("l:\n  - {k: 1, k: 2}\n", "d.yaml"); }) ==
        "d.yaml:2: key 'l[0].k': given twice (first on line 2); give each key once");
  // The same key in two different maps is fine.
  CHECK(error_of([] { InputNode::load_string("a: {k: 1}\nb: {k: 2}\n", "d.yaml"); }).empty());
}

TEST_CASE("messages quote at most one shortened line of the input", "[config]") {
  const std::string junk(5000, 'x');
  const std::string msg = error_of([&] { InputNode::load_string("v: " + junk + "\n", "j.yaml").number("v"); });
  CHECK(msg == "j.yaml:1: key 'v': expected a finite number (got '" + std::string(80, 'x') + "...')");
  const std::string root = error_of([&] { InputNode::load_string(junk, "j.yaml").at("k"); });
  CHECK(root.size() < 200);
  CHECK(root.find("...") != std::string::npos);
}

TEST_CASE("choices: one of a list, the list and the value in the message", "[config]") {
  const auto doc = InputNode::load_string("model: lateral\nroll: kinematc\n", "s.yaml");
  CHECK(doc.at("model").as_choice({"lateral", "full"}) == "lateral");
  CHECK(doc.choice_or("start", "equilibrium", {"equilibrium", "nominal"}) == "equilibrium");
  CHECK(error_of([&] { doc.choice_or("roll", "none", {"kinematic", "none"}); }) ==
        "s.yaml:2: key 'roll': expected 'kinematic' or 'none' (got 'kinematc')");
  CHECK(error_of([&] { doc.at("model").as_choice({"a", "b", "c"}); }) ==
        "s.yaml:1: key 'model': expected 'a', 'b' or 'c' (got 'lateral')");
}

TEST_CASE("a file named in YAML resolves against the reader's folder or names where it looked", "[config]") {
  const std::string dir = std::filesystem::temp_directory_path().string() + "/railsim_yaml_file_test";
  std::filesystem::create_directories(dir);
  { std::ofstream(dir + "/t.yaml") << "x: 1\n"; }
  const auto doc = InputNode::load_string("track: t.yaml\nabs: " + dir + "/t.yaml\nmissing: no.yaml\ndir: .\n",
                                          dir + "/s.yaml");
  CHECK(doc.at("track").as_existing_file(dir) == dir + "/t.yaml");
  CHECK(doc.at("abs").as_existing_file("/elsewhere") == dir + "/t.yaml");
  const std::string m = error_of([&] { doc.at("missing").as_existing_file(dir); });
  CHECK(m.find("s.yaml:3: key 'missing': file 'no.yaml' not found (looked for " + dir + "/no.yaml") != std::string::npos);
  // A folder is not a file, and the message says it is a folder (not "not found").
  CHECK(error_of([&] { doc.at("dir").as_existing_file(dir); }).find("key 'dir': '.' is a folder; expected a file") !=
        std::string::npos);
}
