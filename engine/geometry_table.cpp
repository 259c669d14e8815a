// 13-column contact-geometry table; see geometry_table.hpp.
#include "engine/geometry_table.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "core/errors.hpp"

namespace railsim::engine {

GeometryTable::GeometryTable(const std::string& path) : path_(path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open contact-geometry table");
  std::string line;
  int lineno = 0;
  std::vector<std::vector<double>> cols(12);
  bool header_seen = false;
  while (std::getline(in, line)) {
    ++lineno;
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos) continue;
    if (line[first] == '#') {
      if (!cols[0].empty()) break;  // a second block: further contact points (not used)
      continue;
    }
    if (line[first] == '"') {
      header_seen = true;
      continue;
    }
    std::istringstream ss(line);
    double v[13];
    int n = 0;
    while (n < 13 && ss >> v[n]) ++n;
    std::string rest;
    if (n != 13 || (ss >> rest))
      throw InputError(path + ":" + std::to_string(lineno) + ": expected 13 numbers per row");
    for (int k = 0; k < 12; ++k) {
      if (!std::isfinite(v[k])) throw InputError(path + ":" + std::to_string(lineno) + ": non-finite number");
      cols[k].push_back(v[k]);
    }
  }
  if (!header_seen) throw InputError(path + ": missing the header line of 13 quoted column names");
  rows_ = cols[0].size();
  if (rows_ < 5) throw InputError(path + ": fewer than 5 table rows");
  const double h = (cols[0].back() - cols[0].front()) / double(rows_ - 1);
  if (!(h > 0)) throw InputError(path + ": shift column must increase");
  for (std::size_t i = 1; i < rows_; ++i)
    if (std::abs(cols[0][i] - cols[0][i - 1] - h) > 0.05 * h)
      throw InputError(path + ": row " + std::to_string(i + 1) + ": shift grid is not uniform (step " +
                       std::to_string(cols[0][i] - cols[0][i - 1]) + ")");
  s_min_ = cols[0].front();
  s_max_ = std::min(-s_min_, cols[0].back());
  for (int k = 1; k < 12; ++k) col_.emplace_back(cols[k].begin(), cols[k].end(), s_min_, h);
  WheelContact w;
  evaluate(0.0, w);
  r0_ = w.rolling_radius;
  l0_ = w.lateral;
}

void GeometryTable::evaluate(double s, WheelContact& out) const {
  s = std::clamp(s, s_min_, s_max_);
  out = WheelContact{};
  out.N0 = col_[0](s);
  out.contact_angle = col_[1](s);
  out.semi_a = col_[2](s);
  out.semi_b = col_[3](s);
  out.lateral = col_[4](s);
  out.rolling_radius = col_[5](s);
  out.C11 = col_[6](s);
  out.C22 = col_[7](s);
  out.C23 = col_[8](s);
  out.q0 = col_[10](s);
}

std::string GeometryTable::describe() const {
  return "table " + path_ + " (" + std::to_string(rows_) + " rows, shift " + std::to_string(s_min_ * 1e3) +
         " .. " + std::to_string(s_max_ * 1e3) + " mm)";
}

}  // namespace railsim::engine
