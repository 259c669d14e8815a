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
  int lineno = 0, block_line = 0;
  std::vector<std::vector<double>> cols(12);
  bool header_seen = false;
  auto finish_block = [&]() {
    const std::size_t n = cols[0].size();
    if (n == 0) return;
    const std::string where = path + ":" + std::to_string(block_line);
    if (!header_seen) throw InputError(where + ": missing the header line of 13 quoted column names");
    if (n < 5) throw InputError(where + ": fewer than 5 table rows in this block");
    const double h = (cols[0].back() - cols[0].front()) / double(n - 1);
    if (!(h > 0)) throw InputError(where + ": shift column must increase");
    for (std::size_t i = 1; i < n; ++i)
      if (std::abs(cols[0][i] - cols[0][i - 1] - h) > 0.05 * h)
        throw InputError(where + ": row " + std::to_string(i + 1) + " of the block: shift grid is not uniform");
    Block b;
    b.s_min = cols[0].front();
    b.s_max = cols[0].back();
    for (int k = 1; k < 12; ++k) b.col.emplace_back(cols[k].begin(), cols[k].end(), b.s_min, h);
    if (blocks_.empty()) rows_ = n;
    blocks_.push_back(std::move(b));
    for (auto& c : cols) c.clear();
    header_seen = false;
  };
  while (std::getline(in, line)) {
    ++lineno;
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos) continue;
    if (line[first] == '#') {
      finish_block();
      block_line = lineno;
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
  finish_block();
  if (blocks_.empty()) throw InputError(path + ": no table rows");
  s_min_ = blocks_.front().s_min;
  s_max_ = std::min(-s_min_, blocks_.front().s_max);
  WheelContact w;
  evaluate(0.0, w);
  r0_ = w.rolling_radius;
  l0_ = w.lateral;
}

void GeometryTable::evaluate_point(double s, int k, WheelContact& out) const {
  const Block& b = blocks_[static_cast<std::size_t>(k)];
  out = WheelContact{};
  if (k == 0) s = std::clamp(s, b.s_min, b.s_max);
  else if (s < b.s_min || s > b.s_max) return;  // this point does not exist at this shift (no load)
  out.N0 = b.col[0](s);
  out.contact_angle = b.col[1](s);
  out.semi_a = b.col[2](s);
  out.semi_b = b.col[3](s);
  out.lateral = b.col[4](s);
  out.rolling_radius = b.col[5](s);
  out.C11 = b.col[6](s);
  out.C22 = b.col[7](s);
  out.C23 = b.col[8](s);
  out.q0 = b.col[10](s);
}

std::string GeometryTable::describe() const {
  return "table " + path_ + " (" + std::to_string(blocks_.size()) + " contact point(s), " + std::to_string(rows_) + " rows, shift " + std::to_string(s_min_ * 1e3) +
         " .. " + std::to_string(s_max_ * 1e3) + " mm)";
}

}  // namespace railsim::engine
