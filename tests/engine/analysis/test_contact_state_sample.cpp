// The contact states of a run (engine/analysis/contact_state_sample.hpp): the
// recorded states are the run's own (each patch's input gives back, through
// the run's model, the force the run used; per wheel the patches add up to
// the wheel's normal load and creep forces of the output row), and a sample
// holds the run's extremes and spreads the rest evenly over the run's time.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <set>

#include "contact/registry.hpp"
#include "core/errors.hpp"
#include "engine/analysis/contact_state_sample.hpp"
#include "engine/io/scenario.hpp"
#include "engine/simulation.hpp"
#include "test_support.hpp"

using namespace railsim;
using namespace railsim::engine;

namespace {
// The main job's coach (profiles geometry, CHOPAYA) released with every body
// shifted 4 mm: its wheelsets move across the rails (tread to flange root).
struct RecordedRun {
  Scenario sc;
  ContactStateRecorder rec;
  std::vector<std::vector<WheelOutput>> wheels;  // per output row
  std::vector<double> times;
};

const RecordedRun& recorded_run() {
  static RecordedRun r = [] {
    RecordedRun run{load_scenario(test::source_path("scenarios/manchester_coach_critical_speed.yaml")), {}, {}, {}};
    run.sc.duration = 0.6;
    Eigen::VectorXd x0 = run.sc.x0;
    for (const auto& b : run.sc.model.bodies) x0[b.q_index[kLat]] += 0.004;
    simulate(run.sc.model, run.sc.integrator, x0, run.sc.duration, run.sc.output_interval,
             [&](double t, const Eigen::VectorXd&, const Data& d) {
               run.rec.record(run.sc.model, t, d);
               run.wheels.push_back(d.wheel);
               run.times.push_back(t);
             });
    return run;
  }();
  return r;
}
}  // namespace

TEST_CASE("contact states: the recorded patches are the run's own", "[analysis][audit]") {
  const RecordedRun& r = recorded_run();
  const auto& st = r.rec.states();
  REQUIRE(r.rec.rows() == r.times.size());  // every output row has loaded patches
  REQUIRE(st.size() >= 8 * r.times.size());
  const auto model = contact::make_tangential_model(r.sc.model.coupling.options().tangential);
  const auto ws = model->make_workspace();
  for (std::size_t row = 0; row < r.rec.rows(); ++row) {
    const std::size_t b = r.rec.row_start()[row], e = row + 1 < r.rec.rows() ? r.rec.row_start()[row + 1] : st.size();
    std::vector<double> N(r.wheels[row].size(), 0.0), Fx(N), Fy(N), Mz(N);
    for (std::size_t i = b; i < e; ++i) {
      const RunContactState& s = st[i];
      REQUIRE(s.t == r.times[row]);
      const std::size_t wheel = 2 * static_cast<std::size_t>(s.wheelset) + static_cast<std::size_t>(s.side);
      N[wheel] += s.input.patch.Fz;
      Fx[wheel] += s.forces.Fx;
      Fy[wheel] += s.forces.Fy;
      Mz[wheel] += s.forces.Mz;
      // The run's model on the recorded input gives the recorded force: it is what the model was given.
      const contact::ContactForces f = model->solve(s.input, ws.get());
      CHECK(f.Fx == s.forces.Fx);
      CHECK(f.Fy == s.forces.Fy);
      CHECK(f.Mz == s.forces.Mz);
      CHECK(s.input.patch.a > 0.0);
      CHECK(s.input.patch.b > 0.0);
      CHECK(s.input.material.mu == r.sc.model.coupling.options().material.mu);
      CHECK(s.input.rolling_speed > 0.0);
    }
    // Per wheel the patches add up to the output row's wheel (the channels' Q, Fx, Fy, Mz come from it).
    for (std::size_t w = 0; w < N.size(); ++w) {
      const WheelOutput& o = r.wheels[row][w];
      CHECK(N[w] == Approx(o.N).epsilon(1e-12));
      CHECK(Fx[w] == Approx(o.Fx).epsilon(1e-12).margin(1e-9));
      CHECK(Fy[w] == Approx(o.Fy).epsilon(1e-12).margin(1e-9));
      CHECK(Mz[w] == Approx(o.Mz).epsilon(1e-12).margin(1e-9));
    }
  }
}

TEST_CASE("contact states: a sample holds the run's extremes and spreads the rest over the run", "[analysis][audit]") {
  const RecordedRun& r = recorded_run();
  const auto& st = r.rec.states();
  for (const int n : {3, 9, 40, 101}) {
    INFO("n = " << n);
    const ContactStateSample smp = sample_contact_states(r.rec, n);
    REQUIRE(smp.index.size() == static_cast<std::size_t>(n));
    REQUIRE(smp.why.size() == smp.index.size());
    const std::set<std::size_t> unique(smp.index.begin(), smp.index.end());
    CHECK(unique.size() == smp.index.size());
    // The extremes of the whole run, in their order.
    const auto argmax = [&](auto key) {
      std::size_t best = 0;
      for (std::size_t i = 1; i < st.size(); ++i)
        if (key(st[i]) > key(st[best])) best = i;
      return best;
    };
    const std::size_t maxN = argmax([](const RunContactState& s) { return s.input.patch.Fz; });
    const std::size_t maxPhi = argmax([](const RunContactState& s) { return std::fabs(s.input.creep.phi); });
    const std::size_t maxCreep =
        argmax([](const RunContactState& s) { return std::hypot(s.input.creep.xi, s.input.creep.eta); });
    const std::size_t maxAngle = argmax([](const RunContactState& s) { return std::fabs(s.contact_angle); });
    CHECK(smp.index[0] == maxN);
    CHECK(smp.why[0] == "max normal load");
    if (n >= 9) {
      for (const std::size_t i : {maxN, maxPhi, maxCreep, maxAngle}) CHECK(unique.count(i) == 1);
      CHECK(st[maxAngle].contact_angle > 0.1);  // the shifted coach reaches its flange root
    }
    // The rest: one per equal time slot of the run, in time order.
    std::vector<double> even;
    for (std::size_t k = 0; k < smp.index.size(); ++k)
      if (smp.why[k] == "even in time") even.push_back(st[smp.index[k]].t);
    const std::size_t m = even.size();
    CHECK(m + 9 >= static_cast<std::size_t>(n));
    const double dt = r.sc.output_interval, T = r.times.back() + dt;  // rows cover [0, T)
    for (std::size_t j = 0; j < m; ++j) {  // within its slot, up to the output interval
      CHECK(even[j] >= T * static_cast<double>(j) / static_cast<double>(m) - dt - 1e-9);
      CHECK(even[j] < T * static_cast<double>(j + 1) / static_cast<double>(m) + 1e-9);
      if (j > 0) CHECK(even[j] >= even[j - 1]);
    }
    if (m >= 2) CHECK(even.back() - even.front() > 0.5 * r.times.back());
  }
  // Successive even samples walk through the wheels, not always the same one.
  const ContactStateSample s40 = sample_contact_states(r.rec, 40);
  std::set<std::pair<int, int>> wheels;
  for (std::size_t k = 0; k < s40.index.size(); ++k) wheels.insert({st[s40.index[k]].wheelset, st[s40.index[k]].side});
  CHECK(wheels.size() == 8);
  // As many as recorded or more: all of them.
  const ContactStateSample all = sample_contact_states(r.rec, static_cast<int>(std::min<std::size_t>(st.size(), 10000)));
  if (st.size() <= 10000) {
    CHECK(all.index.size() == st.size());
    CHECK(all.why.front() == "all");
  }
}

TEST_CASE("contact states: bad sample sizes are named", "[analysis][audit][input]") {
  const RecordedRun& r = recorded_run();
  CHECK_THROWS_WITH(sample_contact_states(r.rec, 0), Catch::Contains("[1, 10000]"));
  CHECK_THROWS_WITH(sample_contact_states(r.rec, -3), Catch::Contains("[1, 10000]"));
  CHECK_THROWS_WITH(sample_contact_states(r.rec, 10001), Catch::Contains("[1, 10000]"));
  const ContactStateRecorder empty;
  CHECK_THROWS_AS(sample_contact_states(empty, 5), InputError);
}
