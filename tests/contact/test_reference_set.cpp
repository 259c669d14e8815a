// Every registered tangential model held to railsim's exact reference set with
// spin (tests/data/contact/spin_reference/, MIM grid 120 extrapolated; reference_set.hpp):
// coverage of the set, MIM grid convergence with spin, FaStrip against FASTSIM,
// FASTSIM's flexibility blending, the Coulomb bound and the mirror images.
// Errors are |F - F_ref| / (mu Fz) of the tangential force vector.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "contact/mim/mim_model.hpp"
#include "contact/registry.hpp"
#include "contact/mim_table/mim_table.hpp"
#include "reference_set.hpp"

using namespace railsim::contact;
using railsim::test::extrapolated_reference_set;
using railsim::test::force_error;
using railsim::test::load_reference_set;
using railsim::test::ReferenceState;
using railsim::test::set_error;

namespace {
const auto all = [](const ReferenceState&) { return true; };
const std::vector<ReferenceState>& reference() {
  static const std::vector<ReferenceState> set = load_reference_set();
  return set;
}
}  // namespace

TEST_CASE("reference set: every sign combination, pure spin to 5 1/m, a/b 0.2, 1, 1.33, 5", "[contact][reference]") {
  const auto& set = reference();
  REQUIRE(set.size() == 764);
  std::set<std::string> quadrants;
  std::set<long> aob;
  double max_spin = 0.0;
  for (const auto& s : set) {
    const auto& c = s.in.creep;
    if (s.family == "lat_spin") quadrants.insert(std::string("eta") + (c.eta > 0 ? "+" : "-") + (c.phi > 0 ? "+" : "-"));
    if (s.family == "long_spin") quadrants.insert(std::string("xi") + (c.xi > 0 ? "+" : "-") + (c.phi > 0 ? "+" : "-"));
    if (s.family == "spin") max_spin = std::max(max_spin, std::abs(c.phi));
    aob.insert(std::lround(100.0 * s.in.patch.a / s.in.patch.b));
    // The exact solution obeys the Coulomb bound.
    CHECK(std::hypot(s.Fx, s.Fy) <= s.muN() * (1.0 + 1e-9));
  }
  CHECK(quadrants.size() == 8);
  CHECK(max_spin == Approx(5.0));
  CHECK(aob == std::set<long>{20, 100, 133, 500});
}

namespace {
// Largest |F_a - F_b| / (mu Fz) per family, and the states with spin above `limit`.
struct GridDifference {
  std::map<std::string, double> worst;
  int above = 0, with_spin = 0;
};
GridDifference grid_difference(const std::vector<ReferenceState>& a, const std::vector<ReferenceState>& b,
                               double limit) {
  REQUIRE(a.size() == b.size());
  GridDifference g;
  for (std::size_t i = 0; i < a.size(); ++i) {
    REQUIRE(a[i].id == b[i].id);
    const double d = std::hypot(a[i].Fx - b[i].Fx, a[i].Fy - b[i].Fy) / b[i].muN();
    g.worst[b[i].family] = std::max(g.worst[b[i].family], d);
    if (b[i].in.creep.phi != 0.0) {
      ++g.with_spin;
      g.above += d > limit;
    }
  }
  return g;
}
std::string describe(const GridDifference& g) {
  std::ostringstream s;
  s << "largest % of mu Fz: spin " << 100 * g.worst.at("spin") << ", long_spin " << 100 * g.worst.at("long_spin")
    << ", lat_spin " << 100 * g.worst.at("lat_spin") << ", combined " << 100 * g.worst.at("combined")
    << ", creep (no spin) " << 100 * g.worst.at("creep") << "; " << g.above << " of " << g.with_spin
    << " states with spin above 0.3 %";
  return s.str();
}
}  // namespace

TEST_CASE("reference set: MIM grid convergence with spin, grid 60 against grid 120", "[contact][reference][mim]") {
  // Issue 15: MIM with spin within 0.3 % of mu Fz of its grid-120 solution at
  // grid 60. The registered model "mim" extrapolates (Richardson, from the
  // grid and the half grid): grid 60 = 2 F_60 - F_30 against grid 120 =
  // 2 F_120 - F_60, measured over all 764 states: largest 0.232 %
  // (aob5/lat_spin/0/0.0005/-0.5), mean 0.03 %. Without extrapolation (CONTACT's
  // discretisation, first order) grid 60 and 120 differ by up to 0.487 %
  // (lateral creepage against spin, a/b 1.33), 8 states above 0.3 %, and pure
  // creepage by 0.39 %.
  const auto plain30 = load_reference_set("mim_grid30.csv");
  const auto plain60 = load_reference_set("mim_grid60.csv");
  const auto plain120 = load_reference_set("mim_grid120.csv");
  const auto plain = grid_difference(plain60, plain120, 0.003);
  WARN("MIM without extrapolation, grid 60 vs 120, " << describe(plain));
  CHECK(plain.with_spin == 688);
  CHECK(plain.worst.at("lat_spin") > 0.004);  // the first-order error the extrapolation removes
  CHECK(plain.above > 0);  // the plain grids miss the 0.3 %; the extrapolation below meets it

  // First order: halving the element size halves the difference (the premise
  // of the extrapolation), on the states where the grid matters.
  double ratio_sum = 0.0;
  int ratios = 0;
  for (std::size_t i = 0; i < plain60.size(); ++i) {
    const double d1 = std::hypot(plain30[i].Fx - plain60[i].Fx, plain30[i].Fy - plain60[i].Fy);
    const double d2 = std::hypot(plain60[i].Fx - plain120[i].Fx, plain60[i].Fy - plain120[i].Fy);
    if (d2 < 1e-3 * plain120[i].muN()) continue;
    ratio_sum += d1 / d2;
    ++ratios;
  }
  INFO("mean ratio of successive grid differences " << ratio_sum / ratios << " over " << ratios << " states");
  CHECK(ratios > 100);
  CHECK(ratio_sum / ratios == Approx(2.0).margin(0.3));

  const auto e60 = extrapolated_reference_set("mim_grid60.csv", "mim_grid30.csv");
  const auto e120 = reference();
  const auto ex = grid_difference(e60, e120, 0.003);
  WARN("MIM (extrapolated), grid 60 vs 120, " << describe(ex));
  CHECK(ex.with_spin == 688);
  for (const auto& [family, d] : ex.worst) {
    INFO(family);
    CHECK(d < 0.003);
  }
  CHECK(ex.above == 0);

  // The files are the live solver's: every 25th state solved again at grid 60,
  // plain and as the registered (extrapolating) model.
  const auto none = make_tangential_model("mim", {60, 1e-8, "", "none", GridExtrapolation::None});
  const auto model = make_tangential_model("mim", {60, 1e-8, ""});
  auto ws_none = none->make_workspace();
  auto ws = model->make_workspace();
  int n = 0;
  for (std::size_t i = 0; i < plain60.size(); i += 25) {
    const ContactForces f = none->solve(plain60[i].in, ws_none.get());
    const ContactForces r = model->solve(plain60[i].in, ws.get());
    INFO(plain60[i].id);
    CHECK(std::abs(f.Fx - plain60[i].Fx) <= 1e-6 * plain60[i].muN());
    CHECK(std::abs(f.Fy - plain60[i].Fy) <= 1e-6 * plain60[i].muN());
    CHECK(std::abs(r.Fx - e60[i].Fx) <= 1e-6 * e60[i].muN());
    CHECK(std::abs(r.Fy - e60[i].Fy) <= 1e-6 * e60[i].muN());
    ++n;
  }
  CHECK(n >= 30);
}

TEST_CASE("reference set: FaStrip is closer than FASTSIM, within 10 % of mu Fz", "[contact][reference][fastrip]") {
  // Measured (grid 20 x 20) against the extrapolated reference: fastrip max
  // 8.95 % (aob5/lat_spin/0/0.01/-2), mean 2.23 %; fastsim (blended)
  // 21.4 %, 2.83 %; fastsim_kalker 24.0 %, 4.20 %. Before issue 15 FaStrip
  // stalled with lateral creepage opposing spin: max 119 % of mu Fz; then
  // 10.40 % (aob5/lat_spin/0/0.001/-1: the Winkler spin part 9 % low at the
  // pure-spin peak on a/b 5) until the per-strip lateral spin flexibility and
  // the substeps of the sliding march (fastrip.hpp, steps 4b and 4c), which
  // meet the 10 % (10 x 10 9.88 %, 40 x 40 9.29 %, 80 x 80 9.85 %).
  const auto& set = reference();
  const auto fr = make_tangential_model("fastrip");
  const auto fs = make_tangential_model("fastsim");
  const auto fk = make_tangential_model("fastsim_kalker");
  const auto efr = set_error(*fr, set, all), efs = set_error(*fs, set, all), efk = set_error(*fk, set, all);
  WARN("fastrip max " << 100 * efr.max << " % (" << efr.worst << "), mean " << 100 * efr.mean << " %; fastsim max "
                      << 100 * efs.max << " % (" << efs.worst << "), mean " << 100 * efs.mean << " %; fastsim_kalker max "
                      << 100 * efk.max << " %, mean " << 100 * efk.mean << " %");
  CHECK(efr.max < 0.10);
  CHECK(efr.max < efs.max);
  CHECK(efr.max < efk.max);
  CHECK(efr.mean < efs.mean);
  // Per family: FaStrip's largest error is below FASTSIM's; in `combined`
  // (xi, eta, phi together) the check is the 10 % target (measured: fastrip
  // 5.96 %, fastsim 9.69 %, both at aob5/combined/0.001/-0.001/1; before
  // steps 4b and 4c fastrip 9.77 %). Means: below FASTSIM's in every family
  // (longitudinal creepage + spin 2.59 % against 2.72 %, before 3.03 %; not
  // checked there).
  for (const char* fam : {"lat_spin", "long_spin", "spin", "creep", "combined"}) {
    const auto in_family = [&](const ReferenceState& s) { return s.family == fam; };
    const auto a = set_error(*fr, set, in_family), b = set_error(*fs, set, in_family);
    INFO(fam << ": fastrip " << a.max << " (" << a.worst << "), fastsim " << b.max << " (" << b.worst << "); means "
             << a.mean << ", " << b.mean);
    if (std::string(fam) == "combined")
      CHECK(a.max < 0.10);
    else
      CHECK(a.max < b.max);
    if (std::string(fam) != "long_spin") CHECK(a.mean < b.mean);
  }
  // The stall of issue 15: circular patch, phi = 1 1/m, eta = -0.01 (CONTACT
  // +0.936 mu Fz; FaStrip gave +0.198, now +0.898: 3.7 % of mu Fz off).
  for (const auto& s : set)
    if (s.id == "aob1/lat_spin/0/-0.01/1" || s.id == "aob1/lat_spin/0/0.01/-1") {
      const ContactForces f = fr->solve(s.in);
      INFO(s.id << ": fastrip Fy " << f.Fy / s.muN() << " mu Fz, exact " << s.Fy / s.muN());
      CHECK(std::abs(s.Fy) > 0.9 * s.muN());
      CHECK(force_error(f, s) < 0.05);
    }
}

TEST_CASE("deep slip with spin: FaStrip within 2 % of mu Fz for every sign combination", "[contact][reference][fastrip]") {
  // tests/data/contact/deep_slip: 96 states, 545 N on a/b 0.25, 1, 2.7, 5,
  // creepage 1, 3, 10 times (0.00504, 0.00346) with spin 0.633 1/m, all eight
  // sign combinations of (xi, eta, phi), against MIM grid 60 (extrapolated).
  // Before the full-slip trigger (fastrip.hpp, step 4) FaStrip gave up to
  // 54 % of mu Fz here whenever spin opposed the strip traction; measured
  // now: fastrip 0.61 % max, 0.13 % mean (before fastrip.hpp steps 4b and
  // 4c 1.31 %, 0.32 %); fastsim 4.04 %; fastsim_kalker 11.9 %.
  const auto set = load_reference_set("mim_grid60.csv", "deep_slip");
  REQUIRE(set.size() == 96);
  const auto fr = set_error(*make_tangential_model("fastrip"), set, all);
  const auto fs = set_error(*make_tangential_model("fastsim"), set, all);
  WARN("deep slip: fastrip max " << 100 * fr.max << " % (" << fr.worst << "), mean " << 100 * fr.mean
                                 << " %; fastsim max " << 100 * fs.max << " % (" << fs.worst << ")");
  CHECK(fr.max < 0.02);
  CHECK(fr.max < fs.max);
  // Every sign combination separately, so an asymmetry cannot hide in the maximum.
  for (const char* signs : {"+1+1+1", "+1+1-1", "+1-1+1", "+1-1-1", "-1+1+1", "-1+1-1", "-1-1+1", "-1-1-1"}) {
    const auto e = set_error(*make_tangential_model("fastrip"), set, [&](const ReferenceState& s) {
      return s.id.size() > 6 && s.id.compare(s.id.size() - 6, 6, signs) == 0;
    });
    const auto n = std::count_if(set.begin(), set.end(), [&](const ReferenceState& s) {
      return s.id.compare(s.id.size() - 6, 6, signs) == 0;
    });
    INFO(signs << ": " << e.max << " (" << e.worst << ") over " << n << " states");
    CHECK(n == 12);  // 4 patches x 3 creepage levels
    CHECK(e.max < 0.02);
  }
  // The file is the live solver's (registered mim at grid 60).
  const auto mim = make_tangential_model("mim", {60, 1e-8, ""});
  for (std::size_t i = 0; i < set.size(); i += 17) {
    const ContactForces f = mim->solve(set[i].in);
    INFO(set[i].id);
    CHECK(std::abs(f.Fx - set[i].Fx) <= 1e-6 * set[i].muN());
    CHECK(std::abs(f.Fy - set[i].Fy) <= 1e-6 * set[i].muN());
  }
}

TEST_CASE("reference set: FASTSIM's flexibility blending is the more accurate variant (the default)", "[contact][reference][fastsim]") {
  const auto& set = reference();
  const auto blended = set_error(*make_tangential_model("fastsim"), set, all);
  const auto three = set_error(*make_tangential_model("fastsim_kalker"), set, all);
  const auto parabolic = set_error(*make_tangential_model("fastsim_parabolic"), set, all);
  WARN("fastsim (blended) max " << 100 * blended.max << " %, mean " << 100 * blended.mean << " %; fastsim_kalker "
                                << 100 * three.max << " %, " << 100 * three.mean << " %; fastsim_parabolic "
                                << 100 * parabolic.max << " %, " << 100 * parabolic.mean << " %");
  CHECK(blended.max < three.max);
  CHECK(blended.mean < three.mean);
  CHECK(blended.mean < parabolic.mean);
}

TEST_CASE("reference set: no tangential model returns |F| > mu Fz, a law limited by more than 0.1 % says so", "[contact][reference][coulomb]") {
  const auto& set = reference();
  for (const auto& e : tangential_models()) {
    const std::string name = e.name;
    if (!e.compared_by_default() || name == "mim" || name == "linear") continue;  // mim: own test; linear: unsaturated by definition
    const auto model = e.make({});
    auto ws = model->make_workspace();
    double worst = 0.0;
    int flagged = 0;
    for (const auto& s : set) {
      const ContactForces f = model->solve(s.in, ws.get());
      worst = std::max(worst, std::hypot(f.Fx, f.Fy) / s.muN());
      if (!f.valid && std::string(f.reason).find("limited to mu Fz") != std::string::npos) ++flagged;
    }
    INFO(name << ": max |F| / (mu Fz) " << worst << ", " << flagged << " states flagged as limited");
    CHECK(worst <= 1.0 + 1e-12);
    // Polach's spin term is superposed on the creep force: its formula exceeds
    // mu Fz with spin (up to 1.46 mu Fz here) and those states are flagged.
    if (name == "polach") CHECK(flagged > 20);
  }
}

TEST_CASE("reference set: every model reproduces the mirror images exactly", "[contact][reference][symmetry]") {
  // Exact for the half-space problem: (xi, -eta, -phi) -> (Fx, -Fy, -Mz)
  // (mirror y -> -y) and (-xi, eta, phi) -> (-Fx, Fy, Mz) (that mirror of the
  // full reversal). The reference set holds every state with its images.
  const auto& set = reference();
  std::map<std::string, const ReferenceState*> by_id;
  for (const auto& s : set) by_id[s.id] = &s;
  const auto image_id = [](const ReferenceState& s, double sx, double sy) {
    const auto g = [](double v) {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%g", v == 0.0 ? 0.0 : v);
      return std::string(buf);
    };
    return s.patch + "/" + s.family + "/" + g(sx * s.in.creep.xi) + "/" + g(sy * s.in.creep.eta) + "/" +
           g(sy * s.in.creep.phi);
  };
  int pairs = 0;
  for (const auto& e : tangential_models()) {
    if (!e.compared_by_default() || std::string(e.name) == "mim") continue;
    const auto model = e.make({});
    for (const auto& s : set) {
      for (const auto& [sx, sy] : {std::pair{1.0, -1.0}, std::pair{-1.0, 1.0}}) {
        const auto it = by_id.find(image_id(s, sx, sy));
        if (it == by_id.end() || it->second == &s) continue;
        const ContactForces f = model->solve(s.in), g = model->solve(it->second->in);
        const double tol = 1e-9 * s.muN();
        INFO(e.name << ": " << s.id << " and its image " << it->second->id);
        CHECK(std::abs(g.Fx - sx * f.Fx) <= tol);
        CHECK(std::abs(g.Fy - sy * f.Fy) <= tol);
        CHECK(std::abs(g.Mz - sy * f.Mz) <= tol * std::sqrt(s.in.patch.a * s.in.patch.b));
        ++pairs;
      }
    }
  }
  CHECK(pairs > 5000);
  // The exact reference itself (MIM grid 120, extrapolated) has the symmetry to its tolerance.
  for (const auto& s : set) {
    const auto it = by_id.find(image_id(s, 1.0, -1.0));
    if (it == by_id.end()) continue;
    CHECK(std::abs(it->second->Fy + s.Fy) <= 1e-5 * s.muN());
    CHECK(std::abs(it->second->Fx - s.Fx) <= 1e-5 * s.muN());
  }
}

TEST_CASE("reference set: the standard mim_table within 2 % of mu Fz everywhere (builds the table)", "[contact][reference][mim_table][.slow]") {
  // Builds MimTableSpec::standard() (56,277 solves, several minutes on two
  // cores) in $RAILSIM_CACHE_DIR or the user cache on first use.
  const auto model = make_tangential_model("mim_table");
  const auto e = set_error(*model, reference(), all);
  WARN("mim_table max " << 100 * e.max << " % of mu Fz (" << e.worst << "), mean " << 100 * e.mean << " %");
  CHECK(e.max < 0.02);
}
