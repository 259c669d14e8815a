// Python bindings of scenarios and the analyses over them: a scenario loaded
// from a YAML file or from text (the Python wrapper turns a dict into JSON,
// which is YAML), run (engine/analysis/scenario_run.hpp: channels and the
// summary document of `railsim run`), the critical speed (the library call of
// `railsim critical-speed`, engine::analyse_critical_speed, with the settings
// resolved as the command resolves them), and the
// modes versus speed (engine/analysis/mode_sweep.hpp, as `railsim modes`).
// Speeds in km/h and shifts in mm where the command line has them; the
// returned arrays say their unit in their name. The GIL is released while the
// engine runs.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <filesystem>
#include <optional>
#include <string>

#include "config/yaml_input.hpp"
#include "contact/reduction.hpp"
#include "core/errors.hpp"
#include "core/output_lock.hpp"
#include "engine/analysis/critical_speed.hpp"
#include "engine/analysis/critical_speed_study.hpp"
#include "engine/analysis/sweep_limits.hpp"
#include "engine/analysis/mode_sweep.hpp"
#include "engine/analysis/scenario_run.hpp"
#include "engine/io/scenario.hpp"
#include "python/src/bindings.hpp"
#include "python/src/keyboard_interrupt.hpp"

namespace py = pybind11;

namespace railsim::python {

namespace {

py::array_t<double> to_array(const std::vector<double>& v) {
  py::array_t<double> a(static_cast<py::ssize_t>(v.size()));
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

engine::Scenario from_text(const std::string& text, const std::string& name, const std::string& base_dir) {
  const auto root = config::InputNode::load_string(text, name);
  engine::Scenario s = engine::load_scenario(root, base_dir);
  s.file = name;
  if (s.name.empty()) s.name = "scenario";
  return s;
}

py::dict run(const engine::Scenario& sc, const std::string& out_dir) {
  engine::ScenarioRunOptions o;
  o.out_dir = out_dir;
  o.keep_channels = true;
  o.stop = keyboard_interrupt_request();  // Ctrl-C: files up to then, then KeyboardInterrupt
  // One writer per output folder, as the program (a running `railsim` in it: InputError naming its pid).
  std::optional<OutputLock> lock;
  if (!out_dir.empty()) lock.emplace(out_dir, "run");
  engine::ScenarioRunResult r;
  {
    py::gil_scoped_release release;
    r = engine::run_scenario(sc, o);
  }
  const std::size_t nc = r.channel_names.size();
  py::array_t<double> data({static_cast<py::ssize_t>(r.rows), static_cast<py::ssize_t>(nc)});
  std::copy(r.channels.begin(), r.channels.end(), data.mutable_data());
  py::dict d;
  d["names"] = r.channel_names;
  d["data"] = data;
  d["summary_json"] = r.summary.dump(0);
  return d;
}

py::dict critical_speed(const engine::Scenario& base, const std::string& method, const std::string& model,
                        const std::string& reduction, double v_min_kmh, double v_max_kmh, double v_step_kmh,
                        double duration, double disturbance_mm, double small_disturbance_mm, double threshold_mm,
                        double deceleration, bool up_branch, int continuation, int threads, const std::string& dir) {
  contact::ReductionFactors k;
  const contact::ReductionFactors* kp = nullptr;
  if (!reduction.empty()) {
    k = contact::parse_reduction(reduction, "reduction");
    kp = &k;
  }
  const engine::Scenario sc = engine::with_contact(base, model, kp);
  // The settings as `railsim critical-speed` resolves them: the scenario's
  // critical_speed section, then what the call gives (NaN = not given).
  engine::CriticalSpeedStudySettings st = engine::study_settings(sc.critical_speed);
  st.method = engine::parse_critical_speed_method(method, "method");
  engine::CriticalSpeedOverrides given;
  given.v_min_kmh = v_min_kmh;
  given.v_max_kmh = v_max_kmh;
  given.v_step_kmh = v_step_kmh;
  given.duration = duration;
  given.large_disturbance_mm = disturbance_mm;
  given.small_disturbance_mm = small_disturbance_mm;
  given.threshold_mm = threshold_mm;
  given.deceleration = deceleration;
  if (continuation >= 0) given.continuation = continuation == 1;
  given.v_max_name = "v_max_kmh";
  engine::apply_overrides(st, given);
  st.up_branch = up_branch;
  st.threads = threads;
  st.stop = keyboard_interrupt_request();  // Ctrl-C: finished points stay for the resume
  // The command line's ranges, naming the arguments.
  engine::check_given_settings(given, threads);
  engine::check_speed_range(st.v_min * 3.6, st.v_max * 3.6, st.v_step * 3.6, {"v_min_kmh", "v_max_kmh", "v_step_kmh"});
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw InputError(dir + ": cannot create the output folder (" + ec.message() + ")");
  const OutputLock lock(dir, "critical-speed");  // one writer per output folder, as the program

  engine::CriticalSpeedOutcome r;
  {
    py::gil_scoped_release release;
    r = engine::analyse_critical_speed(sc, st, dir);
  }
  py::dict d;
  d["scenario"] = sc.name;
  d["method"] = method;
  d["contact_model"] = sc.model.coupling.options().tangential;
  d["contact_description"] = sc.model.coupling.describe();
  d["reduction"] = contact::describe_reduction(sc.model.coupling.options().reduction);
  py::dict settings;
  settings["v_min_kmh"] = engine::given_kmh(st.v_min), settings["v_max_kmh"] = engine::given_kmh(st.v_max);
  settings["threshold_mm"] = engine::given_mm(st.threshold);
  if (st.method == engine::CriticalSpeedMethod::bifurcation) {
    std::vector<double> v, amp, freq, growth;
    std::vector<std::string> branch, state;
    std::vector<bool> failed, numerical_failure, continued;
    const engine::BifurcationOptions bo = engine::bifurcation_options(st);
    for (const auto& p : r.bifurcation.points) {
      v.push_back(engine::given_kmh(p.speed)), amp.push_back(p.amplitude * 1e3), freq.push_back(p.frequency);
      growth.push_back(p.growth), branch.push_back(engine::branch_name(p.branch)), failed.push_back(p.failed);
      numerical_failure.push_back(p.numerical_failure);
      state.push_back(engine::point_state_name(engine::point_state(p, bo)));
      continued.push_back(p.continued);
    }
    py::dict pts;
    pts["speed_kmh"] = to_array(v), pts["branch"] = branch, pts["amplitude_mm"] = to_array(amp);
    pts["frequency_hz"] = to_array(freq), pts["growth"] = to_array(growth), pts["failed"] = failed;
    pts["numerical_failure"] = numerical_failure, pts["state"] = state;
    pts["continued"] = continued;
    d["points"] = pts;
    // No critical speed because of a numerical failure or runs too short: why (None: the verdict stands).
    d["undetermined"] = r.bifurcation.undetermined.empty() ? py::object(py::none())
                                                           : py::object(py::str(r.bifurcation.undetermined));
    settings["v_step_kmh"] = engine::given_kmh(st.v_step), settings["duration_s"] = st.duration;
    settings["large_disturbance_mm"] = engine::given_mm(st.large_disturbance);
    settings["small_disturbance_mm"] = engine::given_mm(st.small_disturbance);
    settings["up_branch"] = st.up_branch, settings["continuation"] = st.continuation;
  } else {
    const engine::RampingResult& rr = r.ramping;
    std::vector<double> v(rr.speed.size()), y(rr.max_lateral.size());
    for (std::size_t i = 0; i < v.size(); ++i) v[i] = rr.speed[i] * 3.6;
    for (std::size_t i = 0; i < y.size(); ++i) y[i] = rr.max_lateral[i] * 1e3;
    py::dict rec;
    rec["time_s"] = to_array(rr.time), rec["speed_kmh"] = to_array(v), rec["max_lateral_mm"] = to_array(y);
    d["ramping"] = rec;
    d["hunting_at_start"] = rr.hunting_at_start;
    d["hunting_at_end"] = rr.hunting_at_end;
    d["derailment"] = rr.derailment.empty() ? py::object(py::none()) : py::object(py::str(rr.derailment));
    d["left_model_range"] = rr.range_stop.empty() ? py::object(py::none()) : py::object(py::str(rr.range_stop));
    settings["start_speed_kmh"] = engine::given_kmh(st.ramp_start), settings["disturbance_mm"] = engine::given_mm(st.ramp_disturbance);
    settings["deceleration_m_s2"] = st.deceleration;
  }
  d["critical_speed_kmh"] = std::isnan(r.critical) ? py::object(py::none()) : py::object(py::float_(engine::given_kmh(r.critical)));
  d["linear_critical_speed_kmh"] =
      std::isnan(r.linear) ? py::object(py::none()) : py::object(py::float_(r.linear * 3.6));
  d["settings"] = settings;
  return d;
}

py::dict modes(const engine::Scenario& sc, double v_min_kmh, double v_max_kmh, double v_step_kmh, int count) {
  // The command line's range (railsim modes), naming the arguments.
  const int n = engine::check_speed_range(v_min_kmh, v_max_kmh, v_step_kmh, {"v_min_kmh", "v_max_kmh", "v_step_kmh"});
  if (count < 1 || count > 50) throw InputError("count: expected a whole number in [1, 50] (got " + std::to_string(count) + ")");
  std::vector<double> speeds;
  for (int i = 0; i < n; ++i) speeds.push_back((v_min_kmh + i * v_step_kmh) / 3.6);
  std::vector<std::vector<engine::Mode>> all;
  double v_lin = NAN;
  bool below = false;  // unstable already at v_min_kmh: the critical speed is at or below it
  {
    py::gil_scoped_release release;
    all = engine::modes_versus_speed(sc, speeds, count);
    below = engine::linearly_unstable(sc, v_min_kmh / 3.6);
    if (!below) v_lin = engine::linear_critical_speed(sc, v_min_kmh / 3.6, v_max_kmh / 3.6);
  }
  std::vector<double> v, f, z, re, im;
  std::vector<int> rank;
  for (int i = 0; i < n; ++i)
    for (std::size_t k = 0; k < all[static_cast<std::size_t>(i)].size(); ++k) {
      const auto& md = all[static_cast<std::size_t>(i)][k];
      v.push_back(v_min_kmh + i * v_step_kmh), rank.push_back(static_cast<int>(k) + 1);
      f.push_back(md.frequency), z.push_back(md.damping_ratio);
      re.push_back(md.eigenvalue.real()), im.push_back(md.eigenvalue.imag());
    }
  py::dict d;
  d["speed_kmh"] = to_array(v), d["rank"] = rank, d["frequency_hz"] = to_array(f), d["damping_ratio"] = to_array(z);
  d["real_1_s"] = to_array(re), d["imag_rad_s"] = to_array(im);
  d["linear_critical_speed_kmh"] = std::isnan(v_lin) ? py::object(py::none()) : py::object(py::float_(v_lin * 3.6));
  d["unstable_at_v_min"] = below;
  return d;
}

}  // namespace

void bind_scenario(py::module_& m) {
  py::class_<engine::Scenario>(m, "Scenario", "A scenario: vehicle, track, speed, contact, integrator, duration")
      .def_readonly("name", &engine::Scenario::name)
      .def_readonly("file", &engine::Scenario::file)
      .def_readonly("duration", &engine::Scenario::duration)
      .def_readonly("output_interval", &engine::Scenario::output_interval)
      .def_property_readonly("vehicle", [](const engine::Scenario& s) { return s.model.vehicle_name; })
      .def_property_readonly("states", [](const engine::Scenario& s) { return s.model.n_states; })
      .def_property_readonly("contact", [](const engine::Scenario& s) { return s.model.coupling.describe(); })
      .def("__repr__", [](const engine::Scenario& s) {
        return "<railsim.Scenario " + s.name + ": " + s.model.vehicle_name + ", " + s.model.coupling.describe() + ">";
      });
  m.def("_load_scenario", [](const std::string& path) { return engine::load_scenario(path); }, py::arg("path"));
  m.def("_scenario_from_text", &from_text, py::arg("text"), py::arg("name"), py::arg("base_dir"));
  m.def("_run", &run, py::arg("scenario"), py::arg("out_dir") = "");
  m.def("_critical_speed", &critical_speed, py::arg("scenario"), py::arg("method"), py::arg("model"),
        py::arg("reduction"), py::arg("v_min_kmh"), py::arg("v_max_kmh"), py::arg("v_step_kmh"), py::arg("duration"),
        py::arg("disturbance_mm"), py::arg("small_disturbance_mm"), py::arg("threshold_mm"), py::arg("deceleration"),
        py::arg("up_branch"), py::arg("continuation"), py::arg("threads"), py::arg("dir"));
  m.def("_modes", &modes, py::arg("scenario"), py::arg("v_min_kmh"), py::arg("v_max_kmh"), py::arg("v_step_kmh"),
        py::arg("count"));
}

}  // namespace railsim::python
