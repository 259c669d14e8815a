// Equivalent conicity by linear regression over a harmonic (see conicity.hpp).
#include "contact/geometry/conicity.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/errors.hpp"

namespace railsim::contact {

RollingRadiusCurve rolling_radius_difference(const ContactTable& table) {
  RollingRadiusCurve c;
  const auto cols = ContactTable::column_names();
  int rl = -1, rr = -1;
  for (int i = 0; i < static_cast<int>(cols.size()); ++i) {
    if (cols[static_cast<std::size_t>(i)] == "left_radius") rl = i;
    if (cols[static_cast<std::size_t>(i)] == "right_radius") rr = i;
  }
  for (std::size_t r = 0; r < table.rows(); ++r) {
    c.y.push_back(table.value(r, 0));
    c.delta_r.push_back(table.value(r, rl) - table.value(r, rr));
  }
  return c;
}

double equivalent_conicity(const ContactTable& table, double amplitude, int samples) {
  const TableGrid& g = table.grid();
  if (!(amplitude > 0.0) || -amplitude < g.y_min - 1e-12 || amplitude > g.y_max + 1e-12) {
    char buf[200];
    // The sweep runs over [-amplitude, amplitude]: a positive amplitude the table covers on both sides.
    std::snprintf(buf, sizeof buf,
                  "equivalent conicity: amplitude %.6g m: expected a value in (0, %.6g] m (positive, and the sweep "
                  "[-amplitude, amplitude] within the table's range [%.6g, %.6g] m)",
                  amplitude, std::min(-g.y_min, g.y_max), g.y_min, g.y_max);
    throw InputError(buf);
  }
  // The regression needs the delta-r curve resolved over the sweep: rows at
  // most a quarter of the amplitude apart (a 12 mm step gave 0 at every amplitude).
  if (g.y_step > 0.25 * amplitude + 1e-15) {
    char buf[200];
    std::snprintf(buf, sizeof buf,
                  "equivalent conicity at amplitude %.6g mm: the table's y step %.6g mm is too coarse (at most a "
                  "quarter of the amplitude, %.6g mm)",
                  amplitude * 1e3, g.y_step * 1e3, 0.25 * amplitude * 1e3);
    throw InputError(buf);
  }
  return equivalent_conicity(
      [&](double y) {
        TableSample s;
        table.lookup(std::clamp(y, g.y_min, g.y_max), s);
        return s.wheel[0].p[0].radius - s.wheel[1].p[0].radius;
      },
      amplitude, samples);
}

double equivalent_conicity(const std::function<double(double)>& delta_r, double amplitude, int samples) {
  if (!(amplitude > 0.0) || samples < 4) throw InputError("equivalent conicity: need a positive amplitude");
  double sy = 0, sd = 0, syy = 0, syd = 0;
  const double pi = std::acos(-1.0);
  for (int i = 0; i < samples; ++i) {
    const double y = amplitude * std::sin(2.0 * pi * (i + 0.5) / samples);
    const double dr = delta_r(y);
    sy += y;
    sd += dr;
    syy += y * y;
    syd += y * dr;
  }
  const double n = samples;
  const double slope = (n * syd - sy * sd) / (n * syy - sy * sy);
  return 0.5 * slope;
}

}  // namespace railsim::contact
