// Track files: every shipped track loads and matches its description; malformed
// files give errors naming the file, line and segment (through the library and
// through the railsim binary, exit code 2); `railsim track` samples a file.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <string>

#include "config/yaml_input.hpp"
#include "core/errors.hpp"
#include "results/csv_writer.hpp"
#include "test_support.hpp"
#include "track/track_file.hpp"

using namespace railsim::track;
using railsim::test::source_path;

namespace {

Track load_text(const std::string& text) {
  return load_track(railsim::config::InputNode::load_string(text, "t.yaml"), railsim::test::data_path("tracks"), "t");
}

std::string error_of(const std::string& text) {
  try {
    load_text(text);
  } catch (const railsim::InputError& e) {
    return e.what();
  }
  return "no error";
}

const char* kCurve = R"(segments:
  - {type: straight, length: 50}
  - {type: clothoid, length: 30}
  - {type: circular, length: 60, radius: 250, direction: left, cant_mm: 100}
  - {type: clothoid, length: 30}
  - {type: straight, length: 100}
)";

}  // namespace

TEST_CASE("shipped track files load and match their descriptions", "[tracks][track_file]") {
  {
    const Track t = load_track(source_path("tracks/straight_lateral_defect.yaml"));
    CHECK(t.length() == 2000.0);
    CHECK(t.at(90.0).irregularity[Channel::lateral] == Approx(0.010).epsilon(1e-14));
    CHECK(t.at(90.0).curvature == 0.0);
    CHECK(t.at(500.0).irregularity[Channel::lateral] == 0.0);
  }
  {
    const Track t = load_track(source_path("tracks/curve_twist.yaml"));
    CHECK(t.length() == 270.0);
    CHECK(t.alignment().segment_count() == 5);
    CHECK(t.at(110.0).curvature == Approx(1.0 / 250).epsilon(1e-14));
    CHECK(t.at(110.0).cant == Approx(0.100).epsilon(1e-14));
    CHECK(t.at(65.0).cant == Approx(0.050).epsilon(1e-14));  // linear ramp in the entry clothoid
    // Twist in the exit clothoid: design ramp -100 mm / 30 m plus the defect -18 mm / 3 m on the right rail.
    const TrackState a = t.at(150.0), b = t.at(153.0);
    CHECK(a.segment == 3);
    const double design = (b.cant - a.cant) / 3.0;
    const double defect = (b.irregularity[Channel::cross_level] - a.irregularity[Channel::cross_level]) / 3.0;
    CHECK(design == Approx(-0.1 / 30).epsilon(1e-12));
    CHECK(defect == Approx(-0.006).epsilon(1e-12));
    CHECK(b.irregularity.left_vertical() == Approx(0.0).margin(1e-16));
    CHECK(b.irregularity.right_vertical() == Approx(-0.018).epsilon(1e-12));
  }
  {
    const Track t = load_track(source_path("tracks/straight_erri_low.yaml"));
    CHECK(t.at(50.0).irregularity[Channel::vertical] == 0.0);  // before 'from'
    double sum2 = 0;
    int n = 0;
    for (double s = 200; s < 2800; s += 0.5, ++n) sum2 += std::pow(t.at(s).irregularity[Channel::vertical], 2);
    // One 2.6 km realisation: within 25 % of the 2.86 mm of the spectrum (3-150 m).
    CHECK(std::sqrt(sum2 / n) * 1e3 == Approx(2.86).epsilon(0.25));
  }
  for (const char* f : {"tracks/curve_R300.yaml", "tracks/curve_R1000.yaml"}) {
    const Track t = load_track(source_path(f));
    CHECK(t.irregularities().empty());
  }
  CHECK(load_track(source_path("tracks/curve_R300.yaml")).at(300).cant == Approx(-0.150).epsilon(1e-14));
  CHECK(load_track(source_path("tracks/curve_R1000.yaml")).at(500).curvature == Approx(1e-3).epsilon(1e-14));
}

TEST_CASE("malformed track files name the segment and the key", "[tracks][track_file]") {
  std::string bad = kCurve;
  bad.replace(bad.find("clothoid, length: 30"), 20, "clothoid, length: 0");
  CHECK(error_of(bad) == "t.yaml:3: segments[1] (clothoid): key 'length': expected a positive number (got 0)");
  CHECK_THAT(error_of(R"(segments:
  - {type: straight, length: 50}
  - {type: circular, length: 60, radius: 250, direction: left, cant_mm: 100, speed: 3}
)"),
             Catch::Contains("t.yaml:3: segments[1] (circular): key 'speed': unknown key"));
  CHECK_THAT(error_of("segments:\n  - {type: spiral, length: 5}\n"),
             Catch::Contains("segments[0] (spiral): key 'type': unknown segment type 'spiral'"));
  CHECK_THAT(error_of("segments:\n  - {type: circular, length: 60, radius: 250, direction: up}\n"),
             Catch::Contains("segments[0] (circular): key 'direction'") && Catch::Contains("left, right"));
  CHECK_THAT(error_of("segments:\n  - {type: circular, length: 60, radius: 250, direction: left, cant_mm: 400}\n"),
             Catch::Contains("segments[0] (circular): key 'cant_mm'"));
  CHECK_THAT(error_of("segments:\n  - {type: circular, length: 60, direction: left}\n"),
             Catch::Contains("segments[0] (circular)") && Catch::Contains("missing required key 'radius'"));
  // Curvature / cant jumps and adjacent clothoids.
  CHECK_THAT(error_of(R"(segments:
  - {type: straight, length: 50}
  - {type: circular, length: 60, radius: 250, direction: left}
)"),
             Catch::Contains("t.yaml:3: segments[1] (circular): starts with curvature 0.004") &&
                 Catch::Contains("insert a clothoid"));
  CHECK_THAT(error_of(R"(segments:
  - {type: straight, length: 50}
  - {type: clothoid, length: 30}
  - {type: clothoid, length: 30}
)"),
             Catch::Contains("segments[1] (clothoid): a clothoid") && Catch::Contains("cannot be adjacent"));
  CHECK_THAT(error_of("name: x\nsegmnts: []\n"), Catch::Contains("key 'segmnts': unknown key"));
  CHECK_THAT(error_of("segments: []\n"), Catch::Contains("at least one segment"));
  // The gauge lies inside the distance of the rail centres.
  CHECK_THAT(error_of("gauge: 1.6\nsegments:\n  - {type: straight, length: 50}\n"),
             Catch::Contains("t.yaml:1: key 'gauge': gauge 1.6 m is not smaller than rail_spacing 1.5 m (the default)"));
  CHECK_THAT(error_of("rail_spacing: 1.2\nsegments:\n  - {type: straight, length: 50}\n"),
             Catch::Contains("t.yaml:1: key 'rail_spacing': gauge 1.435 m is not smaller than rail_spacing 1.2 m"));
  CHECK(error_of("gauge: 1.676\nrail_spacing: 1.75\nsegments:\n  - {type: straight, length: 50}\n") == "no error");
  // The start pose: within 1e7 m and one turn (x = 1e300 wrote x = 1e300 on every row, the metres lost).
  CHECK_THAT(error_of("start: {x: 1e300}\nsegments:\n  - {type: straight, length: 50}\n"),
             Catch::Contains("t.yaml:1: key 'start.x': expected a number in [-10000000, 10000000]"));
  CHECK_THAT(error_of("start: {y: -2e7}\nsegments:\n  - {type: straight, length: 50}\n"),
             Catch::Contains("key 'start.y'"));
  CHECK_THAT(error_of("start: {heading_deg: 1e20}\nsegments:\n  - {type: straight, length: 50}\n"),
             Catch::Contains("key 'start.heading_deg': expected a number in [-360, 360]"));
  CHECK(error_of("start: {x: -1e7, y: 1e7, heading_deg: -360}\nsegments:\n  - {type: straight, length: 50}\n") ==
        "no error");
  // Irregularities.
  CHECK_THAT(error_of(std::string(kCurve) + "irregularities:\n  - {type: bump, start: 3}\n"),
             Catch::Contains("irregularities[0] (bump): key 'type': unknown irregularity type 'bump'") &&
                 Catch::Contains("defect, twist, psd, measured"));
  CHECK_THAT(error_of(std::string(kCurve) +
                      "irregularities:\n  - {type: defect, channel: sideways, start: 3, wavelength: 5, amplitude_mm: 1}\n"),
             Catch::Contains("t.yaml:8: irregularities[0] (defect): key 'channel': unknown channel 'sideways'"));
  CHECK_THAT(error_of(std::string(kCurve) +
                      "irregularities:\n  - {type: defect, channel: lateral, start: 260, wavelength: 20, amplitude_mm: 1}\n"),
             Catch::Contains("outside the track (0 .. 270 m)"));
  CHECK_THAT(error_of(std::string(kCurve) + "irregularities:\n  - {type: psd, spectrum: erri_mid, seed: 1}\n"),
             Catch::Contains("irregularities[0] (psd): key 'spectrum': unknown spectrum 'erri_mid'"));
  CHECK_THAT(error_of(std::string(kCurve) + "irregularities:\n  - {type: psd, spectrum: fra_5, seed: -4}\n"),
             Catch::Contains("key 'seed': expected a non-negative integer"));
  CHECK_THAT(error_of(std::string(kCurve) + "irregularities:\n  - {type: measured, file: measured_unsorted.csv}\n"),
             Catch::Contains("irregularities[0] (measured): key 'file':") &&
                 Catch::Contains("measured_unsorted.csv:5:"));
  CHECK_THAT(error_of(std::string(kCurve) +
                      "irregularities:\n  - {type: measured, file: measured_good.csv, channels: [gauge]}\n"),
             Catch::Contains("channel 'gauge' is not a column"));
  // A record placed off the track (it gave a silent zero irregularity), a scale beyond the range.
  CHECK_THAT(error_of(std::string(kCurve) + "irregularities:\n  - {type: measured, file: measured_good.csv, offset: 500}\n"),
             Catch::Contains("irregularities[0] (measured): key 'offset'") &&
                 Catch::Contains("outside the track (0 .. 270 m)"));
  CHECK_THAT(error_of(std::string(kCurve) + "irregularities:\n  - {type: measured, file: measured_good.csv, offset: 1e300}\n"),
             Catch::Contains("key 'offset'"));
  CHECK_THAT(error_of(std::string(kCurve) + "irregularities:\n  - {type: measured, file: measured_large.csv, scale: 2}\n"),
             Catch::Contains("key 'scale': scale 2 makes the record's largest value 300 mm"));
  // Rows closer than 1 mm (a 10 mm spike over 1e-12 m was lost without a word).
  CHECK_THAT(error_of(std::string(kCurve) + "irregularities:\n  - {type: measured, file: measured_spike.csv}\n"),
             Catch::Contains("measured_spike.csv:5: distance s = 50.000000000001 m is only") &&
                 Catch::Contains("rows must be at least 1 mm apart"));
}

// A record that reaches far beyond the track's end was accepted without a
// word (the part beyond is never used); one whose distances are millimetres
// put its rows 250 m apart and ran as a smooth 10 km wave.
TEST_CASE("a measured record reaching beyond the track is said, one in mm refused", "[tracks][track_file]") {
  // 0 .. 400 m every 5 m on the 270 m track: 130 m beyond the end, 27 of 81 rows unused.
  const Track t = load_text(std::string(kCurve) + "irregularities:\n  - {type: measured, file: measured_long.csv}\n");
  REQUIRE(t.warnings().size() == 1);
  CHECK_THAT(t.warnings()[0], Catch::Contains("t.yaml:8: irregularities[0] (measured): key 'file':") &&
                                  Catch::Contains("measured_long.csv covers s = 0 .. 400 m, the track 0 .. 270 m") &&
                                  Catch::Contains("130 m beyond its end are not used (55 of 81 rows lie on the "
                                                  "track)"));
  // The record still applies on the track.
  CHECK(t.at(10.0).irregularity[Channel::lateral] == Approx(2.0e-3).epsilon(1e-12));
  // Placed 20 m early: both ends said.
  const Track early = load_text(std::string(kCurve) +
                                "irregularities:\n  - {type: measured, file: measured_long.csv, offset: -20}\n");
  REQUIRE(early.warnings().size() == 1);
  CHECK_THAT(early.warnings()[0], Catch::Contains("(offset -20 m)") &&
                                      Catch::Contains("110 m beyond its end and 20 m before its start are not used"));
  // A record within the track, or past it by less than 10 % of its length: nothing to say.
  CHECK(load_text(std::string(kCurve) + "irregularities:\n  - {type: measured, file: measured_good.csv, offset: 268}\n")
            .warnings()
            .empty());
  CHECK(load_text(std::string(kCurve) + "irregularities:\n  - {type: measured, file: measured_good.csv}\n")
            .warnings()
            .empty());
  // s in mm: 0 .. 10000 "m" with rows 250 m apart on a 270 m track.
  CHECK_THAT(error_of(std::string(kCurve) + "irregularities:\n  - {type: measured, file: measured_s_in_mm.csv}\n"),
             Catch::Contains("t.yaml:8: irregularities[0] (measured): key 'file':") &&
                 Catch::Contains("measured_s_in_mm.csv covers s = 0 .. 10000 m, the track 0 .. 270 m") &&
                 Catch::Contains("rows 250 m apart") && Catch::Contains("is column 's' in mm?"));
}

TEST_CASE("a measured irregularity and a twist load from YAML", "[tracks][track_file]") {
  const Track t = load_text(std::string(kCurve) + R"(irregularities:
  - {type: measured, file: measured_good.csv, offset: 10, units: mm}
  - {type: twist, start: 150, base_length: 3, amplitude_mm: 9, hold: 1}
)");
  CHECK(t.at(12.0).irregularity[Channel::lateral] == Approx(2.0e-3).epsilon(1e-14));
  CHECK(t.at(153.5).irregularity[Channel::cross_level] == Approx(9e-3).epsilon(1e-14));
  CHECK(t.irregularities().components().size() == 2);
}

TEST_CASE("railsim track samples a file and bad files exit with code 2 naming the segment", "[tracks][track_file][cli]") {
  const std::string dir = railsim::test::temp_dir("tracks_cli");
  const std::string out = dir + "/twist.csv";
  const auto ok = railsim::test::run_railsim("track '" + source_path("tracks/curve_twist.yaml") + "' --out '" + out +
                                             "' --step 0.5 --from 40 --to 200 --speed-kmh 60");
  INFO(ok.output);
  REQUIRE(ok.exit_code == 0);
  const auto csv = railsim::results::read_csv(out);
  CHECK(csv.rows.size() == 321);
  CHECK(csv.number(0, "s") == 40.0);
  CHECK(csv.number(140, "s") == 110.0);
  CHECK(csv.number(140, "cant_mm") == Approx(100.0).epsilon(1e-9));
  CHECK(csv.number(140, "curvature") == Approx(0.004).epsilon(1e-9));
  // 11.8 V^2 / R - E at 60 km/h on R 250 with 100 mm: 69.9 mm excess.
  CHECK(csv.number(140, "cant_deficiency_mm") == Approx(1.5 * std::pow(60 / 3.6, 2) / (9.81 * 250) * 1e3 - 100).epsilon(1e-6));
  CHECK(csv.number(226, "cross_level_mm") == Approx(-18.0).epsilon(1e-9));  // s = 153 m

  // A record reaching far beyond the track: the program says so and runs.
  const std::string long_record = dir + "/long_record.yaml";
  std::ofstream(long_record) << kCurve << "irregularities:\n  - {type: measured, file: '"
                             << railsim::test::data_path("tracks/measured_long.csv") << "'}\n";
  const auto warned = railsim::test::run_railsim("track '" + long_record + "' --out '" + dir + "/long.csv'");
  CHECK(warned.exit_code == 0);
  CHECK_THAT(warned.output, Catch::Contains("long_record.yaml:8: irregularities[0] (measured)") &&
                                Catch::Contains("130 m beyond its end are not used"));

  const std::string bad = dir + "/bad.yaml";
  std::ofstream(bad) << "segments:\n  - {type: straight, length: 50}\n  - {type: clothoid, length: -3}\n";
  const auto r = railsim::test::run_railsim("track '" + bad + "' --out '" + dir + "/bad.csv'");
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.output, Catch::Contains("bad.yaml:3: segments[1] (clothoid): key 'length': expected a positive number (got -3)"));
  const auto missing = railsim::test::run_railsim("track '" + dir + "/nope.yaml' --out '" + dir + "/x.csv'");
  CHECK(missing.exit_code == 2);
  const auto step = railsim::test::run_railsim("track '" + source_path("tracks/curve_R300.yaml") + "' --out '" + dir +
                                               "/x.csv' --step 0");
  CHECK(step.exit_code == 2);
}

// A clothoid shorter than 1 m or with a cant ramp steeper than 20 mm/m was a
// step in disguise (0.5 m from 0 to 150 mm: runs failed with wheel loads of
// 1e10 N); refused naming the segment, the ramp and the length it needs.
TEST_CASE("clothoids: at least 1 m and at most 20 mm/m of cant ramp", "[tracks][track_file]") {
  const std::string head = "segments:\n  - {type: straight, length: 50}\n";
  const std::string curve = "  - {type: circular, length: 100, radius: 300, direction: left, cant_mm: 150}\n";
  CHECK(error_of(head + "  - {type: clothoid, length: 0.5}\n" + curve) ==
        "t.yaml:3: segments[1] (clothoid): key 'length': a clothoid of 0.5 m: at least 1 m (transitions are tens of "
        "metres long)");
  CHECK(error_of(head + "  - {type: clothoid, length: 5}\n" + curve) ==
        "t.yaml:3: segments[1] (clothoid): key 'length': the cant changes by 150 mm over 5 m (30 mm/m): at most "
        "20 mm/m, about ten times what line standards allow (EN 13803: 2.25-2.5 mm/m); give a clothoid of at least "
        "7.5 m");
  CHECK(error_of(head + "  - {type: clothoid, length: 7.5}\n" + curve) == "no error");  // 20 mm/m: the limit itself
}
