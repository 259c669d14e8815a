// Profile reading, validation and spline evaluation (contact/geometry/profile.cpp).
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>

#include "contact/geometry/profile.hpp"
#include "core/errors.hpp"
#include "results/csv_writer.hpp"
#include "test_support.hpp"

using namespace railsim;
using namespace railsim::contact;

namespace {
// Wheel-profile z at lateral y from the spline (bisection on the chord parameter).
double z_at(const Profile& p, double y) {
  double lo = 0.0, hi = p.spline().length();
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (p.spline().eval(mid).y < y ? lo : hi) = mid;
  }
  return p.spline().eval(0.5 * (lo + hi)).z;
}
}  // namespace

TEST_CASE("S1002 file agrees with the analytic Netter definition", "[geometry][profile]") {
  const Profile w = read_profile("S1002", ProfileKind::wheel);
  // Oriented: flange (max z = 28 mm) at y = -55 mm, back face at -70 mm.
  const auto imax = std::max_element(w.z().begin(), w.z().end()) - w.z().begin();
  CHECK(w.y()[static_cast<std::size_t>(imax)] == Approx(-0.055).margin(0.5e-3));
  CHECK(w.z()[static_cast<std::size_t>(imax)] == Approx(0.028).margin(0.01e-3));
  const auto ref = results::read_csv(test::data_path("contact_geometry/s1002_netter.csv"));
  double worst = 0.0;
  for (std::size_t i = 0; i < ref.rows.size(); ++i) {
    const double s = ref.number(i, "s_mm") * 1e-3, F = ref.number(i, "F_mm") * 1e-3;
    if (s < w.y().front() || s > w.y().back()) continue;
    worst = std::max(worst, std::abs(z_at(w, s) - F));
  }
  INFO("largest |F_file - F_Netter| = " << worst * 1e3 << " mm");
  CHECK(worst < 0.02e-3);  // 20 um: digitised file vs analytic definition
}

TEST_CASE("Spline curvature of a sampled circle", "[geometry][profile]") {
  // Circle of radius 0.3 m sampled every 0.5 mm: curvature 1/R, slope exact.
  std::vector<double> y, z;
  const double R = 0.3;
  for (double v = -0.03; v <= 0.03 + 1e-12; v += 0.5e-3) {
    y.push_back(v);
    z.push_back(R - std::sqrt(R * R - v * v));
  }
  const Profile p(ProfileKind::rail, "circle", y, z);
  for (double t : {0.01, 0.03, 0.045}) {
    const CurvePoint c = p.spline().eval(t);
    const double n2 = c.dy * c.dy + c.dz * c.dz;
    const double k = (c.dy * c.ddz - c.dz * c.ddy) / (n2 * std::sqrt(n2));
    CHECK(k == Approx(1.0 / R).epsilon(1e-3));
    CHECK(c.dz / c.dy == Approx(c.y / std::sqrt(R * R - c.y * c.y)).margin(1e-5));
  }
}

TEST_CASE("Bad profiles give InputError with file and line", "[geometry][profile][errors]") {
  auto msg = [](const std::string& file) {
    try {
      read_profile(test::data_path("contact_geometry/" + file), ProfileKind::rail);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  CHECK_THAT(msg("unsorted.csv"), Catch::Contains("unsorted.csv:8") && Catch::Contains("not sorted"));
  CHECK_THAT(msg("duplicated.csv"), Catch::Contains("duplicated.csv:6") && Catch::Contains("duplicated"));
  CHECK_THAT(msg("self_intersecting.csv"), Catch::Contains("self_intersecting.csv:") && Catch::Contains("self-intersecting"));
  CHECK_THAT(msg("too_short.csv"), Catch::Contains("too short"));
  CHECK_THAT(msg("no_units.csv"), Catch::Contains("length unit unknown"));
  CHECK_THAT(msg("missing_file.csv"), Catch::Contains("cannot open"));
  // An empty file or one with only a header has no points (it was "length unit unknown").
  const std::string dir = test::temp_dir("profile_empty");
  std::ofstream(dir + "/empty.csv").close();
  std::ofstream(dir + "/header_only.csv") << "y,z\n";
  for (const char* f : {"/empty.csv", "/header_only.csv"})
    CHECK_THROWS_WITH(read_profile(dir + f, ProfileKind::wheel),
                      Catch::Contains(f) && Catch::Contains("no profile points found in the wheel profile"));
  CHECK_THROWS_AS(read_profile("S1002", ProfileKind::rail), InputError);
  // The unit option fixes the missing unit.
  ProfileReadOptions o;
  o.unit = 1e-3;
  CHECK(read_profile(test::data_path("contact_geometry/no_units.csv"), ProfileKind::rail, o).y().front() ==
        Approx(-0.030));
}

TEST_CASE("profile widths outside the usual range give a warning naming the width and the range",
          "[geometry][profile][sanity]") {
  // Shipped profiles are inside (S1002 130 mm, UIC60 74-81 mm).
  CHECK(profile_width_warning(read_profile("S1002", ProfileKind::wheel)).empty());
  for (const char* rail : {"UIC60", "UIC60_MBench", "UIC60_true"})
    CHECK(profile_width_warning(read_profile(rail, ProfileKind::rail)).empty());
  const auto made = [](ProfileKind kind, double width) {
    std::vector<double> y, z;
    for (int i = 0; i <= 40; ++i) {
      y.push_back(-0.5 * width + width * i / 40.0);
      z.push_back(0.002 * std::pow(2.0 * y.back() / width, 2));
    }
    return Profile(kind, "made.csv", y, z);
  };
  // Inside, at the bounds and outside, wheels and rails (both sides of each range).
  CHECK(profile_width_warning(made(ProfileKind::wheel, 0.130)).empty());
  CHECK(profile_width_warning(made(ProfileKind::wheel, 0.1001)).empty());
  CHECK(profile_width_warning(made(ProfileKind::wheel, 0.1999)).empty());
  CHECK(profile_width_warning(made(ProfileKind::rail, 0.074)).empty());
  CHECK(profile_width_warning(made(ProfileKind::rail, 0.0501)).empty());
  CHECK_THAT(profile_width_warning(made(ProfileKind::wheel, 0.060)),
             Catch::Contains("made.csv: wheel profile 60.0 mm wide") && Catch::Contains("usual 100-200 mm"));
  CHECK_THAT(profile_width_warning(made(ProfileKind::wheel, 0.250)), Catch::Contains("250.0 mm wide"));
  CHECK_THAT(profile_width_warning(made(ProfileKind::rail, 0.030)),
             Catch::Contains("rail profile 30.0 mm wide") && Catch::Contains("usual 50-200 mm"));
  CHECK_THAT(profile_width_warning(made(ProfileKind::rail, 0.250)), Catch::Contains("usual 50-200 mm"));
  // The corpus file: a wheel cut to 60 mm.
  const std::string narrow = test::data_path("bad_input/profile_wheel_narrow.csv");
  CHECK_THAT(profile_width_warning(read_profile(narrow, ProfileKind::wheel)),
             Catch::Contains(narrow + ": wheel profile 60.0 mm wide"));
}

// SIMPACK processing keys railsim does not apply (shift.y, shift.z, rotate)
// were ignored silently when non-zero: refused naming the file, line and key;
// a mirror mode other than 0 or 1 likewise. The shipped files (all zero) load.
TEST_CASE("prw/prr: shift and rotation keys are refused unless zero", "[geometry][profile][errors]") {
  const std::string src = test::read_text(test::source_path("profiles/MBench_S1002_v3.prw"));
  const std::string dir = test::temp_dir("prw_keys");
  auto with = [&](const std::string& key, const std::string& value) {
    std::string text = src;
    const auto at = text.find("    " + key + " ");
    REQUIRE(at != std::string::npos);
    const auto eq = text.find('=', at), bang = text.find('!', eq);
    text.replace(eq + 1, bang - eq - 1, " " + value + "   ");
    const std::string path = dir + "/" + key + ".prw";
    std::ofstream(path) << text;
    try {
      read_profile(path, ProfileKind::wheel);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  CHECK_THAT(with("rotate", "+3.0e-01"), Catch::Contains("rotate.prw:27") && Catch::Contains("key 'rotate'") &&
                                             Catch::Contains("does not apply SIMPACK's shift and rotation"));
  CHECK_THAT(with("shift.y", "+5.0e+00"), Catch::Contains("shift.y.prw:25") && Catch::Contains("key 'shift.y'"));
  CHECK_THAT(with("shift.z", "-1"), Catch::Contains("shift.z.prw:26") && Catch::Contains("key 'shift.z'"));
  CHECK_THAT(with("mirror.y", "2"), Catch::Contains("mirror.y.prw:32") && Catch::Contains("expected 0") &&
                                        Catch::Contains("or 1 (got '2')"));
  CHECK(with("rotate", "+0.000e+00") == "no error");
  CHECK_NOTHROW(read_profile(test::source_path("profiles/MBench_UIC60_v3.prr"), ProfileKind::rail));
}

// SIMPACK's extension says the kind: a .prr given as the wheel (or a .prw as
// the rail) is refused naming the file (it gave a flangeless "wheel").
TEST_CASE("prw/prr: the extension's kind must match the use", "[geometry][profile][errors]") {
  const std::string prr = test::source_path("profiles/MBench_UIC60_v3.prr");
  const std::string prw = test::source_path("profiles/MBench_S1002_v3.prw");
  CHECK_THROWS_WITH(read_profile(prr, ProfileKind::wheel),
                    Catch::Contains("MBench_UIC60_v3.prr") && Catch::Contains("a SIMPACK rail profile (.prr) given as "
                                                                              "the wheel profile"));
  CHECK_THROWS_WITH(read_profile(prw, ProfileKind::rail), Catch::Contains("a SIMPACK wheel profile (.prw)"));
  CHECK_NOTHROW(read_profile(prw, ProfileKind::wheel));
}

// A wheel file with z up (the flange an interior minimum, the largest z at an
// end) was read as a wheel without a flange (conicity 0.018 for S1002):
// refused naming the file; the same points with z down read as S1002.
TEST_CASE("a wheel profile with z up is refused", "[geometry][profile][errors]") {
  const Profile s1002 = read_profile("S1002", ProfileKind::wheel);
  const std::string dir = test::temp_dir("wheel_z_up");
  std::ofstream up(dir + "/up.csv"), down(dir + "/down.csv");
  up << "y_m,z_m\n";
  down << "y_m,z_m\n";
  up.precision(17);
  down.precision(17);
  for (std::size_t i = 0; i < s1002.y().size(); ++i) {
    up << s1002.y()[i] << "," << -s1002.z()[i] << "\n";
    down << s1002.y()[i] << "," << s1002.z()[i] << "\n";
  }
  up.close();
  down.close();
  CHECK_THROWS_WITH(read_profile(dir + "/up.csv", ProfileKind::wheel),
                    Catch::Contains("up.csv") && Catch::Contains("flange points up") &&
                        Catch::Contains("railsim's z points down"));
  ProfileReadOptions zup;
  zup.z_up = true;
  CHECK(read_profile(dir + "/up.csv", ProfileKind::wheel, zup).z().size() == s1002.z().size());
  const Profile back = read_profile(dir + "/down.csv", ProfileKind::wheel);
  CHECK(back.z() == s1002.z());
}
