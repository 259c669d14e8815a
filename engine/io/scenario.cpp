// Scenario YAML reader; see scenario.hpp.
#include "engine/io/scenario.hpp"

#include <spdlog/spdlog.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>

#include "contact/geometry/conicity.hpp"
#include "contact/geometry/wheel_rail_geometry.hpp"
#include "contact/hertz.hpp"
#include "contact/reduction.hpp"
#include "contact/registry.hpp"
#include "core/errors.hpp"
#include "engine/equilibrium.hpp"
#include "engine/wheel_rail/geometry_registry.hpp"
#include "engine/wheel_rail/profile_geometry.hpp"
#include "engine/wheel_rail/strip_patches.hpp"
#include "engine/wheel_rail/track_flexibility.hpp"
#include "engine/system.hpp"
#include "engine/track_input.hpp"
#include "engine/io/vehicle_file.hpp"
#include "track/track_file.hpp"

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

CriticalSpeedSettings load_critical_speed_settings(const InputNode& n) {
  n.allow_only({"v_min_kmh", "v_max_kmh", "v_step_kmh", "duration", "disturbance_mm", "small_disturbance_mm",
                "threshold_mm", "continuation", "ramping"});
  CriticalSpeedSettings c;
  constexpr double mm = 1e-3;  // the file's lengths; speeds / 3.6 (the file's km/h)
  if (n.has("v_min_kmh")) c.v_min = n.in_range("v_min_kmh", 0.0, 720.0, true) / 3.6;
  if (n.has("v_max_kmh")) c.v_max = n.in_range("v_max_kmh", 0.0, 720.0, true) / 3.6;
  if (c.v_max <= c.v_min) n.fail("need v_min_kmh < v_max_kmh");
  if (n.has("v_step_kmh")) c.v_step = n.in_range("v_step_kmh", 0.0, 720.0, true) / 3.6;
  if (n.has("duration")) c.duration = n.in_range("duration", 0.5, 600.0);
  if (n.has("disturbance_mm")) c.disturbance = n.in_range("disturbance_mm", 0.01, 20.0) * mm;
  if (n.has("small_disturbance_mm")) c.small_disturbance = n.in_range("small_disturbance_mm", 0.001, 20.0) * mm;
  if (n.has("threshold_mm")) c.threshold = n.in_range("threshold_mm", 0.001, 20.0) * mm;
  if (auto cn = n.find("continuation")) c.continuation = cn->as_bool();
  if (auto r = n.find("ramping")) {
    r->allow_only({"v_start_kmh", "disturbance_mm", "deceleration"});
    if (r->has("v_start_kmh")) c.ramp_start = r->in_range("v_start_kmh", 0.0, 720.0, true) / 3.6;
    if (r->has("disturbance_mm")) c.ramp_disturbance = r->in_range("disturbance_mm", 0.01, 20.0) * mm;
    if (r->has("deceleration")) c.deceleration = r->in_range("deceleration", 0.001, 10.0);
  }
  return c;
}

}  // namespace

Scenario load_scenario(const std::string& path) {
  const auto root = InputNode::load_file(path);
  Scenario s = load_scenario(root, fs::path(path).parent_path().string());
  s.file = path;
  if (s.name.empty()) s.name = fs::path(path).stem().string();
  return s;
}

namespace {

// Step: the track (a file or an inline map).
std::shared_ptr<const track::Track> read_track(const InputNode& root, const std::string& base) {
  const InputNode tn = root.at("track");
  return std::make_shared<const track::Track>(tn.is_scalar() ? track::load_track(tn.as_existing_file(base))
                                                              : track::load_track(tn, base, "track"));
}

// Step: speed profile, start distance, duration and output sampling.
void read_motion(const InputNode& root, double track_length, Scenario& sc) {
  Model& m = sc.model;
  if (root.has("speed") == root.has("speed_kmh")) root.fail("give exactly one of 'speed' [m/s] or 'speed_kmh'");
  m.speed.v0 =
      root.has("speed") ? root.in_range("speed", 0.0, 200.0, true) : root.in_range("speed_kmh", 0.0, 720.0, true) / 3.6;
  m.speed.accel = root.has("acceleration") ? root.in_range("acceleration", -kMaxAcceleration, kMaxAcceleration) : 0.0;
  if (root.has("start_distance")) {
    // Outside [0, length] the track is an extrapolation of its end (no
    // irregularities): a run there would not be a run on the track given.
    const double len = track_length;
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
  // Past the track's defined length the track continues as the extension of
  // its end, without irregularities: legal (a long straight run), but not the
  // track given, so the run says so.
  // The foremost body (the leading wheelset) leaves first.
  double lead = 0.0;
  for (const auto& body : m.bodies) lead = std::max(lead, body.position.x());
  const double s_end = m.speed.distance(sc.duration) + lead;
  if (s_end > track_length * (1.0 + 1e-9)) {
    const double v_avg = (s_end - lead - m.speed.s0) / sc.duration;
    const double t_leave = v_avg > 0.0 ? std::max(0.0, track_length - lead - m.speed.s0) / v_avg : 0.0;
    sc.run_warnings.push_back(root.at("duration").where() + ": key 'duration': at " +
                          config::format_number(m.speed.v0 * 3.6) + " km/h for " + config::format_number(sc.duration) +
                          " s the leading wheelset ends at track distance " + config::format_number(s_end) +
                          " m, past the track's defined length " + config::format_number(track_length) +
                          " m (left at about t = " + config::format_number(t_leave) +
                          " s); beyond it the track is the extension of its end without irregularities: shorten "
                          "the duration or lengthen the track");
  }
  sc.output_interval = 0.01;
  if (root.has("output_interval")) {
    sc.output_interval = root.positive("output_interval");
    // Named with both keys (a --set duration that made the run shorter than the
    // interval was reported as a bad output_interval alone).
    if (sc.output_interval > sc.duration)
      root.at("output_interval")
          .fail(config::format_number(sc.output_interval) + " s is longer than the run (key 'duration': " +
                config::format_number(sc.duration) + " s); give an output_interval in (0, duration]");
  }
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

// Step: the wheelset model and its options (model.hpp).
void read_wheelset_model(const InputNode& root, Model& m) {
  m.wheelset_model = root.choice_or("wheelset_model", "lateral", {"lateral", "full"}) == "full" ? WheelsetModel::full
                                                                                                : WheelsetModel::lateral;
  if (root.has("wheelset_roll")) m.kinematic_roll = root.at("wheelset_roll").as_choice({"kinematic", "none"}) == "kinematic";
  // Axle rotation (lateral model): free unless the scenario imposes V / r0.
  m.free_axle_rotation = root.choice_or("axle_rotation", "free", {"free", "imposed"}) == "free";
  if (root.has("max_lateral_shift")) m.max_lateral_shift = root.in_range("max_lateral_shift", 0.0, 0.2, true);
}

// Step: the flexible track under the wheelsets (wheel_rail/track_flexibility.hpp),
// rigid rails when absent. Each direction {mass, stiffness, damping}.
// The vertical part may name the rail's bending stiffness EI (N m^2): the
// rails then follow the vertical geometry smoothed by their bending.
void read_track_flexibility(const InputNode& root, double track_length, Model& m) {
  const auto node = root.find("track_flexibility");
  if (!node) return;
  node->allow_only({"lateral", "vertical"});
  auto support = [](const InputNode& n, TrackSupport& out, bool vertical) {
    if (vertical) n.allow_only({"mass", "stiffness", "damping", "bending_stiffness"});
    else n.allow_only({"mass", "stiffness", "damping"});
    out.active = true;
    out.mass = n.in_range("mass", 1.0, 1e5);              // kg: a rail's metre to a track panel
    out.stiffness = n.in_range("stiffness", 1e5, 1e10);   // N/m
    out.damping = n.in_range("damping", 0.0, 1e8);        // N s/m
    if (vertical && n.has("bending_stiffness"))           // N m^2 (UIC60 vertical: 6.4e6)
      out.bending_stiffness = n.in_range("bending_stiffness", 1e4, 1e9);
  };
  TrackFlexibility& tf = m.track_flexibility;
  if (auto l = node->find("lateral")) support(*l, tf.lateral, false);
  if (auto v = node->find("vertical")) support(*v, tf.vertical, true);
  if (!tf.lateral.active && !tf.vertical.active)
    node->fail("expected 'lateral' and/or 'vertical', each {mass, stiffness, damping}");
  if (tf.vertical.bending_stiffness > 0.0 && m.wheelset_model == WheelsetModel::full) {  // (lateral model: no use)
    const double beta = rail_foundation_beta(tf.vertical.stiffness, tf.vertical.bending_stiffness);
    // The smoothed rails are tabulated over the whole track: every 5 cm (or
    // 0.1 / beta where that is finer: 60 rows per wavelength 2 pi / beta of
    // the influence line), coarser on a long track so that the table keeps at
    // most 1e6 rows (64 MB while it is built, about a second), as long as a
    // row every 0.1 / beta is kept.
    const double step = std::max(std::min(0.05, 0.1 / beta), track_length / 1e6);
    if (!(beta * step <= 0.1))
      node->at("vertical").at("bending_stiffness").fail(
          "on a track of " + config::format_number(track_length) + " m the rails' bending table would have a row "
          "every " + config::format_number(step) + " m, coarser than 0.1 / beta = " + config::format_number(0.1 / beta) +
          " m (beta = (stiffness / 8 EI)^(1/3) = " + config::format_number(beta) + " 1/m); use a track of at most " +
          config::format_number(1e6 * 0.1 / beta) + " m, or give no bending_stiffness");
    tf.vertical_geometry = std::make_shared<const SmoothedRailGeometry>(*m.track, track_length, beta, step);
  }
}

// The contact section as read, before the model is finalised (the Hertz
// patch needs the static wheel loads).
struct ContactSection {
  CouplingOptions options;
  std::shared_ptr<const ContactGeometry> geometry;
  bool hertz = false;           // conical wheels with curvatures: patch from Hertz at the static load
  double static_approach = 7e-5;
  PatchShape patch_shape = PatchShape::hertz;
  contact::ReductionSpec reduction;
  std::string reduction_where;
};

contact::Material read_material(const InputNode& mat, CouplingOptions& co, std::vector<std::string>& warnings) {
  mat.allow_only({"E", "nu", "mu", "shear_modulus"});
  contact::Material m = co.material;
  if (mat.has("E")) m.E = mat.in_range("E", 1e9, 1e13);  // [Pa], as contact case files (steel 2.1e11)
  if (mat.has("nu")) m.nu = mat.in_range("nu", 0.0, 0.5, true, false);
  if (mat.has("mu")) m.mu = mat.in_range("mu", 0.0, 2.0, true);
  if (m.mu > 1.0) {
    warnings.push_back(mat.at("mu").where() + ": key 'contact.material.mu': " + config::format_number(m.mu) +
                       " is legal but implausible for wheel on rail (usual range 0.05-0.6; above 1 is beyond "
                       "measured wheel-rail friction)");
    spdlog::warn("{}", warnings.back());
  }
  co.shear_modulus = mat.has("shear_modulus") ? mat.in_range("shear_modulus", 1e9, 1e13) : 0.0;  // [Pa]
  return m;
}

// Step: the contact section (geometry by registry, tangential model, material,
// reductions, creep coefficients or patch).
ContactSection read_contact(const InputNode& c, const std::string& base, const track::Track& track, Scenario& sc) {
  c.allow_only({"geometry", "normal", "tangential", "saturation", "material", "reduction", "creep_coefficients",
                "patch", "spin", "static_approach", "normal_damping"});
  ContactSection cs;
  CouplingOptions& co = cs.options;
  if (auto mat = c.find("material")) co.material = read_material(*mat, co, sc.warnings);
  const InputNode gn = c.at("geometry");
  const GeometryKind& kind = find_geometry_kind(gn);
  cs.geometry = kind.read(gn, GeometryReadContext{base, co.material, &sc.warnings,
                                                  track.gauge_given() ? track.gauge() : 0.0});
  // The patch shape of distributed contact (profiles; wheel_rail/strip_patches.hpp).
  if (c.choice_or("normal", "hertz", {"hertz", "semi_hertz"}) == "semi_hertz") {
    if (!cs.geometry->distributed())
      c.at("normal").fail("'semi_hertz' needs the profiles geometry (contact.geometry.type: profiles), whose strips "
                          "give the patch's shape; geometry '" + std::string(kind.name) + "' gives one Hertz ellipse "
                          "per contact point (use 'hertz' or omit the key)");
    cs.patch_shape = PatchShape::semi_hertz;
  }
  co.tangential = c.string_or("tangential", "coefficients");
  if (auto t = c.find("tangential")) {  // an unknown name, named where it was given
    try {
      contact::find_tangential_model(co.tangential);
    } catch (const InputError& e) {
      t->fail(e.what());
    }
  }
  co.saturation = c.choice_or("saturation", "none", {"none", "she"});
  if (auto r = c.find("reduction")) {
    cs.reduction_where = r->where() + ": key 'reduction'";
    cs.reduction = contact::parse_reduction_spec(r->as_string(), cs.reduction_where);
    if (cs.reduction.resolved) co.reduction = cs.reduction.k;
  }
  if (auto f = c.find("creep_coefficients")) {
    f->allow_only({"f11", "f22", "f23", "f33", "N_ref"});
    // Kalker's coefficients of a wheel-rail patch: f11, f22 of the order of
    // 1e6-1e8 N (G a b C11 at 50-200 kN), f23 1e3-1e5 N m, f33 up to about
    // 1e2 N m^2; the ranges leave two decades on either side. N_ref: the load
    // they belong to (0: constant coefficients).
    co.f11 = f->in_range("f11", 0.0, 1e10, true);
    co.f22 = f->in_range("f22", 0.0, 1e10, true);
    co.f23 = f->has("f23") ? f->in_range("f23", 0.0, 1e8) : 0.0;
    co.f33 = f->has("f33") ? f->in_range("f33", 0.0, 1e6) : 0.0;
    co.N_ref = f->has("N_ref") ? f->in_range("N_ref", 0.0, 1e7) : 0.0;
    if (co.N_ref > 0.0 && co.N_ref < 1.0)
      f->at("N_ref").fail("expected 0 (constant coefficients) or a wheel load in [1, 1e7] N (got " +
                          config::format_number(co.N_ref) + ")");
  }
  if (auto p = c.find("patch")) {
    p->allow_only({"a", "b", "N_ref"});
    co.patch_a = p->in_range("a", 1e-6, 1.0);  // [m], as contact case files
    co.patch_b = p->in_range("b", 1e-6, 1.0);
    co.N_ref = p->in_range("N_ref", 1.0, 1e7);  // [N]
  }
  if (auto sp = c.find("spin")) co.spin = sp->as_bool();
  if (c.has("normal_damping")) co.normal_damping = c.in_range("normal_damping", 0.0, 1e8);
  // Geometries that carry their own patch (table, profiles) need nothing more;
  // conical wheels need coefficients, a patch or Hertz curvatures.
  const ContactPointGeometry c0 = cs.geometry->main_point(0.0);
  cs.hertz = !kind.carries_patch && c0.A > 0 && c0.B > 0;
  if (!kind.carries_patch && co.patch_a <= 0 && !cs.hertz && !(co.f11 > 0 && contact::find_tangential_model(co.tangential).geometry_coefficients))
    c.fail("conical wheels need 'creep_coefficients' (f11, f22, ...; tangential 'coefficients' only), 'patch' "
           "(a, b, N_ref) or geometry 'curvatures' (A, B) for Hertz");
  if (cs.hertz && (co.patch_a > 0 || c.has("static_approach")))
    c.fail("give either geometry 'curvatures' (Hertz) or 'patch' / 'static_approach', not both");
  if (c.has("static_approach")) cs.static_approach = c.in_range("static_approach", 0.0, 1e-2, true);
  return cs;
}

// Step: integrator options (integrator.hpp), checked against the run's duration and output interval.
void read_integrator(const InputNode& in, Scenario& sc) {
  in.allow_only({"method", "rtol", "atol", "max_step", "initial_step", "min_step", "max_steps", "jacobian",
                 "linear_solver", "max_order", "stability_limit_detection", "atol_contact_modes",
                 "jacobian_max_age"});
  auto& o = sc.integrator;
  o.method = in.string_or("method", o.method);
  // Below 1e-12 (about 5000 machine epsilons) the integrators cannot meet rtol
  // in double precision and end in CV_TOO_MUCH_WORK after minutes.
  if (in.has("rtol")) o.rtol = in.in_range("rtol", 1e-12, 0.1);
  if (in.has("atol")) o.atol = in.in_range("atol", 0.0, 0.1, true);
  if (auto ms = in.find("max_step")) {
    // 0 would be read by the integrators as "no limit": refused, the key is omitted for that.
    const double v = ms->as_number();
    if (!(v > 0.0 && v <= sc.duration))
      ms->fail("expected a step in (0, " + config::format_number(sc.duration) + "] s (the duration; got " +
               config::format_number(v) + "); omit max_step to leave the step unlimited");
    o.max_step = v;
  }
  if (auto is = in.find("initial_step")) {
    const double v = is->as_number();
    if (!(v >= 0.0 && v <= sc.duration))
      is->fail("expected a step in [0, " + config::format_number(sc.duration) +
               "] s (0: the integrator's choice; at most the duration; got " + config::format_number(v) + ")");
    o.initial_step = v;
  }
  if (auto ms = in.find("min_step")) {
    const double v = ms->as_number();
    const double hi = o.max_step > 0.0 ? std::min(o.max_step, sc.output_interval) : sc.output_interval;
    if (!(v >= 0.0 && v < hi))
      ms->fail("expected a step in [0, " + config::format_number(hi) + ") s (below the output interval" +
               std::string(o.max_step > 0.0 ? " and max_step" : "") + "; got " + config::format_number(v) + ")");
    o.min_step = v;
  }
  if (in.has("max_steps")) o.max_steps = in.integer_in_range("max_steps", 1, 1000000000);
  if (in.has("max_order")) o.max_order = static_cast<int>(in.integer_in_range("max_order", 1, 5));
  if (in.has("jacobian_max_age")) o.jacobian_max_age = in.integer_in_range("jacobian_max_age", 1, 1000000);
  if (in.has("atol_contact_modes")) o.atol_contact_modes = in.in_range("atol_contact_modes", 0.0, 1.0);
  if (auto sl = in.find("stability_limit_detection")) o.stability_limit_detection = sl->as_bool();
  o.jacobian = in.choice_or("jacobian", o.jacobian, {"fd", "assembled"});
  o.linear_solver = in.choice_or("linear_solver", o.linear_solver, {"auto", "klu", "dense", "band"});
  bool known = false;
  for (const auto& e : integrators()) known |= o.method == e.name;
  if (!known) in.at("method").fail("unknown integrator '" + o.method + "' (known: " + integrator_names() + ")");
  if (o.linear_solver == "klu" && o.jacobian == "fd")
    in.at("jacobian").fail("'fd' works with the dense and band solvers only; 'klu' needs 'assembled'");
}

// Step (after finalize_model): the coupling with the patch at the static load
// of the first wheel (Hertz: a, b ~ N^{1/3} for fixed A, B) and the static approach.
void build_coupling(ContactSection& cs, Model& m) {
  CouplingOptions& co = cs.options;
  double q0 = cs.static_approach;
  if (cs.hertz) {
    const ContactPointGeometry c0 = cs.geometry->main_point(0.0);
    const double Ns = m.wheelsets.front().static_load[0];
    const contact::HertzPatch hp = contact::hertz_from_load(c0.A, c0.B, Ns, co.material);
    co.patch_a = hp.a;
    co.patch_b = hp.b;
    co.N_ref = Ns;
    q0 = hp.approach;
  }
  m.coupling = WheelRailCoupling(co);
  for (auto& w : m.wheelsets) w.hertz_q0[0] = w.hertz_q0[1] = q0;
}

// Step: the nominal patch (centred wheelset, static load of the first wheel)
// for layer factors and reports (Scenario::nominal_patch).
contact::HertzPatch nominal_patch(const Scenario& sc, const ContactGeometry& geo) {
  const Model& m = sc.model;
  const CouplingOptions& co = m.coupling.options();
  const ContactPointGeometry c0 = geo.main_point(0.0);
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
  if (!(a > 0 && b > 0) && Ns > 0 && geo.distributed() && geo.strips(0.0, 0.0, ProfileGeometry::kGapCutoff, set)) {
    // Distributed contact (profiles): the most loaded patch of the centred
    // wheel under its static vertical load, as the wheelset models form it
    // (engine/wheel_rail/strip_patches.hpp: equivalent ellipse, normal load N).
    StripLoads loads;
    strip_approach_for_load(set, Ns, 0.0, geo.contact_modulus(), loads, m.patch_shape);
    int best = -1;
    for (int k = 0; k < loads.n; ++k)
      if (best < 0 || loads.N[k] > loads.N[best]) best = k;
    if (best >= 0 && loads.N[best] > 0) {
      a = loads.patch[best].semi_a;
      b = loads.patch[best].semi_b;
      N = loads.N[best];
    }
  }
  return a > 0 && b > 0 && N > 0 ? contact::hertz_from_semi_axes(a, b, N, sc.creep_material) : contact::HertzPatch{};
}

// Step: the start state, (quasi-)static (equilibrium.hpp) unless `start:
// nominal`, with the user's `initial:` deviations on top, each range-checked.
void read_start_state(const InputNode& root, Scenario& sc) {
  const Model& m = sc.model;
  sc.x0 = Eigen::VectorXd::Zero(m.n_states);
  if (root.choice_or("start", "equilibrium", {"equilibrium", "nominal"}) == "equilibrium") {
    EquilibriumResult eq;
    try {
      eq = static_equilibrium(m, 0.0);
    } catch (const NumericalError& e) {
      // The model fails at the nominal start state itself (every body on its
      // track frame): the start lies outside the model's range (a wheelset
      // beyond the geometry inside a large irregularity): bad input, not a
      // numerical failure of the run, and no physics result.
      const InputNode& at = root.has("start_distance") ? root.at("start_distance") : root;
      at.fail("the start state (every body centred on its track frame) is outside the model's range there, so no "
              "run can start: " + std::string(e.what()) + "; start elsewhere on the track");
    }
    if (eq.converged) {
      sc.x0 = eq.x;
    } else {  // said in the run's summary.json (warnings) and the log
      char head[160];
      std::snprintf(head, sizeof head,
                    "no (quasi-)static equilibrium found at the start (residual: largest acceleration %.3g m/s^2)",
                    eq.residual);
      sc.warnings.push_back("scenario '" + sc.name + "': " + head + "; starting from the nominal state (every body "
                            "centred on its track frame, a start transient follows): " + eq.message);
      spdlog::warn("{}", sc.warnings.back());
    }
    sc.start_residual = eq.residual;
  }
  auto init = root.find("initial");
  if (!init) return;
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
  // Deviations within their ranges can still put the start outside what the
  // model covers (the lateral model's wheel unloaded by a large shift): the
  // user's input, so bad input here, not a numerical failure at t = 0.
  Data data(m);
  Eigen::VectorXd xdot(m.n_states);
  if (!rhs(m, data, 0.0, sc.x0.data(), xdot.data()) && data.left_range)
    init->fail("these deviations put the start state outside the model's range (" + data.failure +
               "); give smaller ones");
}

}  // namespace

Scenario load_scenario(const InputNode& root, const std::string& base) {
  root.allow_only({"name", "description", "vehicle", "track", "speed", "speed_kmh", "acceleration", "start",
                   "start_distance", "duration", "output_interval", "wheelset_model", "max_lateral_shift",
                   "wheelset_roll", "axle_rotation", "contact", "integrator", "initial", "critical_speed",
                   "running_safety", "track_flexibility"});
  Scenario sc;
  sc.name = root.string_or("name", "");
  Model& m = sc.model;
  load_vehicle(root.at("vehicle").as_existing_file(base), m);
  const auto track = read_track(root, base);
  for (const std::string& w : track->warnings()) {  // e.g. a measured record reaching far beyond the track
    sc.warnings.push_back(w);
    spdlog::warn("{}", w);
  }
  m.track = std::make_shared<TrackInput>(track);
  read_motion(root, track->length(), sc);
  read_wheelset_model(root, m);
  read_track_flexibility(root, track->length(), m);
  ContactSection contact = read_contact(root.at("contact"), base, *track, sc);
  const ContactGeometry& geo = *contact.geometry;
  sc.geometry_description = geo.describe();
  if (geo.max_shift() >= 3e-3)
    sc.equivalent_conicity_3mm = contact::equivalent_conicity(
        [&](double y) { return geo.main_point(y).rolling_radius - geo.main_point(-y).rolling_radius; }, 3e-3, 400);
  for (auto& w : m.wheelsets) w.geometry = contact.geometry;
  m.patch_shape = contact.patch_shape;
  if (auto in = root.find("integrator")) read_integrator(*in, sc);

  finalize_model(m);
  build_coupling(contact, m);
  const CouplingOptions& co = contact.options;
  sc.creep_material = co.shear_modulus > 0
                          ? contact::Material::from_shear_modulus(co.shear_modulus, co.material.nu, co.material.mu)
                          : co.material;
  sc.nominal_patch = nominal_patch(sc, geo);
  if (contact.reduction.form != contact::ReductionForm::unset)
    apply_reduction(sc, contact.reduction, contact.reduction_where);
  if (auto cs = root.find("critical_speed")) sc.critical_speed = load_critical_speed_settings(*cs);
  sc.running_safety = root.find("running_safety");
  read_start_state(root, sc);
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
