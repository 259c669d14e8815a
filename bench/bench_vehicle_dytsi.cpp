// railsim against DYTSI (the open-source DTU code, daniele-bigoni/dytsi, BDF
// solver) on the same Cooperrider car, RSGEO table and start
// (scenarios/cooperrider_car_dytsi.yaml: 5 mm on the leading wheelset,
// straight perfect track, 20 s), both wheelset models, at 60 and 100 m/s
// (decaying) and 120 and 130 m/s (hunting).
// Counters: cpu_per_sim_s = CPU seconds of the run per simulated second;
// vs_dytsi = DYTSI's CPU seconds per simulated second on this machine kind
// (measured side by side: 0.68, 0.62, 2.56, 2.42 s at 60, 100, 120, 130 m/s)
// divided by ours; steps, rhs_calls, jac = Jacobian evaluations; LL_mm and
// LL_Hz: amplitude and frequency of the leading wheelset's lateral motion over
// the last 5 s (DYTSI at 120 m/s: 4.36 mm, 5.80 Hz).
// Four variants: `dytsi` (full, lateral) runs the scenario as it is (DYTSI's tolerances, no
// contact damping, max step 2 ms); `damped` adds what a vehicle code would
// use: track damping under each wheel (contact.normal_damping 2e5 N s/m, as
// in the coach's scenarios; it damps the ~266 Hz wheelset bounce on the Hertz
// springs, zeta 3.6e-5 without it), a looser absolute tolerance of those
// contact modes (bounce and spin, 1e-4 m/s, rad/s) and a 10 ms step cap (the
// output interval); the lateral model the step cap and the spin tolerance.
// The full model's `damped` also turns on CVODE's BDF stability-limit
// detection (orders 3-5 are not A-stable: at rtol 1e-6 the bounce's eigenvalue
// near the imaginary axis otherwise caps the step; 100 m/s: 36.7k steps
// without, 2.3k with). `damped_rtol1e-4` is `damped` at rtol 1e-4, atol 1e-6
// without the detection: at that tolerance the bounce does not cap the step
// (100 m/s: 2,279 steps either way) and the detection costs steps and CPU
// time while hunting (130 m/s: 30.5k against 27.0k steps, 0.031 against
// 0.025 s per s). The limit cycle is unchanged (LL within 0.03 % of the dytsi
// variant, checked by the LL counters). `contact_modes` is the scenario as it
// is with only the contact modes' absolute tolerance loosened (1e-4 m/s,
// rad/s; no damping, DYTSI's rtol and atol for everything else): the model is
// DYTSI's, and the step count shows what the undamped bounce costs at atol
// 1e-8 (issue 13's step count: 120 m/s full model 164k steps -> 87k, LL
// unchanged; the wheel load within 0.09 % of Q of a run at rtol 1e-8).
#include <benchmark/benchmark.h>
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <string>
#include <vector>

#include "engine/io/scenario.hpp"
#include "engine/simulation.hpp"
#include "engine/system.hpp"
#include "results/limit_cycle.hpp"

namespace {

using namespace railsim;

double dytsi_cpu(double V) {
  if (V < 80) return 0.68;
  if (V < 110) return 0.62;
  if (V < 125) return 2.56;
  return 2.42;
}

enum class Variant { dytsi, contact_modes, damped, damped_loose };

void cooperrider(benchmark::State& state, const char* wheelset_model, Variant variant) {
  const double V = double(state.range(0));
  const auto path = (std::filesystem::path(RAILSIM_SOURCE_DIR) / "scenarios" /
                     "cooperrider_car_dytsi.yaml").string();
  double cpu = 0, steps = 0, calls = 0, jac = 0, amp = 0, freq = 0;
  for (auto _ : state) {
    YAML::Node node = YAML::LoadFile(path);
    node["speed"] = V;
    node["wheelset_model"] = wheelset_model;
    if (variant == Variant::contact_modes) node["integrator"]["atol_contact_modes"] = 1e-4;
    if (variant != Variant::dytsi && variant != Variant::contact_modes) {
      if (variant == Variant::damped_loose) {
        node["integrator"]["rtol"] = 1e-4;
        node["integrator"]["atol"] = 1e-6;
      }
      node["integrator"]["max_step"] = 0.01;
      node["integrator"]["atol_contact_modes"] = 1e-4;
      if (std::string(wheelset_model) == "full") {
        node["contact"]["normal_damping"] = 2e5;
        if (variant == Variant::damped) node["integrator"]["stability_limit_detection"] = true;
      }
    }
    const engine::Scenario s =
        engine::load_scenario(config::InputNode(node, path, ""), std::filesystem::path(path).parent_path().string());
    std::vector<double> t, y;
    const int qi = s.model.bodies[s.model.wheelsets[0].body].q_index[engine::kLat];
    const auto r = engine::simulate(s.model, s.integrator, s.x0, s.duration, s.output_interval,
                                    [&](double tt, const Eigen::VectorXd& x, const engine::Data&) {
                                      if (tt >= s.duration - 5.0) {
                                        t.push_back(tt);
                                        y.push_back(x[qi]);
                                      }
                                    });
    cpu = r.cpu_time / s.duration;
    steps = double(r.stats.steps);
    calls = double(r.stats.rhs_calls);
    jac = double(r.stats.jacobian_evals);
    const auto lc = results::settled_amplitude(t, y, 1.0);
    amp = lc.amplitude * 1e3;
    freq = lc.frequency;
  }
  state.counters["cpu_per_sim_s"] = cpu;
  state.counters["vs_dytsi"] = dytsi_cpu(V) / cpu;
  state.counters["steps"] = steps;
  state.counters["rhs_calls"] = calls;
  state.counters["jac"] = jac;
  state.counters["LL_mm"] = amp;
  state.counters["LL_Hz"] = freq;
}

}  // namespace

#define RAILSIM_COOPERRIDER(name, model, variant) \
  BENCHMARK_CAPTURE(cooperrider, name, model, variant)->Arg(60)->Arg(100)->Arg(120)->Arg(130)->Unit(benchmark::kSecond)->Iterations(1)
RAILSIM_COOPERRIDER(full, "full", Variant::dytsi);
RAILSIM_COOPERRIDER(lateral, "lateral", Variant::dytsi);
RAILSIM_COOPERRIDER(full_contact_modes, "full", Variant::contact_modes);
RAILSIM_COOPERRIDER(lateral_contact_modes, "lateral", Variant::contact_modes);
RAILSIM_COOPERRIDER(full_damped, "full", Variant::damped);
RAILSIM_COOPERRIDER(lateral_damped, "lateral", Variant::damped);
RAILSIM_COOPERRIDER(full_damped_rtol1e-4, "full", Variant::damped_loose);
RAILSIM_COOPERRIDER(lateral_damped_rtol1e-4, "lateral", Variant::damped_loose);

BENCHMARK_MAIN();
