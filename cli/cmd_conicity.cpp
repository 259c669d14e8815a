// `railsim conicity`: equivalent conicity (EN 15302 regression over a harmonic
// of amplitude A) at 1..6 mm, and optionally the rolling-radius-difference
// curve: of wheel and rail profiles (railsim's contact search), or with
// --table of a contact-geometry table file (RSGEO format, the engine's smoothed
// reading of it, engine/wheel_rail/geometry_table.hpp).
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "cli/commands.hpp"
#include "cli/support_geometry.hpp"
#include "cli/support_option_checks.hpp"
#include "config/yaml_input.hpp"
#include "contact/geometry/conicity.hpp"
#include "core/errors.hpp"
#include "engine/wheel_rail/geometry_table.hpp"
#include "results/csv_writer.hpp"

namespace railsim::cli {

namespace {
// The amplitudes 1..n mm (n at most 6) whose sweep +-A lies within shifts of
// +-reach [m]: the ones a table or a shift range can give.
int amplitudes_within(double reach) { return std::min(6, int(std::floor(reach * 1e3 + 1e-9))); }
}  // namespace

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
  cmd->callback([&run, cmd, o, out, table] {
    // With --table the file holds its own geometry and shift grid: the
    // profile and grid options do not apply (they were ignored silently).
    std::string misplaced;
    if (!table->empty())
      for (const char* opt : {"--wheel", "--rail", "--wheel-units", "--rail-units", "--inclination", "--gauge",
                              "--gauge-depth", "--flange-back", "--back-face", "--radius", "--y-min", "--y-max",
                              "--y-step", "--cache-dir", "--no-cache"})
        if (misplaced.empty() && cmd->count(opt) > 0) misplaced = opt;
    run = [o, out, table, misplaced] {
      check_out_against_inputs(*out, {o->wheel, o->rail, *table});
      if (!misplaced.empty())
        throw InputError(misplaced + ": does not apply with --table (the table file holds its own geometry and "
                                     "shift grid)");
      if (!table->empty()) {
        const engine::GeometryTable t(*table);
        auto dr = [&](double y) { return t.main_point(y).rolling_radius - t.main_point(-y).rolling_radius; };
        const int fitting = amplitudes_within(t.max_shift());
        if (fitting < 1)
          throw InputError("--table " + *table + ": the table covers shifts up to +-" +
                           config::format_number(t.max_shift() * 1e3) +
                           " mm: no amplitude of 1..6 mm fits (the sweep +-A must lie within the table)");
        std::printf("amplitude_mm,equivalent_conicity\n");
        for (int a = 1; a <= fitting; ++a) std::printf("%d,%.5f\n", a, contact::equivalent_conicity(dr, a * 1e-3));
        if (fitting < 6)
          spdlog::warn("--table {}: amplitudes {}..6 mm lie beyond the table's +-{} mm: not computed", *table,
                       fitting + 1, config::format_number(t.max_shift() * 1e3));
        if (!out->empty()) {
          // 0.1 mm, finer on a narrow table (at least 100 intervals).
          const double step = std::min(1e-4, t.max_shift() / 50.0);
          const int n = int(std::floor(2.0 * t.max_shift() / step + 1e-9));
          results::CsvWriter w(*out, {"y", "delta_r"}, false, 0, 10);
          for (int i = 0; i <= n; ++i) {
            const double y = -t.max_shift() + i * step;
            w.row({y, dr(y)});
          }
        }
        return 0;
      }
      const GeometrySetup g = make_geometry(*o);
      const contact::ContactTable t = make_table(*o, g);
      // As with --table: the amplitudes whose sweep +-A lies within the shifts are computed (their
      // regression sees the whole delta-r curve over +-A, the result is the conicity at that amplitude),
      // the others are named in a warning; only a range that fits no amplitude is refused. (A range
      // narrower than +-3 mm refused every amplitude, where a table of the same range gave 1 and 2 mm.)
      const int fitting = amplitudes_within(std::min(-t.grid().y_min, t.grid().y_max));
      if (fitting < 1)
        throw InputError("--y-min/--y-max: the shifts " + config::format_number(t.grid().y_min * 1e3) + " .. " +
                         config::format_number(t.grid().y_max * 1e3) +
                         " mm fit no amplitude of 1..6 mm (the sweep +-A must lie within them: --y-min at most -1 mm "
                         "and --y-max at least 1 mm; -6 mm and 6 mm for every amplitude)");
      double conicity[6];
      for (int a = 1; a <= fitting; ++a) {
        try {
          conicity[a - 1] = contact::equivalent_conicity(t, a * 1e-3);
        } catch (const InputError& e) {
          throw InputError(std::string(std::string(e.what()).find("y step") != std::string::npos ? "--y-step"
                                                                                                  : "--y-min/--y-max") +
                           ": " + e.what());
        }
      }
      std::printf("amplitude_mm,equivalent_conicity\n");
      for (int a = 1; a <= fitting; ++a) std::printf("%d,%.5f\n", a, conicity[a - 1]);
      if (fitting < 6)
        spdlog::warn("--y-min/--y-max: amplitudes {}..6 mm lie beyond the shifts {} .. {} mm: not computed (widen the "
                     "range to +-6 mm for every amplitude)",
                     fitting + 1, config::format_number(t.grid().y_min * 1e3),
                     config::format_number(t.grid().y_max * 1e3));
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
