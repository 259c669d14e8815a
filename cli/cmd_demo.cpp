// `railsim demo [--out DIR]`: every registered tangential contact model on a few
// typical wheel-rail contacts (embedded case set below), a one-screen comparison
// table on stdout and DIR/demo.csv (columns as `railsim contact`).
// The model list comes from contact::tangential_models(), so models registered
// later appear automatically (except cached-table models such as mim_table,
// whose first use builds the table: see compare-contact --with-mim-table).
#include <spdlog/spdlog.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/support_contact_cases.hpp"
#include "contact/registry.hpp"
#include "core/errors.hpp"
#include "core/output_lock.hpp"

namespace railsim::cli {

namespace {

// Wheel radius 460 mm on a 300 mm rail head (A = 1/0.92, B = 1/0.6 1/m, a/b ~ 1.33),
// 75 kN, steel, mu = 0.3.
constexpr const char* kDemoCases = R"(material: {E: 2.1e11, nu: 0.28, mu: 0.3}
cases:
  - {id: tread,        A: 1.0869565217, B: 1.6666666667, Fz: 75000, xi: 0.0005, eta: 0.0005, phi: 0.05}
  - {id: longitudinal, A: 1.0869565217, B: 1.6666666667, Fz: 75000, xi: 0.001,  eta: 0.0,    phi: 0.0}
  - {id: lateral,      A: 1.0869565217, B: 1.6666666667, Fz: 75000, xi: 0.0,    eta: 0.001,  phi: 0.0}
  - {id: spin,         A: 1.0869565217, B: 1.6666666667, Fz: 75000, xi: 0.0,    eta: 0.0005, phi: 1.0}
  - {id: saturated,    A: 1.0869565217, B: 1.6666666667, Fz: 75000, xi: 0.01,   eta: 0.01,   phi: 0.0}
)";

int run_demo(const std::string& out_dir) {
  const ContactCaseSet set = read_contact_cases(config::InputNode::load_string(kDemoCases, "<demo cases>"));
  std::error_code ec;
  std::filesystem::create_directories(out_dir, ec);
  if (ec) throw InputError("--out: cannot create folder '" + out_dir + "': " + ec.message());
  const OutputLock lock(out_dir);  // one writer per output folder
  const std::string csv_path = (std::filesystem::path(out_dir) / "demo.csv").string();
  results::CsvWriter csv(csv_path, contact_csv_columns());

  const double muN = set.material.mu * set.cases.front().input.patch.Fz;
  std::printf("railsim demo: tangential contact models on typical wheel-rail contacts\n");
  std::printf("steel E = %.0f GPa, nu = %.2f, mu = %.2f; Fz = %.0f kN; patch a = %.2f mm, b = %.2f mm, p0 = %.0f MPa\n",
              set.material.E / 1e9, set.material.nu, set.material.mu, set.cases.front().input.patch.Fz / 1e3,
              set.cases.front().input.patch.a * 1e3, set.cases.front().input.patch.b * 1e3,
              set.cases.front().input.patch.p0 / 1e6);
  for (const auto& c : set.cases)
    std::printf("  %-14s xi = %-8g eta = %-8g phi = %g 1/m\n", c.id.c_str(), c.input.creep.xi, c.input.creep.eta,
                c.input.creep.phi);
  std::printf("\nFx/Fy in kN (* = outside the model's validity domain); |F|/(mu Fz); cost per call\n");
  std::printf("%-18s", "model");
  for (const auto& c : set.cases) std::printf("%15s", c.id.c_str());
  std::printf("%9s\n", "ns/call");

  int failed = 0;
  for (const auto& entry : contact::tangential_models()) {
    if (!entry.compared_by_default()) continue;  // cached-table models: compare-contact --with-mim-table
    std::printf("%-18s", entry.name);
    try {
      const auto model = entry.make({});
      const auto ws = model->make_workspace();
      double total_ns = 0.0;
      std::string ratios;
      for (const auto& c : set.cases) {
        const TimedForces r = solve_timed(*model, c.input, ws.get());
        write_contact_row(csv, c, entry.name, r);
        total_ns += r.time_ns;
        char buf[64];
        std::snprintf(buf, sizeof buf, "%.1f/%.1f%s", r.forces.Fx / 1e3 + 0.0, r.forces.Fy / 1e3 + 0.0,
                      r.forces.valid ? " " : "*");
        std::printf("%15s", buf);
        std::snprintf(buf, sizeof buf, "%15.3f", std::hypot(r.forces.Fx, r.forces.Fy) / muN);
        ratios += buf;
      }
      std::printf("%9.0f\n%-18s%s\n", total_ns / static_cast<double>(set.cases.size()), "", ratios.c_str());
    } catch (const std::exception& e) {
      ++failed;
      std::printf("  failed: %s\n", e.what());
      spdlog::warn("demo: model {} failed: {}", entry.name, e.what());
    }
  }
  std::printf("\nAll rows: %s\n", csv_path.c_str());
  return failed == 0 ? 0 : kExitNumericalFailure;
}

}  // namespace

void register_demo(CLI::App& app, CommandRunner& run) {
  auto out = std::make_shared<std::string>("railsim_demo");
  auto* cmd = app.add_subcommand("demo", "Compare every tangential contact model on typical wheel-rail contacts");
  cmd->add_option("--out", *out, "Output folder for demo.csv")->capture_default_str();
  cmd->callback([&run, out] { run = [out] { return run_demo(*out); }; });
}

}  // namespace railsim::cli
