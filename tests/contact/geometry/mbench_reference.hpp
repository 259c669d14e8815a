// Reading the CONTACT Manchester-benchmark sweep and the exclusion list for the
// geometry tests (see tests/data/reference/contact/README.md section (d)).
#pragma once

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "results/csv_writer.hpp"
#include "test_support.hpp"

namespace railsim::test {

struct MbenchRow {
  std::string series, side;
  double y_ws = 0, yaw = 0, roll = 0;  // CONTACT: y_ws positive to the right (mm -> m), yaw about z down
  double xcp = 0, ycp_tr = 0, r_roll = 0, delta = 0, pen = 0, FN = 0, pmax = 0, area = 0, length = 0, width = 0;  // SI
  int npatch = 0;
};

inline std::vector<MbenchRow> read_mbench() {
  const auto t = results::read_csv(reference_path("contact/mbench_S1002_UIC60_sweep.csv"));
  std::vector<MbenchRow> rows;
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    MbenchRow r;
    r.series = t.rows[i][t.column("series")];
    r.side = t.rows[i][t.column("side")];
    r.y_ws = t.number(i, "y_ws_mm") * 1e-3;
    r.yaw = t.number(i, "yaw_ws_rad");
    r.roll = t.number(i, "roll_ws_rad");
    r.xcp = t.number(i, "xcp_tr_mm") * 1e-3;
    r.ycp_tr = t.number(i, "ycp_tr_mm") * 1e-3;
    r.r_roll = t.number(i, "r_roll_mm") * 1e-3;
    r.delta = t.number(i, "delta_cp_tr_rad");
    r.pen = t.number(i, "pen_mm") * 1e-3;
    r.FN = t.number(i, "FN_N");
    r.pmax = t.number(i, "pmax_MPa") * 1e6;
    r.area = t.number(i, "contact_area_mm2") * 1e-6;
    r.length = t.number(i, "patch_length_x_mm") * 1e-3;
    r.width = t.number(i, "patch_width_s_mm") * 1e-3;
    r.npatch = static_cast<int>(t.number(i, "npatch"));
    rows.push_back(r);
  }
  return rows;
}

// True when (series, side, y_ws) is listed for `what` in tests/data/contact_geometry/mbench_exclusions.csv.
inline bool excluded(const MbenchRow& r, const std::string& what) {
  static const std::vector<std::vector<std::string>> list = [] {
    std::vector<std::vector<std::string>> l;
    std::ifstream in(data_path("contact_geometry/mbench_exclusions.csv"));
    std::string line;
    while (std::getline(in, line)) {
      if (line.empty() || line[0] == '#') continue;
      std::vector<std::string> c;
      std::size_t a = 0;
      for (int k = 0; k < 4; ++k) {
        const auto b = line.find(',', a);
        c.push_back(line.substr(a, b - a));
        a = b + 1;
      }
      l.push_back(c);
    }
    return l;
  }();
  for (const auto& e : list)
    if ((e[0] == "*" || e[0] == r.series) && e[1] == r.side && std::abs(std::stod(e[2]) * 1e-3 - r.y_ws) < 1e-9 &&
        e[3] == what)
      return true;
  return false;
}

}  // namespace railsim::test
