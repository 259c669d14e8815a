// The bad-input corpus (tests/data/bad_input/, README there): every file is
// refused by the reader that would read it, with a message naming the file,
// the line, the key (or table column) and the allowed range; legal but
// implausible values are read and reported as warnings. Also the SUNDIALS
// set-up calls: a setting CVODE or ARKODE refuses is an InputError naming the
// call and SUNDIALS' flag, not a setting silently ignored.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "contact/geometry/profile.hpp"
#include "core/errors.hpp"
#include "core/input_file.hpp"
#include "engine/wheel_rail/geometry_table.hpp"
#include "engine/integrators/integrator.hpp"
#include "engine/model.hpp"
#include "engine/io/scenario.hpp"
#include "engine/simulation.hpp"
#include "engine/io/vehicle_file.hpp"
#include "test_support.hpp"
#include "track/track_file.hpp"

using namespace railsim;

namespace {

std::string bad(const std::string& name) { return test::data_path("bad_input/" + name); }

std::string input_error(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}

struct Case {
  std::string file;
  std::vector<std::string> parts;  // expected in the message, in this order
};

void check_cases(const std::vector<Case>& cases, const std::function<void(const std::string&)>& read) {
  for (const auto& c : cases) {
    const std::string msg = input_error([&] { read(bad(c.file)); });
    INFO(c.file << ": " << msg);
    // The file first (with its line where one exists), then the key and the range.
    CHECK(msg.find(c.file) != std::string::npos);
    std::size_t at = 0;
    for (const auto& p : c.parts) {
      const std::size_t k = msg.find(p, at);
      CHECK(k != std::string::npos);
      if (k != std::string::npos) at = k + p.size();
    }
    // One line of message, of bounded length (no input echoed whole).
    CHECK(msg.find('\n') == std::string::npos);
    CHECK(msg.size() < 600);
  }
}

}  // namespace

TEST_CASE("bad scenarios: refused naming file, line, key and the allowed range", "[engine][bad_input]") {
  check_cases(
      {
          {"scenario_max_step_zero.yaml",
           {":10: key 'integrator.max_step'", "expected a step in (0, 1] s", "got 0", "omit max_step"}},
          {"scenario_min_step_above_duration.yaml",
           {":10: key 'integrator.min_step'", "expected a step in [0, 0.002) s", "got 10"}},
          {"scenario_duplicate_key.yaml", {":10: key 'speed'", "given twice (first on line 4)"}},
          {"scenario_duplicate_nested_key.yaml",
           {":9: key 'contact.creep_coefficients.f11'", "given twice (first on line 9)"}},
          {"scenario_start_distance_1e6.yaml",
           {":10: key 'start_distance'", "expected a number in [0, 400]", "track's defined length", "got 1000000"}},
          {"scenario_start_distance_minus_1e6.yaml",
           {":10: key 'start_distance'", "[0, 400]", "got -1000000"}},
          {"scenario_start_distance_1e300.yaml", {":10: key 'start_distance'", "[0, 400]", "got 1e+300"}},
          {"scenario_acceleration_huge.yaml",
           {":10: key 'acceleration'", "expected a number in [-10, 10]", "got 1000000"}},
          {"scenario_duration_huge.yaml",
           {"key 'output_interval'", "100000000001 output samples", "limit of 1000000"}},
          {"scenario_output_interval_tiny.yaml",
           {":6: key 'output_interval'", "1000000000 output samples", "limit of 1000000"}},
          {"scenario_mu_zero.yaml", {":10: key 'contact.material.mu'", "expected a number in (0, 2]", "got 0"}},
          {"scenario_nu_zero.yaml", {":10: key 'contact.material.nu'", "expected a number in (0, 0.5]", "got 0"}},
          {"scenario_f11_huge.yaml",
           {":9: key 'contact.creep_coefficients.f11'", "expected a number in (0, 10000000000]", "got 1e+20"}},
          {"scenario_nref_tiny.yaml",
           {":9: key 'contact.creep_coefficients.N_ref'", "expected 0 (constant coefficients) or a wheel load in [1, 1e7] N",
            "got 1e-300"}},
          {"scenario_E_tiny.yaml", {":10: key 'contact.material.E'", "expected a number in [1000000000, 10000000000000]", "got 1"}},
          // The error is in the file the scenario names: that file, line and key.
          {"vehicle_self_spring.yaml", {":6: key 'elements[0].other'", "to itself"}},
          {"table_negative_c11.dat", {":5: column 8 (C11 [-])", "expected a number in (0, 100]", "got -5"}},
          {"scenario_initial_lateral_huge.yaml",
           {":10: key 'initial.ws1.lateral'", "expected a deviation in [-0.05, 0.05] m", "lateral range", "got 0.5"}},
          {"scenario_initial_yaw_huge.yaml", {":10: key 'initial.ws1.yaw'", "[-0.1, 0.1] rad", "got 2"}},
          {"scenario_rtol_tiny.yaml", {":10: key 'integrator.rtol'", "expected a number in [1e-12, 0.1]", "got 1e-15"}},
          {"scenario_jacobian_max_age_zero.yaml",
           {":10: key 'integrator.jacobian_max_age'", "[1, 1000000]", "got 0"}},
          {"deep_nesting.yaml", {":2: YAML nested too deeply"}},
          {"junk_long_line.yaml", {":1: expected a mapping (got xxxx", "...)"}},
      },
      [](const std::string& path) {
        // A scenario whose vehicle or table is bad is read through the scenario.
        std::string p = path;
        if (p.find("vehicle_self_spring") != std::string::npos) p = bad("scenario_vehicle_self_spring.yaml");
        if (p.find("table_negative_c11") != std::string::npos) p = bad("scenario_table_negative_c11.yaml");
        engine::load_scenario(p);
      });
}

TEST_CASE("bad vehicles: refused naming file, line, key and the allowed range", "[engine][bad_input]") {
  check_cases(
      {
          {"vehicle_self_spring.yaml", {":6: key 'elements[0].other'", "joins body 'ws1' to itself"}},
          {"vehicle_duplicate_element.yaml",
           {":8: key 'elements[1].name'", "duplicate element name 'primary_L'"}},
          {"vehicle_duplicate_element_kinds.yaml",
           {":8: key 'elements[1].name'", "duplicate element name 'primary_L'"}},
          {"vehicle_mass_huge.yaml", {":4: key 'bodies[0].mass'", "expected a number in [1, 1000000]", "got 1e+300"}},
          {"vehicle_mass_tiny.yaml", {":4: key 'bodies[0].mass'", "[1, 1000000]", "got 1e-06"}},
          {"vehicle_inertia_triangle.yaml",
           {":4: key 'bodies[0].inertia'", "triangle inequality", "Ixx + Iyy = 212 < Izz = 1120"}},
          {"vehicle_duplicate_key.yaml", {":4: key 'bodies[0].mass'", "given twice (first on line 4)"}},
          // Values beyond any rail vehicle (they ran to a solver failure, exit 3, or were accepted).
          {"vehicle_spring_huge.yaml",
           {":7: key 'elements[0].stiffness'", "expected numbers in [0, 10000000000] N/m", "got 1e+300"}},
          {"vehicle_point_far.yaml", {":6: key 'elements[0].at'", "expected numbers in [-50, 50] m", "got 1000000000"}},
          {"vehicle_wheelset_offset.yaml", {":4: key 'bodies[0].position'", "a wheelset's y must be 0", "got 0.5"}},
          {"vehicle_wheelsets_same_x.yaml",
           {":5: key 'bodies[1].position'", "wheelset 'ws2' at x = 0.2 m lies within 0.5 m of wheelset 'ws1'"}},
          {"vehicle_dofs_twice.yaml", {":5: key 'bodies[1].dofs[1]'", "DOF 'lateral' given twice"}},
          {"vehicle_bump_stop_huge.yaml",
           {":9: key 'elements[1].table[1]'", "a force in [0, 100000000] N", "got [0.02, 1e+300]"}},
      },
      [](const std::string& path) {
        engine::Model m;
        engine::load_vehicle(path, m);
      });
}

TEST_CASE("bad tracks, geometry tables and profiles name file, line and column or unit", "[engine][bad_input]") {
  check_cases({{"track_duplicate_key.yaml", {":5: key 'segments'", "given twice (first on line 3)"}}},
              [](const std::string& path) { track::load_track(path); });
  check_cases(
      {
          {"table_negative_c11.dat", {":5: column 8 (C11 [-])", "(0, 100]", "got -5"}},
          {"table_zero_a.dat", {":5: column 4 (a [m])", "expected a number in (0, 0.1]", "got 0"}},
          {"table_negative_n0.dat", {":5: column 2 (N0 [N])", "expected a number in (0, 1e+07]", "got -60000"}},
          // Rows out of order: the line of the row (it named the block's first line).
          {"table_unsorted.dat",
           {":13: row 11 of the block (starting on line 1): shift -0.00039 after -0.00041", "not uniform"}},
      },
      [](const std::string& path) { engine::GeometryTable t(path); });
  check_cases({{"profile_mm_declared_m.csv",
                {"lateral extent 140000 mm", "plausible 500 mm", "length unit m",
                 "the column names on line 1", "another unit"}}},
              [](const std::string& path) { contact::read_profile(path, contact::ProfileKind::wheel); });
}

TEST_CASE("legal but implausible friction is read, with a warning naming file, key and the usual range",
          "[engine][bad_input]") {
  const engine::Scenario sc = engine::load_scenario(bad("scenario_mu_high_warning.yaml"));
  CHECK(sc.model.coupling.options().material.mu == Approx(1.5));
  REQUIRE(sc.warnings.size() == 1);
  INFO(sc.warnings[0]);
  CHECK(sc.warnings[0].find("scenario_mu_high_warning.yaml:10: key 'contact.material.mu': 1.5") != std::string::npos);
  CHECK(sc.warnings[0].find("usual range 0.05-0.6") != std::string::npos);
  // The shipped scenarios read without warnings.
  CHECK(engine::load_scenario(test::source_path("scenarios/single_wheelset.yaml")).warnings.empty());
}

TEST_CASE("input files: folders, devices and files beyond the size limit are refused before reading",
          "[engine][bad_input]") {
  const std::string dir = test::temp_dir("bad_input_files");
  CHECK(input_error([&] { engine::load_scenario(dir); }).find(dir + ": YAML input: is a folder") == 0);
  CHECK(input_error([] { engine::load_scenario("/dev/zero"); }).find("/dev/zero: YAML input: not a regular file") ==
        0);
  CHECK(input_error([] { engine::GeometryTable t("/dev/zero"); })
            .find("/dev/zero: contact-geometry table: not a regular file") == 0);
  // A sparse file one byte beyond the limit: refused from its size, never read.
  const std::string big = dir + "/big.yaml";
  { std::ofstream(big) << "name: x\n"; }
  std::filesystem::resize_file(big, kMaxInputFileBytes + 1);
  const std::string msg = input_error([&] { engine::load_scenario(big); });
  INFO(msg);
  CHECK(msg.find(big + ": YAML input: 67108865 bytes, larger than the limit of 67108864 bytes") == 0);
}

TEST_CASE("a setting SUNDIALS refuses is an input error naming the call and the flag", "[engine][bad_input]") {
  // Past the scenario reader (which refuses min_step >= max_step itself): the
  // integrators check the return code of every set-up call.
  const engine::Scenario sc = engine::load_scenario(test::source_path("scenarios/single_wheelset.yaml"));
  for (const std::string method : {"cvode_bdf", "arkode_erk", "arkode_dirk"}) {
    engine::IntegratorOptions o = sc.integrator;
    o.method = method;
    o.max_step = 1e-3;
    o.min_step = 1e-2;  // above max_step
    const std::string msg = input_error([&] { engine::simulate(sc.model, o, sc.x0, 0.01, 0.01); });
    INFO(method << ": " << msg);
    CHECK(msg.find("integrator set-up: ") == 0);
    CHECK(msg.find("SetMinStep (min_step 0.01") != std::string::npos);
    CHECK(msg.find("_ILL_INPUT (flag -22)") != std::string::npos);
  }
}

namespace {
std::string numerical_error(const std::function<void()>& f) {
  try {
    f();
  } catch (const NumericalError& e) {
    return e.what();
  }
  return "(no NumericalError)";
}
}  // namespace

TEST_CASE("integrator failures name time, place, model and the last step, and say what to change",
          "[engine][bad_input]") {
  // max_steps 1 (corpus): CVODE stops at once; the message names the setting and its value.
  {
    const engine::Scenario sc = engine::load_scenario(bad("scenario_max_steps_one.yaml"));
    const std::string msg = numerical_error([&] { engine::simulate(sc.model, sc.integrator, sc.x0, sc.duration,
                                                                   sc.output_interval); });
    INFO(msg);
    CHECK(msg.find("t = ") == 0);
    CHECK(msg.find("cvode_bdf") != std::string::npos);
    CHECK(msg.find("CV_TOO_MUCH_WORK (flag -1)") != std::string::npos);
    CHECK(msg.find("raise integrator.max_steps (now 1, default 100000)") != std::string::npos);
    CHECK(msg.find("(last step ") != std::string::npos);
    CHECK(msg.find("place: track distance 0.00-0.40 m (t = 0-0.01 s)") != std::string::npos);
    CHECK(msg.find("model: lateral wheelset, contact coefficients") != std::string::npos);
    CHECK(msg.find("stiff for an explicit") == std::string::npos);  // an implicit method: not blamed on stiffness
  }
  // min_step 1 ms on the shipped wheelset's 10 mm defect: the step cannot shrink.
  {
    const engine::Scenario sc = engine::load_scenario(test::source_path("scenarios/single_wheelset.yaml"));
    engine::IntegratorOptions o = sc.integrator;
    o.min_step = 1e-3;
    const std::string msg = numerical_error([&] { engine::simulate(sc.model, o, sc.x0, sc.duration,
                                                                   sc.output_interval); });
    INFO(msg);
    CHECK(msg.find("CV_ERR_FAILURE (flag -3)") != std::string::npos);
    CHECK(msg.find("could not shrink below integrator.min_step (now 0.001 s): lower min_step or omit it") !=
          std::string::npos);
    CHECK(msg.find("place: track distance ") != std::string::npos);
  }
  // An explicit method out of steps: the setting first, then the stiffness hint.
  {
    const engine::Scenario sc = engine::load_scenario(bad("scenario_max_steps_one.yaml"));
    for (const std::string method : {"arkode_erk", "odeint_dopri5"}) {
      engine::IntegratorOptions o = sc.integrator;
      o.method = method;
      const std::string msg = numerical_error([&] { engine::simulate(sc.model, o, sc.x0, sc.duration,
                                                                     sc.output_interval); });
      INFO(method << ": " << msg);
      CHECK(msg.find("raise integrator.max_steps (now 1, default 100000)") != std::string::npos);
      CHECK(msg.find("use cvode_bdf or arkode_dirk") != std::string::npos);
      CHECK(msg.find("place: track distance") != std::string::npos);
    }
  }
}
