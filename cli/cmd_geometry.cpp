// `railsim geometry`: wheel-rail contact table versus lateral shift (CSV).
// One row per y (wheelset shift, positive to the left), SI units, angles in rad;
// columns as ContactTable::column_names() (left_*/right_* = touching point,
// left2_*/right2_* = second point of two-point contact, NaN when absent).
#include <spdlog/spdlog.h>

#include <cmath>
#include <string>

#include "cli/commands.hpp"
#include "cli/support_geometry.hpp"
#include "cli/support_option_checks.hpp"
#include "results/csv_writer.hpp"

namespace railsim::cli {

void register_geometry(CLI::App& app, CommandRunner& run) {
  auto* cmd = app.add_subcommand("geometry", "Wheel-rail contact geometry table versus lateral shift (CSV)");
  auto o = std::make_shared<GeometryOptions>();
  auto out = std::make_shared<std::string>();
  add_geometry_options(*cmd, *o);
  cmd->add_option("--out", *out, "Output CSV file")->required();
  cmd->callback([&run, o, out] {
    run = [o, out] {
      check_out_against_inputs(*out, {o->wheel, o->rail});
      const GeometrySetup g = make_geometry(*o);
      const contact::ContactTable t = make_table(*o, g);
      results::CsvWriter w(*out, contact::ContactTable::column_names(), false, 0, 10);
      for (std::size_t r = 0; r < t.rows(); ++r) {
        for (int c = 0; c < contact::ContactTable::kColumns; ++c) w.cell(t.value(r, c));
        w.end_row();
      }
      w.close();
      // Flange contact onset: first shift where the touching point's contact angle exceeds 30 deg.
      const double lim = 30.0 * std::acos(-1.0) / 180.0;
      const auto names = contact::ContactTable::column_names();
      int la = -1, ra = -1;
      for (int i = 0; i < static_cast<int>(names.size()); ++i) {
        if (names[static_cast<std::size_t>(i)] == "left_angle") la = i;
        if (names[static_cast<std::size_t>(i)] == "right_angle") ra = i;
      }
      double yl = NAN, yr = NAN;
      for (std::size_t r = 0; r < t.rows(); ++r)
        if (t.value(r, 0) >= 0 && std::isnan(yl) && std::abs(t.value(r, la)) > lim) yl = t.value(r, 0);
      for (std::size_t r = t.rows(); r-- > 0;)
        if (t.value(r, 0) <= 0 && std::isnan(yr) && std::abs(t.value(r, ra)) > lim) yr = t.value(r, 0);
      std::printf("wrote %s (%zu rows)\n", out->c_str(), t.rows());
      // A wheel that meets no contact angle above 30 deg within the table's range has none to report.
      const double y_lo = t.value(0, 0), y_hi = t.value(t.rows() - 1, 0);
      auto say = [](double y, double edge) {
        char buf[64];
        if (std::isnan(y)) std::snprintf(buf, sizeof buf, "none up to y = %+.1f mm", edge * 1e3);
        else std::snprintf(buf, sizeof buf, "from y = %+.1f mm", y * 1e3);
        return std::string(buf);
      };
      std::printf("flange contact (angle > 30 deg): left wheel %s, right wheel %s\n", say(yl, y_hi).c_str(),
                  say(yr, y_lo).c_str());
      return 0;
    };
  });
}

}  // namespace railsim::cli
