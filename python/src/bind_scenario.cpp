// Python bindings of scenarios and the analyses over them: a scenario loaded
// from a YAML file or from text (the Python wrapper turns a dict into JSON,
// which is YAML), run (engine/analysis/scenario_run.hpp: channels and the
// summary document of `railsim run`), the critical speed (the library calls of
// `railsim critical-speed`: engine::bifurcation_sweep or engine::ramping, and
// engine::linear_critical_speed over max(1, V_min / 4) .. 1.5 V_max), and the
// modes versus speed (engine/analysis/mode_sweep.hpp, as `railsim modes`).
// Speeds in km/h and shifts in mm where the command line has them; the
// returned arrays say their unit in their name. The GIL is released while the
// engine runs.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "config/yaml_input.hpp"
#include "contact/reduction.hpp"
#include "core/errors.hpp"
#include "engine/analysis/critical_speed.hpp"
#include "engine/analysis/mode_sweep.hpp"
#include "engine/analysis/scenario_run.hpp"
#include "engine/io/scenario.hpp"
#include "python/src/bindings.hpp"

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

double or_default(double v, double fallback) { return std::isnan(v) ? fallback : v; }

py::dict critical_speed(const engine::Scenario& base, const std::string& method, const std::string& model,
                        const std::string& reduction, double v_min_kmh, double v_max_kmh, double v_step_kmh,
                        double duration, double disturbance_mm, double small_disturbance_mm, double threshold_mm,
                        double deceleration, bool up_branch, int continuation, int threads, const std::string& dir) {
  if (method != "bifurcation" && method != "ramping")
    throw InputError("method: expected 'bifurcation' or 'ramping' (got '" + method + "')");
  contact::ReductionFactors k;
  const contact::ReductionFactors* kp = nullptr;
  if (!reduction.empty()) {
    k = contact::parse_reduction(reduction, "reduction");
    kp = &k;
  }
  const engine::Scenario sc = engine::with_contact(base, model, kp);
  const engine::CriticalSpeedSettings& s = sc.critical_speed;
  const bool range_given = !std::isnan(v_max_kmh), disturbance_given = !std::isnan(disturbance_mm);
  v_min_kmh = or_default(v_min_kmh, s.v_min * 3.6);
  v_max_kmh = or_default(v_max_kmh, s.v_max * 3.6);
  v_step_kmh = or_default(v_step_kmh, s.v_step * 3.6);
  duration = or_default(duration, s.duration);
  disturbance_mm = or_default(disturbance_mm, s.disturbance * 1e3);
  small_disturbance_mm = or_default(small_disturbance_mm, s.small_disturbance * 1e3);
  threshold_mm = or_default(threshold_mm, s.threshold * 1e3);
  deceleration = or_default(deceleration, s.deceleration);
  const bool cont = continuation < 0 ? s.continuation : continuation == 1;
  if (!(v_min_kmh >= 0 && v_max_kmh > v_min_kmh && v_step_kmh > 0))
    throw InputError("speed range: need 0 <= v_min_kmh < v_max_kmh and v_step_kmh > 0");
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw InputError(dir + ": cannot create the output folder (" + ec.message() + ")");

  py::dict d;
  d["scenario"] = sc.name;
  d["method"] = method;
  d["contact_model"] = sc.model.coupling.options().tangential;
  d["contact_description"] = sc.model.coupling.describe();
  d["reduction"] = contact::describe_reduction(sc.model.coupling.options().reduction);
  py::dict settings;
  settings["v_min_kmh"] = v_min_kmh, settings["v_max_kmh"] = v_max_kmh, settings["threshold_mm"] = threshold_mm;
  const double v_lo = v_min_kmh / 3.6, v_hi = v_max_kmh / 3.6;
  double critical = NAN, linear = NAN;
  if (method == "bifurcation") {
    engine::BifurcationOptions o;
    o.v_min = v_lo;
    o.v_max = v_hi;
    o.v_step = v_step_kmh / 3.6;
    o.duration = duration;
    o.large_disturbance = disturbance_mm * 1e-3;
    o.small_disturbance = small_disturbance_mm * 1e-3;
    o.threshold = threshold_mm * 1e-3;
    o.up_branch = up_branch;
    o.continuation = cont;
    o.threads = threads;
    engine::BifurcationResult r;
    {
      py::gil_scoped_release release;
      linear = engine::linear_critical_speed(sc, std::max(1.0, 0.25 * v_lo), 1.5 * v_hi);
      r = engine::bifurcation_sweep(sc, o, dir + "/bifurcation.csv");
    }
    critical = r.nonlinear_critical_speed;
    std::vector<double> v, amp, freq, growth;
    std::vector<std::string> branch;
    std::vector<bool> failed, continued;
    for (const auto& p : r.points) {
      v.push_back(p.speed * 3.6), amp.push_back(p.amplitude * 1e3), freq.push_back(p.frequency);
      growth.push_back(p.growth), branch.push_back(engine::branch_name(p.branch)), failed.push_back(p.failed);
      continued.push_back(p.continued);
    }
    py::dict pts;
    pts["speed_kmh"] = to_array(v), pts["branch"] = branch, pts["amplitude_mm"] = to_array(amp);
    pts["frequency_hz"] = to_array(freq), pts["growth"] = to_array(growth), pts["failed"] = failed;
    pts["continued"] = continued;
    d["points"] = pts;
    settings["v_step_kmh"] = v_step_kmh, settings["duration_s"] = duration;
    settings["large_disturbance_mm"] = disturbance_mm, settings["small_disturbance_mm"] = small_disturbance_mm;
    settings["up_branch"] = up_branch, settings["continuation"] = cont;
  } else {
    engine::RampingOptions o;
    const double start = range_given || s.ramp_start <= 0 ? v_max_kmh : s.ramp_start * 3.6;
    const double dist = disturbance_given || s.ramp_disturbance <= 0 ? disturbance_mm : s.ramp_disturbance * 1e3;
    o.v_start = start / 3.6;
    o.v_end = v_lo;
    o.deceleration = deceleration;
    o.disturbance = dist * 1e-3;
    o.threshold = threshold_mm * 1e-3;
    engine::RampingResult r;
    {
      py::gil_scoped_release release;
      linear = engine::linear_critical_speed(sc, std::max(1.0, 0.25 * v_lo), 1.5 * v_hi);
      r = engine::ramping(sc, o);
    }
    critical = r.critical_speed;
    std::vector<double> v(r.speed.size()), y(r.max_lateral.size());
    for (std::size_t i = 0; i < v.size(); ++i) v[i] = r.speed[i] * 3.6;
    for (std::size_t i = 0; i < y.size(); ++i) y[i] = r.max_lateral[i] * 1e3;
    py::dict rec;
    rec["time_s"] = to_array(r.time), rec["speed_kmh"] = to_array(v), rec["max_lateral_mm"] = to_array(y);
    d["ramping"] = rec;
    d["hunting_at_start"] = r.hunting_at_start;
    d["hunting_at_end"] = r.hunting_at_end;
    settings["start_speed_kmh"] = start, settings["disturbance_mm"] = dist, settings["deceleration_m_s2"] = deceleration;
  }
  d["critical_speed_kmh"] = std::isnan(critical) ? py::object(py::none()) : py::object(py::float_(critical * 3.6));
  d["linear_critical_speed_kmh"] = std::isnan(linear) ? py::object(py::none()) : py::object(py::float_(linear * 3.6));
  d["settings"] = settings;
  return d;
}

py::dict modes(const engine::Scenario& sc, double v_min_kmh, double v_max_kmh, double v_step_kmh, int count) {
  if (!(v_min_kmh > 0 && v_max_kmh >= v_min_kmh && v_step_kmh > 0))
    throw InputError("speed range: need 0 < v_min_kmh <= v_max_kmh and v_step_kmh > 0");
  const int n = static_cast<int>(std::floor((v_max_kmh - v_min_kmh) / v_step_kmh + 1e-9)) + 1;
  std::vector<double> speeds;
  for (int i = 0; i < n; ++i) speeds.push_back((v_min_kmh + i * v_step_kmh) / 3.6);
  std::vector<std::vector<engine::Mode>> all;
  double v_lin = NAN;
  {
    py::gil_scoped_release release;
    all = engine::modes_versus_speed(sc, speeds, count);
    v_lin = engine::linear_critical_speed(sc, v_min_kmh / 3.6, v_max_kmh / 3.6);
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
