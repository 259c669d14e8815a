// `railsim conicity`: equivalent conicity (EN 15302 regression over a harmonic
// of amplitude A) at 1..6 mm, and optionally the rolling-radius-difference
// curve: of wheel and rail profiles (railsim's contact search), or with
// --table of a contact-geometry table file (RSGEO format, the engine's smoothed
// reading of it, engine/wheel_rail/geometry_table.hpp).
#include <cstdio>

#include "cli/commands.hpp"
#include "cli/support_geometry.hpp"
#include "contact/geometry/conicity.hpp"
#include "engine/wheel_rail/geometry_table.hpp"
#include "results/csv_writer.hpp"

namespace railsim::cli {

void register_conicity(CLI::App& app, CommandRunner& run) {
  auto* cmd = app.add_subcommand("conicity", "Equivalent conicity at 1..6 mm amplitude and the delta-r curve");
  auto o = std::make_shared<GeometryOptions>();
  auto out = std::make_shared<std::string>();
  auto table = std::make_shared<std::string>();
  add_geometry_options(*cmd, *o);
  cmd->add_option("--out", *out, "Optional CSV of the rolling-radius difference y, delta_r [m]");
  cmd->add_option("--table", *table,
                  "Contact-geometry table file (RSGEO format, e.g. vehicles/contact_tables/RSGEO_S1002_UIC60_1in40.dat) "
                  "instead of profiles");
  cmd->callback([&run, o, out, table] {
    run = [o, out, table] {
      if (!table->empty()) {
        const engine::GeometryTable t(*table);
        auto dr = [&](double y) { return t.main_point(y).rolling_radius - t.main_point(-y).rolling_radius; };
        std::printf("amplitude_mm,equivalent_conicity\n");
        for (int a = 1; a <= 6; ++a) {
          if (a * 1e-3 > t.max_shift()) break;
          std::printf("%d,%.5f\n", a, contact::equivalent_conicity(dr, a * 1e-3));
        }
        if (!out->empty()) {
          results::CsvWriter w(*out, {"y", "delta_r"}, false, 0, 10);
          for (double y = -t.max_shift(); y <= t.max_shift() + 1e-12; y += 1e-4) w.row({y, dr(y)});
        }
        return 0;
      }
      const GeometrySetup g = make_geometry(*o);
      const contact::ContactTable t = make_table(*o, g);
      std::printf("amplitude_mm,equivalent_conicity\n");
      for (int a = 1; a <= 6; ++a) std::printf("%d,%.5f\n", a, contact::equivalent_conicity(t, a * 1e-3));
      if (!out->empty()) {
        const auto c = contact::rolling_radius_difference(t);
        results::CsvWriter w(*out, {"y", "delta_r"}, false, 0, 10);
        for (std::size_t i = 0; i < c.y.size(); ++i) w.row({c.y[i], c.delta_r[i]});
      }
      return 0;
    };
  });
}

}  // namespace railsim::cli
