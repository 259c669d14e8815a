// `railsim wheelset-contact CASES.yaml --model NAME --out forces.csv [--grid N]
// [--tolerance T] [--extrapolation none|richardson]`: the
// contact of a whole wheelset at given poses (engine/analysis/
// wheelset_contact_cases.hpp), one row per position: the total force of each
// wheel on its rail in railsim's track frame and, per contact patch, its
// positions on wheel and rail, rolling radius, contact angle (track frame:
// a left flange > 0, a right flange < 0, as `railsim geometry`), semi-axes,
// normal load, creepages, forces and the model's validity flag (0: outside
// its domain, with a warning naming the position and the reason). CASES.yaml:
//   wheel: S1002            # profile file (relative to CASES.yaml) or shipped name
//   rail: UIC60
//   inclination: 1/40       # 0 when the rail file is already inclined
//   gauge: 1.435            # [m], measured gauge_depth below the top of rail
//   gauge_depth: 0.014      # [m], optional
//   flange_back: 1.360      # [m]
//   back_face: -0.070       # [m], optional: wheel-profile y of the flange back face
//   nominal_radius: 0.46    # [m]
//   material: {G: 8.2e10, nu: 0.28, mu: 0.3}   # or E instead of G
//   speed: 2.0              # [m/s]
//   strip: 2.5e-4           # [m], optional strip width of the normal contact
//   positions:              # y toward the left wheel [m], yaw leading end to the left [rad], Fz per wheel [N]
//     - {y: 0.001, yaw: 0.0024, Fz: 1.0e4, roll: -1.1e-4, omega: 4.348}   # roll [rad], omega [rad/s] optional
//     - {y: 0.005, Fz: 6.0e4, omega: free}   # the free axle's speed (no torque from the creep forces)
// Without omega the axle turns at V / r0 (driven: in flange contact a large
// net longitudinal force); `omega: free` finds the speed of a free axle. The
// CSV's column omega is the speed used.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "cli/commands.hpp"
#include "cli/support_option_checks.hpp"
#include "config/yaml_input.hpp"
#include "contact/geometry/profile.hpp"
#include "contact/geometry/wheel_rail_geometry.hpp"
#include "contact/registry.hpp"
#include "core/errors.hpp"
#include "engine/analysis/wheelset_contact_cases.hpp"
#include "engine/io/scenario.hpp"
#include "results/csv_writer.hpp"

namespace railsim::cli {

namespace {

struct WheelsetContactArgs {
  std::string cases;
  std::string model = "chopaya";
  std::string out = "wheelset_contact.csv";
  int grid = 0;
  double tolerance = 0.0;
  std::string extrapolation;
};

constexpr int kMinPatchColumns = 3;  // patches per wheel written: at least 3, more when a wheel has more

int run_wheelset_contact(const WheelsetContactArgs& a) {
  namespace fs = std::filesystem;
  check_out_is_not_input(a.out, a.cases);
  const auto root = config::InputNode::load_file(a.cases);
  root.allow_only({"wheel", "rail", "inclination", "gauge", "gauge_depth", "flange_back", "back_face",
                   "nominal_radius", "material", "speed", "strip", "positions"});
  const std::string base = fs::path(a.cases).parent_path().string();
  engine::WheelsetContactSetup s;
  auto profile = [&](const char* key, const std::string& fallback) {
    if (!root.has(key)) return fallback;
    const std::string v = root.string(key);
    const fs::path p = fs::path(v).is_absolute() ? fs::path(v) : fs::path(base) / v;
    if (fs::exists(p)) return p.lexically_normal().string();
    if (contact::is_shipped_profile_name(v)) return v;
    // Not the working folder's file of that name: the case file means its own folder.
    root.at(key).fail("no profile file " + p.lexically_normal().string() +
                      " (a relative path is taken from the case file's folder) and not a shipped profile name (" +
                      contact::shipped_profile_names() + ")");
  };
  s.wheel = profile("wheel", s.wheel);
  s.rail = profile("rail", s.rail);
  check_out_against_inputs(a.out, {s.wheel, s.rail});  // a profile file of the cases: not the result file
  s.track = engine::read_track_setup(root, "nominal_radius");
  if (auto m = root.find("material")) {
    m->allow_only({"E", "G", "nu", "mu"});
    if (m->has("E") && m->has("G")) m->fail("give E or G, not both");
    const double nu = m->has("nu") ? m->in_range("nu", 0.0, 0.5, true, false) : s.material.nu;
    const double mu = m->has("mu") ? m->in_range("mu", 0.0, 2.0, true) : s.material.mu;
    if (m->has("G")) s.material = contact::Material::from_shear_modulus(m->in_range("G", 1e9, 1e12), nu, mu);
    else s.material = {m->has("E") ? m->in_range("E", 1e9, 1e13) : s.material.E, nu, mu};
  }
  s.speed = root.has("speed") ? root.in_range("speed", 0.0, 200.0, true) : 1.0;
  if (root.has("strip")) s.strip = root.in_range("strip", 2e-5, 2e-3);
  s.where = a.cases;
  s.model = a.model;
  s.model_options.grid = a.grid;
  s.model_options.tolerance = a.tolerance;
  if (!a.extrapolation.empty())
    s.model_options.extrapolation = contact::grid_extrapolation_from_name(a.extrapolation, "--extrapolation");
  check_model_reads_options(tangential_model_option("--model", a.model), s.model_options);
  std::vector<engine::WheelsetContactPosition> pos;
  for (const auto& n : root.at("positions").elements()) {
    n.allow_only({"y", "yaw", "Fz", "roll", "omega"});
    engine::WheelsetContactPosition p;
    p.where = n.where() + ": key 'positions[" + std::to_string(pos.size()) + "]'";
    p.y = n.in_range("y", -0.03, 0.03);
    p.yaw = n.has("yaw") ? n.in_range("yaw", -0.1, 0.1) : 0.0;
    // At least 1 N: 1e-6 N gave a 37 nm patch (a/b 200) that took MIM 39 s and 730 MB.
    p.Fz = n.in_range("Fz", 1.0, 1e6);
    if (n.has("roll")) {
      p.roll = n.in_range("roll", -0.1, 0.1);
      p.has_roll = true;
    }
    if (n.has("omega")) {
      const config::InputNode o = n.at("omega");
      if (o.is_scalar() && o.as_string() == "free") {
        p.free_rolling = true;  // the free axle's speed, found
      } else {
        if (o.is_scalar()) {  // a word other than free: say that free is the word
          const std::string v = o.as_string();
          char* end = nullptr;
          std::strtod(v.c_str(), &end);
          if (v.empty() || end != v.c_str() + v.size())
            o.fail("expected a rolling speed [rad/s] or free (got " + o.text() + ")");
        }
        p.omega = o.as_in_range(0.0, 1e4, true);
        p.has_omega = true;
      }
    }
    pos.push_back(p);
  }
  if (pos.empty()) root.at("positions").fail("expected at least one position");
  const auto res = engine::wheelset_contact(s, pos);
  int patch_columns = kMinPatchColumns;  // every patch of every wheel gets its columns
  for (const auto& r : res)
    for (const auto& w : r.wheel) patch_columns = std::max(patch_columns, int(w.patches.size()));

  std::vector<std::string> cols = {"y", "yaw", "roll", "omega"};
  for (const char* w : {"left", "right"})
    for (const char* f : {"Fx", "Fy", "Fz", "patches", "climbing"}) cols.push_back(std::string(w) + "_" + f);
  const char* fields[] = {"N", "y_wheel", "y_rail", "y_track", "x_track", "rolling_radius", "contact_angle",
                          "a", "b", "xi", "eta", "spin", "Fx_patch", "Fy_patch", "valid"};
  for (const char* w : {"left", "right"})
    for (int k = 1; k <= patch_columns; ++k)
      for (const char* f : fields) cols.push_back(std::string(w) + std::to_string(k) + "_" + f);
  results::CsvWriter csv(a.out, cols, false, 0, 10);
  for (const auto& r : res) {
    csv.cell(r.position.y).cell(r.position.yaw).cell(r.roll).cell(r.omega);
    for (const auto& w : r.wheel)
      csv.cell(w.Fx).cell(w.Fy).cell(w.Fz).cell(long(w.patches.size())).cell(long(w.climbing));
    for (const auto& w : r.wheel)
      for (int k = 0; k < patch_columns; ++k) {
        if (k < int(w.patches.size())) {
          const auto& p = w.patches[std::size_t(k)];
          for (double v : {p.N, p.y_wheel, p.y_rail, p.y_track, p.x_track, p.rolling_radius, p.contact_angle, p.a, p.b,
                           p.creep.xi, p.creep.eta, p.creep.phi, p.forces.Fx, p.forces.Fy})
            csv.cell(v);
          csv.cell(long(p.forces.valid));  // 0: outside the model's validity domain (and a warning)
        } else {
          for (std::size_t f = 0; f < std::size(fields); ++f) csv.cell(std::nan(""));
        }
      }
    csv.end_row();
  }
  csv.close();
  for (const auto& r : res)
    for (const auto& w : r.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
  std::printf("wrote %s (%zu positions, model %s)\n", a.out.c_str(), res.size(), a.model.c_str());
  return kExitSuccess;
}

}  // namespace

void register_wheelset_contact(CLI::App& app, CommandRunner& run) {
  auto a = std::make_shared<WheelsetContactArgs>();
  auto* cmd = app.add_subcommand("wheelset-contact",
                                 "Contact forces of a whole wheelset at given poses (profiles, yaw, loads), per wheel "
                                 "and patch (CSV)");
  cmd->add_option("cases", a->cases, "Cases YAML file (profiles, set-up, material, speed, positions)")->required();
  cmd->add_option("--model", a->model, "Tangential contact model (e.g. mim, fastsim, chopaya)")->capture_default_str();
  cmd->add_option("--out", a->out, "Output CSV file")->capture_default_str();
  cmd->add_option("--grid", a->grid, "Elements across the minor axis (mim; 0 = model default)")
      ->check(CLI::Range(0, 400));
  cmd->add_option("--tolerance", a->tolerance, "Solver tolerance (mim; 0 = model default)")->check(number_range(0.0, 0.1));
  cmd->add_option("--extrapolation", a->extrapolation,
                  "Grid extrapolation of model mim: richardson (default; from grid N and N/2) or none (the grid's "
                  "own forces, CONTACT's discretisation)")
      ->check(CLI::IsMember({"none", "richardson"}));
  cmd->callback([a, &run] { run = [a] { return run_wheelset_contact(*a); }; });
}

}  // namespace railsim::cli
