// Charts: the JSON description and the PNG are produced (PNG signature checked).
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "core/errors.hpp"
#include "results/chart.hpp"
#include "json_support.hpp"
#include "test_support.hpp"

using namespace railsim::results;

TEST_CASE("a chart renders to a PNG file next to its JSON description", "[results][chart]") {
  const std::string dir = railsim::test::temp_dir("chart");
  Chart c;
  c.title = "amplitude against speed";
  c.xlabel = "speed [km/h]";
  c.ylabel = "amplitude [mm]";
  c.series.push_back({"down", {100, 150, 200}, {0, 2.5, 4.0}, "line+markers", ""});
  c.lines.push_back({180.0, "linear critical speed", "r", true});
  const std::string png = dir + "/c.png";
  REQUIRE(draw(c, png));
  std::ifstream f(png, std::ios::binary);
  char sig[8] = {};
  f.read(sig, 8);
  CHECK(std::string(sig + 1, 3) == "PNG");
  CHECK(std::filesystem::file_size(png) > 5000);
  CHECK(std::filesystem::exists(png + ".json"));
}

TEST_CASE("a chart with panels renders small multiples", "[results][chart]") {
  const std::string dir = railsim::test::temp_dir("chart_panels");
  Chart c;
  c.title = "failure map";
  c.xlabel = "creepage [-]";
  c.ylabel = "spin [1/m]";
  c.logx = true;
  c.panels = {"model a", "model b", "model c"};
  for (int p = 0; p < 3; ++p) {
    c.series.push_back({p == 0 ? "ok" : "", {1e-4, 1e-3}, {0.0, 1.0}, "markers", "tab:green", p});
    c.series.push_back({p == 0 ? "failed" : "", {1e-2}, {2.0}, "crosses", "tab:red", p});
  }
  c.annotations.push_back({"note", {1e-3, 1.0}});
  c.annotation_panels.push_back(2);
  const std::string png = dir + "/m.png";
  REQUIRE(draw(c, png));
  CHECK(std::filesystem::file_size(png) > 5000);
  const auto spec = railsim::test::read_json(png + ".json");
  CHECK(spec["panels"].is_array());
  CHECK(spec["annotations"][0]["panel"] == 2);
  CHECK(spec["series"].size() == 6);
  CHECK(spec["series"][5]["panel"] == 2);
  CHECK(spec["series"][1]["y"][0].get<double>() == 2.0);
}

TEST_CASE("a PNG that cannot be written (full disk) is an error naming the file, not a warning",
          "[results][chart][write]") {
  if (!std::filesystem::is_character_file("/dev/full")) return;
  const std::string dir = railsim::test::temp_dir("chart_full");
  Chart c;
  c.title = "t";
  c.series.push_back({"s", {1, 2}, {1, 2}, "line", ""});
  // The PNG on a full device (a link to /dev/full); the description beside it is written.
  std::filesystem::create_symlink("/dev/full", dir + "/full.png");
  Chart other = c;
  std::string m;
  try {
    draw_all({{&other, dir + "/ok.png"}, {&c, dir + "/full.png"}});
  } catch (const railsim::InputError& e) {
    m = e.what();
  }
  INFO(m);
  CHECK(m.find(dir + "/full.png: write failed (No space left on device)") != std::string::npos);
  CHECK(std::filesystem::is_character_file("/dev/full"));
  CHECK(std::filesystem::file_size(dir + "/ok.png") > 1000);  // the other chart was rendered
  for (const auto& e : std::filesystem::directory_iterator(dir))  // no temporary left behind
    CHECK(e.path().filename().string().find(".tmp.") == std::string::npos);
  // The description on a full device.
  std::filesystem::create_symlink("/dev/full", dir + "/d.png.json");
  m.clear();
  try {
    draw(c, dir + "/d.png");
  } catch (const railsim::InputError& e) {
    m = e.what();
  }
  CHECK(m.find(dir + "/d.png.json: write failed (No space left on device)") != std::string::npos);
}
