// Scenario YAML reader; see scenario.hpp.
#include "engine/scenario.hpp"

#include <spdlog/spdlog.h>

#include <cctype>
#include <cmath>
#include <filesystem>
#include <limits>
#include <tuple>

#include "contact/geometry/profile.hpp"
#include "contact/geometry/conicity.hpp"
#include "contact/geometry/wheel_rail_geometry.hpp"
#include "contact/hertz.hpp"
#include "contact/reduction.hpp"
#include "core/errors.hpp"
#include "engine/conical_geometry.hpp"
#include "engine/equilibrium.hpp"
#include "engine/geometry_table.hpp"
#include "engine/profile_geometry.hpp"
#include "engine/strip_patches.hpp"
#include "engine/system.hpp"
#include "engine/track_input.hpp"
#include "engine/vehicle_file.hpp"
#include "tracks/track_file.hpp"

namespace railsim::engine {
namespace {

using config::InputNode;
namespace fs = std::filesystem;

// The allowed magnitude of an `initial:` deviation of state `idx`, its unit
// and why: wheelset shifts within the contact geometry's lateral range, other
// shifts within suspension travel (0.1 m), angles 0.1 rad (5.7 deg), rates
// 5 m/s and 10 rad/s; other states only finite.
struct InitialRange {
  double limit = std::numeric_limits<double>::infinity();
  std::string unit, why;
};
InitialRange initial_range(const Model& m, int idx) {
  for (const auto& b : m.bodies)
    for (int k = 0; k < kNumDof; ++k) {
      if (b.q_index[k] == idx) {
        const auto& geometry = b.wheelset >= 0 ? m.wheelsets[static_cast<std::size_t>(b.wheelset)].geometry : nullptr;
        if (k == kLat && geometry) {
          const double r = geometry->max_shift();
          if (std::isfinite(r) && r > 0) return {r, "m", "the contact geometry's lateral range"};
          return {0.05, "m", "a wheelset shift"};
        }
        if (k == kLat || k == kVert) return {0.1, "m", "suspension travel"};
        return {0.1, "rad", "5.7 deg"};
      }
      if (b.v_index[k] == idx) return k == kLat || k == kVert ? InitialRange{5.0, "m/s", "a disturbance velocity"}
                                                               : InitialRange{10.0, "rad/s", "a disturbance rate"};
    }
  return {};
}

std::string resolve(const std::string& base, const std::string& p) {
  if (p.empty() || fs::path(p).is_absolute()) return p;
  return (fs::path(base) / p).lexically_normal().string();
}

// The file named by a scalar node, resolved against the scenario's folder; a
// missing file is an InputError naming the scenario file, line and key.
std::string existing_file(const InputNode& n, const std::string& base) {
  const std::string path = resolve(base, n.as_string());
  std::error_code ec;
  if (!fs::is_regular_file(path, ec))
    n.fail("file '" + n.as_string() + "' not found" +
           (path != n.as_string() ? " (looked for " + path + ", relative to the scenario's folder)" : std::string()));
  return path;
}

std::shared_ptr<const ContactGeometry> load_geometry(const InputNode& g, const std::string& base,
                                                     const contact::Material& material,
                                                     std::vector<std::string>& warnings) {
  const std::string type = g.string("type");
  if (type == "conical") {
    g.allow_only({"type", "r0", "conicity", "l0", "contact_angle", "flange_clearance", "flange_stiffness",
                  "max_shift", "curvatures"});
    ConicalParams p;
    p.r0 = g.in_range("r0", 0.1, 1.5);
    p.conicity = g.in_range("conicity", 0.0, 1.0);
    p.l0 = g.in_range("l0", 0.3, 1.5);
    p.contact_angle = g.has("contact_angle") ? g.in_range("contact_angle", -1.5, 1.5) : 0.0;
    p.flange_clearance = g.number_or("flange_clearance", 0.0);
    p.flange_stiffness = g.number_or("flange_stiffness", 0.0);
    if (p.flange_clearance < 0) g.at("flange_clearance").fail("expected a non-negative number");
    if (p.flange_stiffness < 0) g.at("flange_stiffness").fail("expected a non-negative number");
    p.max_shift = g.has("max_shift") ? g.in_range("max_shift", 0.0, 0.2, true) : 0.05;
    if (auto cv = g.find("curvatures")) {
      cv->allow_only({"A", "B"});
      p.A = cv->positive("A");
      p.B = cv->positive("B");
    }
    return std::make_shared<ConicalGeometry>(p);
  }
  if (type == "table") {
    g.allow_only({"type", "file", "node_step", "smoothing"});
    GeometryTableOptions o;
    if (g.has("node_step")) o.node_step = g.in_range("node_step", 1e-6, 2e-3);
    if (g.has("smoothing")) o.smoothing = g.in_range("smoothing", 0.0, 2e-3);
    auto table = std::make_shared<GeometryTable>(existing_file(g.at("file"), base), o);
    spdlog::info("contact geometry: {}; largest deviation of the fit from the rows: {}", table->describe(),
                 table->deviation_report());
    return table;
  }
  if (type == "profiles") {
    g.allow_only({"type", "wheel", "rail", "inclination", "gauge", "gauge_depth", "flange_back", "back_face", "r0",
                  "max_shift", "step", "max_yaw", "yaw_step", "strip", "cache_dir"});
    ProfileGeometryParams p;
    auto profile = [&](const char* key, const std::string& fallback) {
      if (!g.has(key)) return fallback;
      const std::string v = g.string(key);
      // A file relative to the scenario, or a shipped profile name.
      const std::string path = resolve(base, v);
      if (fs::exists(path)) return path;
      std::string lower = v;
      for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      if (lower != "s1002" && lower != "uic60" && lower != "uic60_mbench" && lower != "uic60_true")
        g.at(key).fail("file '" + v + "' not found (looked for " + path +
                       ") and not a shipped profile name (" + contact::shipped_profile_names() + ")");
      return v;
    };
    p.wheel = profile("wheel", p.wheel);
    p.rail = profile("rail", p.rail);
    // Physics sanity: profile widths outside the usual range (a warning in the run's summary).
    for (const auto& [key, path, kind] : {std::tuple{"wheel", p.wheel, contact::ProfileKind::wheel},
                                          std::tuple{"rail", p.rail, contact::ProfileKind::rail}}) {
      const std::string w = contact::profile_width_warning(contact::read_profile(path, kind));
      if (w.empty()) continue;
      warnings.push_back((g.has(key) ? g.at(key).where() : g.where()) + ": key 'contact.geometry." + key + "': " + w);
      spdlog::warn("{}", warnings.back());
    }
    p.setup = read_track_setup(g, "r0");
    const double s_max = g.has("max_shift") ? g.in_range("max_shift", 0.002, 0.02) : 0.015;
    p.grid.y_min = -s_max;
    p.grid.y_max = s_max;
    if (g.has("step")) p.grid.y_step = g.in_range("step", 1e-5, 1e-3);
    if (g.has("max_yaw")) p.grid.yaw_max = g.in_range("max_yaw", 0.0, 0.1);
    if (g.has("yaw_step")) p.grid.yaw_step = g.in_range("yaw_step", 1e-4, 0.05);
    if (g.has("strip")) p.grid.strip = g.in_range("strip", 1e-4, 5e-3);
    if (g.has("cache_dir")) p.cache_dir = resolve(base, g.string("cache_dir"));
    return std::make_shared<ProfileGeometry>(p, material);
  }
  g.at("type").fail("expected 'conical', 'table' or 'profiles' (got '" + type + "')");
}

CriticalSpeedSettings load_critical_speed_settings(const InputNode& n) {
  n.allow_only({"v_min_kmh", "v_max_kmh", "v_step_kmh", "duration", "disturbance_mm", "small_disturbance_mm",
                "threshold_mm", "continuation", "ramping"});
  CriticalSpeedSettings c;
  c.v_min_kmh = n.has("v_min_kmh") ? n.in_range("v_min_kmh", 0.0, 720.0, true) : c.v_min_kmh;
  c.v_max_kmh = n.has("v_max_kmh") ? n.in_range("v_max_kmh", 0.0, 720.0, true) : c.v_max_kmh;
  if (c.v_max_kmh <= c.v_min_kmh) n.fail("need v_min_kmh < v_max_kmh");
  c.v_step_kmh = n.has("v_step_kmh") ? n.in_range("v_step_kmh", 0.0, 720.0, true) : c.v_step_kmh;
  c.duration = n.has("duration") ? n.in_range("duration", 0.5, 600.0) : c.duration;
  c.disturbance_mm = n.has("disturbance_mm") ? n.in_range("disturbance_mm", 0.01, 20.0) : c.disturbance_mm;
  c.small_disturbance_mm =
      n.has("small_disturbance_mm") ? n.in_range("small_disturbance_mm", 0.001, 20.0) : c.small_disturbance_mm;
  c.threshold_mm = n.has("threshold_mm") ? n.in_range("threshold_mm", 0.001, 20.0) : c.threshold_mm;
  if (auto cn = n.find("continuation")) c.continuation = cn->as_bool();
  if (auto r = n.find("ramping")) {
    r->allow_only({"v_start_kmh", "disturbance_mm", "deceleration"});
    if (r->has("v_start_kmh")) c.ramp_start_kmh = r->in_range("v_start_kmh", 0.0, 720.0, true);
    if (r->has("disturbance_mm")) c.ramp_disturbance_mm = r->in_range("disturbance_mm", 0.01, 20.0);
    if (r->has("deceleration")) c.deceleration = r->in_range("deceleration", 0.001, 10.0);
  }
  return c;
}

}  // namespace

contact::TrackSetup read_track_setup(const InputNode& g, const std::string& radius_key) {
  contact::TrackSetup t;
  if (g.has("inclination")) {
    const InputNode n = g.at("inclination");
    t.inclination = contact::parse_inclination(n.as_string(), n.where() + ": key 'inclination'");
  } else {
    t.inclination = std::atan(1.0 / 40.0);
  }
  if (g.has("gauge")) t.gauge = g.in_range("gauge", 0.9, 1.8);
  if (g.has("gauge_depth")) t.gauge_depth = g.in_range("gauge_depth", 0.0, 0.03);
  if (g.has("flange_back")) t.flange_back = g.in_range("flange_back", 0.8, 1.8);
  if (g.has("back_face")) t.back_face = g.in_range("back_face", -0.2, 0.0);
  if (g.has(radius_key)) t.r0 = g.in_range(radius_key, 0.1, 1.5);
  return t;
}

Scenario load_scenario(const std::string& path) {
  const auto root = InputNode::load_file(path);
  Scenario s = load_scenario(root, fs::path(path).parent_path().string());
  s.file = path;
  if (s.name.empty()) s.name = fs::path(path).stem().string();
  return s;
}

Scenario load_scenario(const InputNode& root, const std::string& base) {
  root.allow_only({"name", "description", "vehicle", "track", "speed", "speed_kmh", "acceleration", "start",
                   "start_distance", "duration", "output_interval", "wheelset_model", "max_lateral_shift",
                   "wheelset_roll", "axle_rotation",
                   "contact", "integrator", "initial", "critical_speed", "running_safety"});
  Scenario sc;
  sc.name = root.string_or("name", "");
  Model& m = sc.model;
  load_vehicle(existing_file(root.at("vehicle"), base), m);

  // Track.
  const InputNode tn = root.at("track");
  std::shared_ptr<const tracks::Track> track;
  if (tn.is_scalar()) {
    track = std::make_shared<const tracks::Track>(tracks::load_track(existing_file(tn, base)));
  } else {
    track = std::make_shared<const tracks::Track>(tracks::load_track(tn, base, "track"));
  }
  m.track = std::make_shared<TrackInput>(track);

  // Speed.
  if (root.has("speed") == root.has("speed_kmh")) root.fail("give exactly one of 'speed' [m/s] or 'speed_kmh'");
  m.speed.v0 = root.has("speed") ? root.in_range("speed", 0.0, 200.0, true) : root.in_range("speed_kmh", 0.0, 720.0, true) / 3.6;
  m.speed.accel = root.has("acceleration") ? root.in_range("acceleration", -kMaxAcceleration, kMaxAcceleration) : 0.0;
  if (root.has("start_distance")) {
    // Outside [0, length] the track is an extrapolation of its end (no
    // irregularities): a run there would not be a run on the track given.
    const double len = track->length();
    const InputNode sd = root.at("start_distance");
    const double s0 = sd.as_number();
    if (!(s0 >= 0.0 && s0 <= len))
      sd.fail("expected a number in [0, " + config::format_number(len) + "] (the track's defined length [m]; got " +
              config::format_number(s0) + ")");
    m.speed.s0 = s0;
  }
  sc.duration = root.positive("duration");
  if (m.speed.accel < 0 && m.speed.speed(sc.duration) <= 0)
    root.at("acceleration").fail("the speed would reach zero before the end of the run");
  sc.output_interval = root.has("output_interval") ? root.in_range("output_interval", 0.0, sc.duration, true) : 0.01;
  {
    // Bounded output: the run keeps every sample in memory (RunHistory) and writes it (channels.csv).
    const double samples = std::floor(sc.duration / sc.output_interval) + 1.0;
    if (samples > kMaxOutputSamples) {
      const InputNode where = root.has("output_interval") ? root.at("output_interval") : root.at("duration");
      where.fail("duration " + config::format_number(sc.duration) + " s / output_interval " +
                 config::format_number(sc.output_interval) + " s gives " + config::format_number(samples) +
                 " output samples, more than the limit of " + config::format_number(kMaxOutputSamples) +
                 "; use a larger output_interval or a shorter duration");
    }
  }
  const std::string wm = root.string_or("wheelset_model", "lateral");
  if (wm == "lateral") m.wheelset_model = WheelsetModel::lateral;
  else if (wm == "full") m.wheelset_model = WheelsetModel::full;
  else root.at("wheelset_model").fail("expected 'lateral' or 'full' (got '" + wm + "')");
  if (auto wr = root.find("wheelset_roll")) {
    const std::string v = wr->as_string();
    if (v != "kinematic" && v != "none") wr->fail("expected 'kinematic' or 'none' (got '" + v + "')");
    m.kinematic_roll = v == "kinematic";
  }
  // Axle rotation (lateral model; model.hpp): free unless the scenario imposes V / r0.
  m.free_axle_rotation = true;
  if (auto ar = root.find("axle_rotation")) {
    const std::string v = ar->as_string();
    if (v != "free" && v != "imposed") ar->fail("expected 'free' or 'imposed' (got '" + v + "')");
    m.free_axle_rotation = v == "free";
  }
  if (root.has("max_lateral_shift")) m.max_lateral_shift = root.in_range("max_lateral_shift", 0.0, 0.2, true);

  // Contact.
  const InputNode c = root.at("contact");
  c.allow_only({"geometry", "tangential", "saturation", "material", "reduction", "creep_coefficients", "patch",
                "spin", "static_approach", "normal_damping"});
  CouplingOptions co;
  if (auto mat = c.find("material")) {
    mat->allow_only({"E", "nu", "mu", "shear_modulus"});
    co.material.E = mat->has("E") ? mat->positive("E") : co.material.E;
    co.material.nu = mat->has("nu") ? mat->in_range("nu", 0.0, 0.5, true, false) : co.material.nu;
    co.material.mu = mat->has("mu") ? mat->in_range("mu", 0.0, 2.0, true) : co.material.mu;
    if (co.material.mu > 1.0) {
      sc.warnings.push_back(mat->at("mu").where() + ": key 'contact.material.mu': " +
                            config::format_number(co.material.mu) +
                            " is legal but implausible for wheel on rail (usual range 0.05-0.6; above 1 is beyond "
                            "measured wheel-rail friction)");
      spdlog::warn("{}", sc.warnings.back());
    }
    co.shear_modulus = mat->has("shear_modulus") ? mat->positive("shear_modulus") : 0.0;
  }
  auto geo = load_geometry(c.at("geometry"), base, co.material, sc.warnings);
  sc.geometry_description = geo->describe();
  if (geo->max_shift() >= 3e-3)
    sc.equivalent_conicity_3mm = contact::equivalent_conicity(
        [&](double y) { return geo->main_point(y).rolling_radius - geo->main_point(-y).rolling_radius; }, 3e-3, 400);
  for (auto& w : m.wheelsets) w.geometry = geo;
  co.tangential = c.string_or("tangential", "coefficients");
  co.saturation = c.string_or("saturation", "none");
  if (co.saturation != "none" && co.saturation != "she")
    c.at("saturation").fail("expected 'none' or 'she' (got '" + co.saturation + "')");
  contact::ReductionSpec reduction;
  std::string reduction_where;
  if (auto r = c.find("reduction")) {
    reduction_where = r->where() + ": key 'reduction'";
    reduction = contact::parse_reduction_spec(r->as_string(), reduction_where);
    if (reduction.resolved) co.reduction = reduction.k;
  }
  if (auto f = c.find("creep_coefficients")) {
    f->allow_only({"f11", "f22", "f23", "f33", "N_ref"});
    co.f11 = f->positive("f11");
    co.f22 = f->positive("f22");
    co.f23 = f->number_or("f23", 0.0);
    co.f33 = f->number_or("f33", 0.0);
    co.N_ref = f->number_or("N_ref", 0.0);
    if (co.f23 < 0 || co.f33 < 0 || co.N_ref < 0) f->fail("f23, f33 and N_ref must be non-negative");
  }
  if (auto p = c.find("patch")) {
    p->allow_only({"a", "b", "N_ref"});
    co.patch_a = p->positive("a");
    co.patch_b = p->positive("b");
    co.N_ref = p->positive("N_ref");
  }
  if (auto sp = c.find("spin")) co.spin = sp->as_bool();
  if (c.has("normal_damping")) co.normal_damping = c.in_range("normal_damping", 0.0, 1e8);
  // Tabulated geometries (table file, profiles) carry their own patch at N0.
  const bool table = c.at("geometry").string("type") != "conical";
  const ContactPointGeometry c0 = geo->main_point(0.0);
  const bool hertz = !table && c0.A > 0 && c0.B > 0;
  if (!table && co.patch_a <= 0 && !hertz && !(co.tangential == "coefficients" && co.f11 > 0))
    c.fail("conical wheels need 'creep_coefficients' (f11, f22, ...; tangential 'coefficients' only), 'patch' "
           "(a, b, N_ref) or geometry 'curvatures' (A, B) for Hertz");
  if (hertz && (co.patch_a > 0 || c.has("static_approach")))
    c.fail("give either geometry 'curvatures' (Hertz) or 'patch' / 'static_approach', not both");
  double q0 = c.has("static_approach") ? c.in_range("static_approach", 0.0, 1e-2, true) : 7e-5;

  // Integrator.
  if (auto in = root.find("integrator")) {
    in->allow_only({"method", "rtol", "atol", "max_step", "initial_step", "min_step", "max_steps", "jacobian",
                    "linear_solver", "max_order", "stability_limit_detection", "atol_contact_modes"});
    auto& o = sc.integrator;
    o.method = in->string_or("method", o.method);
    // Below 1e-12 (about 5000 machine epsilons) the integrators cannot meet rtol
    // in double precision and end in CV_TOO_MUCH_WORK after minutes.
    if (in->has("rtol")) o.rtol = in->in_range("rtol", 1e-12, 0.1);
    if (in->has("atol")) o.atol = in->in_range("atol", 0.0, 0.1, true);
    if (auto ms = in->find("max_step")) {
      // 0 would be read by the integrators as "no limit": refused, the key is omitted for that.
      const double v = ms->as_number();
      if (!(v > 0.0 && v <= sc.duration))
        ms->fail("expected a step in (0, " + config::format_number(sc.duration) + "] s (the duration; got " +
                 config::format_number(v) + "); omit max_step to leave the step unlimited");
      o.max_step = v;
    }
    if (auto is = in->find("initial_step")) {
      const double v = is->as_number();
      if (!(v >= 0.0 && v <= sc.duration))
        is->fail("expected a step in [0, " + config::format_number(sc.duration) +
                 "] s (0: the integrator's choice; at most the duration; got " + config::format_number(v) + ")");
      o.initial_step = v;
    }
    if (auto ms = in->find("min_step")) {
      const double v = ms->as_number();
      const double hi = o.max_step > 0.0 ? std::min(o.max_step, sc.output_interval) : sc.output_interval;
      if (!(v >= 0.0 && v < hi))
        ms->fail("expected a step in [0, " + config::format_number(hi) + ") s (below the output interval" +
                 std::string(o.max_step > 0.0 ? " and max_step" : "") + "; got " + config::format_number(v) + ")");
      o.min_step = v;
    }
    if (in->has("max_steps")) o.max_steps = static_cast<long>(in->in_range("max_steps", 1, 1e9));
    if (in->has("max_order")) o.max_order = static_cast<int>(in->in_range("max_order", 1, 5));
    if (in->has("atol_contact_modes")) o.atol_contact_modes = in->in_range("atol_contact_modes", 0.0, 1.0);
    if (auto sl = in->find("stability_limit_detection")) o.stability_limit_detection = sl->as_bool();
    o.jacobian = in->string_or("jacobian", o.jacobian);
    o.linear_solver = in->string_or("linear_solver", o.linear_solver);
    bool known = false;
    for (const auto& e : integrators()) known |= o.method == e.name;
    if (!known) in->at("method").fail("unknown integrator '" + o.method + "' (known: " + integrator_names() + ")");
    if (o.jacobian != "fd" && o.jacobian != "assembled") in->at("jacobian").fail("expected 'fd' or 'assembled'");
    if (o.linear_solver != "auto" && o.linear_solver != "dense" && o.linear_solver != "band" && o.linear_solver != "klu")
      in->at("linear_solver").fail("expected 'auto', 'klu', 'dense' or 'band'");
    if (o.linear_solver == "klu" && o.jacobian == "fd")
      in->at("jacobian").fail("'fd' works with the dense and band solvers only; 'klu' needs 'assembled'");
  }

  finalize_model(m);
  if (hertz) {
    // Hertz patch and approach at the static load of the first wheel (a, b ~ N^{1/3} for fixed A, B).
    const double Ns = m.wheelsets.front().static_load[0];
    const contact::HertzPatch hp = contact::hertz_from_load(c0.A, c0.B, Ns, co.material);
    co.patch_a = hp.a;
    co.patch_b = hp.b;
    co.N_ref = Ns;
    q0 = hp.approach;
  }
  m.coupling = WheelRailCoupling(co);
  for (auto& w : m.wheelsets) w.hertz_q0[0] = w.hertz_q0[1] = q0;
  // Nominal patch (centred wheelset, static load of the first wheel) for layer factors and reports.
  sc.creep_material = co.shear_modulus > 0 ? contact::Material::from_shear_modulus(co.shear_modulus, co.material.nu,
                                                                                   co.material.mu)
                                           : co.material;
  {
    const double Ns = m.wheelsets.empty() ? 0.0 : m.wheelsets.front().static_load[0];
    double a = 0.0, b = 0.0;
    if (c0.semi_a > 0 && c0.N0 > 0) {
      a = c0.semi_a * std::cbrt(Ns / c0.N0);
      b = c0.semi_b * std::cbrt(Ns / c0.N0);
    } else if (co.patch_a > 0 && co.N_ref > 0) {
      a = co.patch_a * std::cbrt(Ns / co.N_ref);
      b = co.patch_b * std::cbrt(Ns / co.N_ref);
    }
    double N = Ns;
    contact::StripSet set;
    if (!(a > 0 && b > 0) && Ns > 0 && geo->distributed() &&
        geo->strips(0.0, 0.0, ProfileGeometry::kGapCutoff, set)) {
      // Distributed contact (profiles): the most loaded patch of the centred
      // wheel under its static vertical load, as the wheelset models form it
      // (engine/strip_patches.hpp: equivalent ellipse, normal load N).
      StripLoads loads;
      strip_approach_for_load(set, Ns, 0.0, geo->contact_modulus(), loads);
      int best = -1;
      for (int k = 0; k < loads.n; ++k)
        if (best < 0 || loads.N[k] > loads.N[best]) best = k;
      if (best >= 0 && loads.N[best] > 0) {
        a = loads.patch[best].semi_a;
        b = loads.patch[best].semi_b;
        N = loads.N[best];
      }
    }
    if (a > 0 && b > 0 && N > 0) sc.nominal_patch = contact::hertz_from_semi_axes(a, b, N, sc.creep_material);
  }
  if (reduction.form != contact::ReductionForm::unset) apply_reduction(sc, reduction, reduction_where);
  if (auto cs = root.find("critical_speed")) sc.critical_speed = load_critical_speed_settings(*cs);
  sc.running_safety = root.find("running_safety");
  sc.x0 = Eigen::VectorXd::Zero(m.n_states);
  // Start from the (quasi-)static state (equilibrium.hpp), the user's
  // deviations on top; `start: nominal` keeps x = 0.
  const std::string start = root.string_or("start", "equilibrium");
  if (start != "equilibrium" && start != "nominal")
    root.at("start").fail("expected 'equilibrium' or 'nominal' (got '" + start + "')");
  if (start == "equilibrium") {
    const EquilibriumResult eq = static_equilibrium(m, 0.0);
    if (eq.converged) {
      sc.x0 = eq.x;
    } else {
      spdlog::warn("scenario '{}': no static equilibrium at the start ({}); starting from the nominal state",
                   sc.name, eq.message);
    }
    sc.start_residual = eq.residual;
  }
  if (auto init = root.find("initial")) {
    for (const auto& key : init->keys()) {
      int idx = -1;
      for (int i = 0; i < m.n_states; ++i)
        if (m.state_names[i] == key) idx = i;
      if (idx < 0) {
        std::string known;
        for (const auto& n : m.state_names) known += (known.empty() ? "" : ", ") + n;
        init->at(key).fail("unknown state '" + key + "' (states: " + known + ")");
      }
      const double v = init->number(key);
      const InitialRange r = initial_range(m, idx);
      if (!(std::fabs(v) <= r.limit))
        init->at(key).fail("expected a deviation in [-" + config::format_number(r.limit) + ", " +
                           config::format_number(r.limit) + "] " + r.unit + " (" + r.why + ") (got " +
                           config::format_number(v) + ")");
      sc.x0[idx] += v;
    }
  }
  return sc;
}

void apply_reduction(Scenario& sc, contact::ReductionSpec spec, const std::string& where,
                     const std::string& cache_dir) {
  CouplingOptions o = sc.model.coupling.options();
  o.material.mu = sc.creep_material.mu;  // the scenario's friction; only a layer's tau_c lowers it
  sc.layer = {};
  if (spec.form == contact::ReductionForm::layer) {
    if (!(sc.nominal_patch.Fz > 0.0))
      throw InputError(where + ": a third-body layer needs the scenario's contact patch (a geometry table or "
                       "profiles with semi-axes, or 'patch' / 'curvatures' for conical wheels); this scenario "
                       "prescribes creep coefficients only");
    contact::Material m = sc.creep_material;
    m.mu = o.material.mu;
    sc.layer = contact::mim::third_body_reduction_cached(sc.nominal_patch, m, spec.layer, cache_dir);
    spec.k = sc.layer.k;
    spec.resolved = true;
    contact::check_reduction(spec.k, where + " (factors computed for the layer)");
    if (sc.layer.mu_limit > 0.0 && sc.layer.mu_limit < o.material.mu) o.material.mu = sc.layer.mu_limit;
  }
  o.reduction = spec.k;
  sc.reduction = spec;
  sc.model.coupling = WheelRailCoupling(o);
}

}  // namespace railsim::engine
