// Charts: the JSON description and the PNG are produced (PNG signature checked).
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "results/chart.hpp"
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
