// `railsim geometry` and `railsim conicity` through the binary (cli/cmd_geometry.cpp, cli/cmd_conicity.cpp).
#include <catch2/catch.hpp>

#include "results/csv_writer.hpp"
#include "test_support.hpp"

using namespace railsim;

TEST_CASE("railsim geometry writes the contact table", "[geometry][cli]") {
  const std::string dir = test::temp_dir("cmd_geometry");
  const auto r = test::run_railsim("geometry --wheel S1002 --rail UIC60 --inclination 1/40 --y-min -0.008 --y-max 0.008 "
                                   "--y-step 0.0005 --cache-dir " + dir + " --out " + dir + "/t.csv");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const auto t = results::read_csv(dir + "/t.csv");
  CHECK(t.rows.size() == 33);
  for (const char* c : {"y", "roll", "left_n", "left_y_rail", "left_radius", "left_angle", "left_A", "left_B", "right_n",
                        "right_y_rail", "right_radius", "right_angle", "right_A", "right_B", "left2_radius", "right2_angle"})
    CHECK_NOTHROW(t.column(c));
  CHECK_THAT(r.output, Catch::Contains("flange contact (angle > 30 deg): left wheel from y = +"));
  // A flange-back spacing that keeps the flanges off the rails within the table: said so (it printed "+nan mm").
  const auto wide = test::run_railsim("geometry --flange-back 1.33 --y-min -0.008 --y-max 0.008 --y-step 0.0005 "
                                      "--cache-dir " + dir + " --out " + dir + "/w.csv");
  INFO(wide.output);
  REQUIRE(wide.exit_code == 0);
  CHECK_THAT(wide.output, Catch::Contains("left wheel none up to y = +8.0 mm, right wheel none up to y = -8.0 mm"));
  CHECK_THAT(wide.output, !Catch::Contains("nan"));
}

TEST_CASE("railsim conicity prints 1..6 mm", "[geometry][cli]") {
  const std::string dir = test::temp_dir("cmd_conicity");
  const auto r = test::run_railsim("conicity --cache-dir " + dir + " --out " + dir + "/dr.csv");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  for (const char* a : {"\n1,", "\n2,", "\n3,", "\n4,", "\n5,", "\n6,"}) CHECK_THAT(r.output, Catch::Contains(a));
  CHECK(results::read_csv(dir + "/dr.csv").rows.size() == 241);
}

TEST_CASE("Geometry commands exit 2 on bad input", "[geometry][cli][errors]") {
  const std::string dir = test::temp_dir("cmd_geometry_bad");
  const std::string out = " --no-cache --out " + dir + "/x.csv";
  auto bad = [&](const std::string& args, const std::string& text) {
    const auto r = test::run_railsim("geometry " + args + out);
    INFO(args << " -> " << r.output);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.output, Catch::Contains(text));
  };
  bad("--rail " + test::data_path("contact_geometry/unsorted.csv"), "not sorted");
  bad("--rail nosuch_rail", "cannot open");
  bad("--inclination 1/0", "--inclination");
  bad("--y-max 0.2", "y range");
  bad("--y-min -0.045 --y-max 0.045 --y-step 0.005", "flange climbing");
  bad("--gauge 5", "gauge");
}
