// The reductions study (engine/analysis/reduction_study.cpp) as a library
// call: layer factors equal the exact solver's creep-curve slopes for the
// scenario's own patch; the linear critical speed falls monotonically with k;
// a sweep with layer factors runs and records them; a resumed study gives the
// same result; the summary and the charts carry every entry.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>

#include "contact/hertz.hpp"
#include "contact/mim/mim_model.hpp"
#include "engine/analysis/reduction_study.hpp"
#include "test_support.hpp"

using namespace railsim::engine;
using railsim::contact::parse_reduction_list;

namespace {

// Slope of the creep curve near zero creepage: F(c) / c at a creepage small
// enough that the slip zone is a few edge elements (mu = 0.3).
double slope(railsim::contact::mim::MimSolver& s, const railsim::contact::HertzPatch& p,
             const railsim::contact::Material& m, int direction, double c) {
  railsim::contact::Creepages cr;
  if (direction == 0) cr.xi = c;
  if (direction == 1) cr.eta = c;
  if (direction == 2) cr.phi = c;
  const auto& r = s.solve_hertz(p, cr, m);
  return (direction == 0 ? r.Fx : r.Fy) / c;
}

}  // namespace

TEST_CASE("layer factors of the thesis's layer equal the exact solver's creep-curve slopes for the coach's patch",
          "[reduction_study][third_body]") {
  const Scenario sc = load_scenario(railsim::test::source_path("scenarios/manchester_coach_critical_speed.yaml"));
  // The nominal patch: centred wheelset under its static vertical wheel load;
  // on the coach's profiles the most loaded strip patch, whose normal load is
  // the vertical load over the cosine of the tread's contact angle (a few
  // degrees at the centre: 1 to 1.002 times the vertical load).
  const auto& p = sc.nominal_patch;
  const double Q = sc.model.wheelsets.front().static_load[0];
  REQUIRE(p.Fz >= Q * (1.0 - 1e-12));
  REQUIRE(p.Fz == Approx(Q).epsilon(2e-3));
  REQUIRE(p.a > 4e-3);
  REQUIRE(p.a < 8e-3);
  const std::string cache = railsim::test::temp_dir("layer_coach");
  const auto spec = railsim::contact::parse_reduction_spec("layer:h=125e-6,G3=820e6", "test");
  const Scenario layered = with_reduction(sc, spec, "test", cache);
  const auto k = layered.reduction.k;
  REQUIRE(layered.reduction.resolved);
  CHECK(layered.model.coupling.options().reduction.k11 == k.k11);
  CHECK(layered.reduction.form == railsim::contact::ReductionForm::layer);
  WARN("coach (own profiles, centred): layer h = 125 um, G3 = 820 MPa -> k11 " << k.k11 << ", k22 " << k.k22
                                                                                << ", k23 " << k.k23);
  // Independent: creep curves of the exact solver with Coulomb friction mu = 0.3
  // at small creepage, with and without the layer (grid 40, the factors' grid).
  railsim::contact::Material m = layered.creep_material;
  m.mu = 0.3;
  railsim::contact::mim::MimOptions o;
  o.grid = 40;
  railsim::contact::mim::MimSolver clean(o);
  o.layer = {125e-6, 820e6, 0.0};
  railsim::contact::mim::MimSolver with(o);
  const double c = std::sqrt(p.a * p.b);
  const double small[3] = {1e-5, 1e-5, 1e-5 / c};
  const double factors[3] = {k.k11, k.k22, k.k23};
  for (int d = 0; d < 3; ++d) {
    const double ratio = slope(with, p, m, d, small[d]) / slope(clean, p, m, d, small[d]);
    INFO("direction " << d);
    // At creepage 1e-5 a few trailing-edge elements slip: within 0.5 %.
    CHECK(ratio == Approx(factors[d]).epsilon(0.005));
  }
  // The layer lowers the linear critical speed's input but not the friction (no tau_c).
  CHECK(layered.model.coupling.options().material.mu == sc.model.coupling.options().material.mu);
  // The same geometry's layer from a YAML key gives the same factors (one resolution path).
  const auto yaml = railsim::config::InputNode::load_string(
      "name: t\nvehicle: " + railsim::test::source_path("vehicles/manchester_coach.yaml") +
          "\ntrack: {name: s, rail_spacing: 1.5, gauge: 1.435, segments: [{type: straight, length: 100}]}\n"
          "speed_kmh: 200\nduration: 1\nwheelset_model: lateral\ncontact:\n  geometry: {type: profiles, wheel: S1002, "
          "rail: UIC60, inclination: 1/40, r0: 0.46}\n  tangential: chopaya\n  material: {E: 2.1e11, nu: 0.28, mu: 0.3}\n  reduction: layer:h=125e-6,G3=820e6\n",
      "inline.yaml");
  const Scenario from_yaml = load_scenario(yaml, ".");
  CHECK(from_yaml.model.coupling.options().reduction.k11 == Approx(k.k11).epsilon(1e-12));
  CHECK(from_yaml.reduction.form == railsim::contact::ReductionForm::layer);
}

TEST_CASE("reductions study: linear critical speed falls monotonically with k, files resume to the same result",
          "[reduction_study]") {
  const Scenario sc = load_scenario(railsim::test::source_path("scenarios/manchester_coach_critical_speed.yaml"));
  const std::string dir = railsim::test::temp_dir("reduction_study");
  ReductionStudyOptions o;
  o.entries = parse_reduction_list("0.9,0.8,0.7,0.6,0.5,elastic_fe", "test");  // no k = 1: added as the reference
  o.bifurcation.v_min = 290 / 3.6;
  o.bifurcation.v_max = 300 / 3.6;
  o.bifurcation.v_step = 10 / 3.6;
  o.bifurcation.duration = 0.6;
  o.bifurcation.large_disturbance = 7e-3;
  o.bifurcation.up_branch = false;
  o.linear_v_lo = 50.0;
  o.linear_v_hi = 150.0;
  o.out_dir = dir + "/study";
  o.threads = 2;
  const ReductionStudyResult r = reduction_study(sc, o);
  REQUIRE(r.entries.size() == 7);
  REQUIRE(r.reference == 6);
  CHECK(r.entries[6].added_reference);
  // 0.6 s per point (a cheap sweep for the linear part and the files): the
  // coach's 290-300 km/h runs end with no cycle in their 0.18 s tail, so the
  // sweeps have no nonlinear verdict, and say why (BifurcationResult::undetermined).
  for (const auto& e : r.entries) {
    INFO(e.label);
    CHECK(std::isnan(e.critical));
    CHECK(e.bifurcation.undetermined_kind == BifurcationResult::Undetermined::too_short);
  }
  CHECK(std::isnan(r.entries[6].change_percent));
  // Linear critical speed (eigenvalues) against uniform k = 1, 0.9, ..., 0.5:
  // strictly falling as k falls (measured 380.8, 363.7, 348.6, 336.4, 328.4, 326.4 km/h).
  double previous = r.entries[6].linear;
  for (int i = 0; i < 5; ++i) {
    INFO("k = " << r.entries[static_cast<std::size_t>(i)].scenario.reduction.k.k11);
    CHECK(r.entries[static_cast<std::size_t>(i)].linear < previous);
    CHECK(r.entries[static_cast<std::size_t>(i)].linear_change_percent < 0.0);
    previous = r.entries[static_cast<std::size_t>(i)].linear;
  }
  // Each entry's value is the one of a direct computation on its scenario.
  CHECK(r.entries[5].linear == linear_critical_speed(r.entries[5].scenario, 50.0, 150.0));
  CHECK(r.entries[5].label == "elastic_fe");
  CHECK(r.entries[0].label == "uniform 0.9");
  for (const auto& e : r.entries) {
    REQUIRE(e.bifurcation.points.size() == 2);
    CHECK(std::filesystem::exists(o.out_dir + "/" + e.folder + "/bifurcation.csv"));
  }

  // Summary: every entry with its factors, speeds and changes; no wall times.
  const std::string summary = reduction_study_summary(sc, o, r).dump();
  CHECK(summary.find("\"wall_time") == std::string::npos);
  CHECK(summary.find("\"label\": \"uniform 0.5\"") != std::string::npos);
  CHECK(summary.find("\"given\": \"0.5\"") != std::string::npos);
  CHECK(summary.find("third_body") == std::string::npos);  // 0.5 was given as a number
  CHECK(summary.find("\"duration_per_point_s\": 0.6") != std::string::npos);
  CHECK(summary.find("\"mu\": 0.3") != std::string::npos);
  CHECK(summary.find("\"equivalent_conicity\"") != std::string::npos);
  CHECK(summary.find("\"saturation_law\": \"chopaya") != std::string::npos);

  // Started again on the same folder: nothing is recomputed, the result is identical.
  ReductionStudyOptions again = o;
  again.threads = 1;
  const ReductionStudyResult r2 = reduction_study(sc, again);
  CHECK(reduction_study_summary(sc, o, r2).dump() == summary);
  for (const auto& e : r2.entries) CHECK(e.wall_time < 0.5);  // read back, not run
  // Another setting on the same folder is refused: its points would not match.
  ReductionStudyOptions other = o;
  other.bifurcation.duration = 1.2;
  CHECK_THROWS_WITH(reduction_study(sc, other), Catch::Contains("other settings"));

  // Charts: one labelled curve per entry, uniform entries sorted on k.
  const auto chart = reductions_chart(sc, o, r);
  int labelled = 0;
  for (const auto& s : chart.series)
    if (s.label.find(": critical speed") != std::string::npos) ++labelled;
  CHECK(labelled == 7);
  CHECK(chart.note.find("lowest speed of the down branch") != std::string::npos);
  const auto vs_k = critical_speed_vs_k_chart(sc, r);
  REQUIRE(vs_k.series.size() >= 4);  // (+ upper bounds where the run below was still decaying)
  CHECK(vs_k.series[1].x == std::vector<double>({0.5, 0.6, 0.7, 0.8, 0.9, 1.0}));
  CHECK(vs_k.series[1].y.back() == Approx(r.entries[6].linear * 3.6).epsilon(1e-12));
  REQUIRE(vs_k.annotations.size() == 1);
  CHECK(vs_k.annotations[0].first.find("elastic_fe") == 0);
}

TEST_CASE("a sweep with layer factors runs and records them", "[reduction_study][third_body]") {
  const Scenario sc = load_scenario(railsim::test::data_path("scenarios/single_wheelset_s1002.yaml"));
  const std::string dir = railsim::test::temp_dir("reduction_layer");
  ReductionStudyOptions o;
  o.entries = parse_reduction_list("1;layer:h=125e-6,G3=820e6,tau_c=100e6", "test");
  o.bifurcation.v_min = 280 / 3.6;
  o.bifurcation.v_max = 320 / 3.6;
  o.bifurcation.v_step = 20 / 3.6;
  o.bifurcation.duration = 2.0;
  o.bifurcation.up_branch = false;
  o.linear_v_lo = 40.0;
  o.linear_v_hi = 200.0;
  o.out_dir = dir + "/study";
  o.cache_dir = dir + "/cache";
  o.threads = 2;
  const ReductionStudyResult r = reduction_study(sc, o);
  REQUIRE(r.entries.size() == 2);
  const auto& e = r.entries[1];
  const Scenario direct = with_reduction(sc, o.entries[1], "test", o.cache_dir);
  CHECK(e.scenario.reduction.k.k11 == direct.reduction.k.k11);
  CHECK_FALSE(e.scenario.layer.from_cache);
  CHECK(direct.layer.from_cache);  // computed once, then read back
  CHECK(e.scenario.reduction.k.k11 < 0.5);
  // tau_c = 100 MPa below mu p0: the layer lowers the friction of the run.
  CHECK(e.scenario.model.coupling.options().material.mu < 0.3);
  CHECK(e.bifurcation.points.size() == 3);
  // This wheelset's creep forces (G = 144 GPa in the scenario) drop to k ~ 0.09
  // with the layer: stable up to the top of the bracket (no linear critical speed).
  CHECK(std::isfinite(r.entries[0].linear));
  CHECK_FALSE(e.linear == r.entries[0].linear);
  const std::string s = reduction_study_summary(sc, o, r).dump();
  CHECK(s.find("\"h_m\": 0.000125") != std::string::npos);
  CHECK(s.find("\"G3_Pa\": 820000000") != std::string::npos);
  CHECK(s.find("\"tau_c_Pa\": 100000000") != std::string::npos);
  CHECK(s.find("\"mu_limit\"") != std::string::npos);
  // A scenario that prescribes creep coefficients has no patch for a layer.
  const Scenario flange = load_scenario(railsim::test::data_path("scenarios/single_wheelset_flange.yaml"));
  CHECK_THROWS_WITH(with_reduction(flange, o.entries[1], "--reductions entry 2", o.cache_dir),
                    Catch::Contains("--reductions entry 2") && Catch::Contains("contact patch"));
}

TEST_CASE("the study's profiles scenarios differ only in the wheelset model", "[reduction_study]") {
  auto lines = [](const std::string& path) {
    std::vector<std::string> out;
    std::stringstream ss(railsim::test::read_text(path));
    for (std::string l; std::getline(ss, l);)
      if (!l.empty() && l[0] != '#') out.push_back(l);
    return out;
  };
  const std::string lat = railsim::test::source_path("scenarios/manchester_coach_profiles_critical_speed.yaml");
  const std::string full = railsim::test::source_path("scenarios/manchester_coach_profiles_critical_speed_full.yaml");
  const auto a = lines(lat), b = lines(full);
  REQUIRE(a.size() == b.size());
  int differ = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i] != b[i]) {
      ++differ;
      INFO(a[i] << " | " << b[i]);
      CHECK((a[i].rfind("name:", 0) == 0 || a[i].rfind("wheelset_model:", 0) == 0));
    }
  CHECK(differ == 2);
  const Scenario sl = load_scenario(lat), sf = load_scenario(full);
  CHECK(sl.model.wheelset_model == WheelsetModel::lateral);
  CHECK(sf.model.wheelset_model == WheelsetModel::full);
  CHECK(sl.geometry_description.rfind("profiles S1002 on UIC60", 0) == 0);
  CHECK(sl.critical_speed.continuation);
}
