// 13-column contact-geometry table; see geometry_table.hpp.
#include "engine/wheel_rail/geometry_table.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "config/yaml_input.hpp"
#include "core/errors.hpp"
#include "core/input_file.hpp"

namespace railsim::engine {

namespace {

// The 12 read columns, as the file format names them (geometry_table.hpp).
const char* const kColumnNames[12] = {"shift",      "N0",  "delta", "a",   "b",   "a_w",
                                      "r_w", "C11", "C22",   "C23", "z_c", "q0"};

// Physical ranges of one row: a wrong unit or sign would otherwise load and
// give valid-looking forces (a negative C11 turns creep forces around).
void check_row(const std::string& path, int lineno, const double* v) {
  struct Range {
    int col;
    double lo, hi;
    bool lo_open;
    const char* unit;
  };
  static const Range ranges[] = {
      {0, -0.1, 0.1, false, "m"},        // shift
      {1, 0.0, 1e7, true, "N"},          // reference normal force
      {2, -1.5, 1.5, false, "rad"},      // contact angle
      {3, 0.0, 0.1, true, "m"},          // semi-axis a
      {4, 0.0, 0.1, true, "m"},          // semi-axis b
      {5, 0.0, 1.5, true, "m"},          // lateral position of the contact point
      {6, 0.1, 1.5, false, "m"},         // rolling radius
      {7, 0.0, 100.0, true, "-"},        // Kalker C11
      {8, 0.0, 100.0, true, "-"},        // Kalker C22
      {9, 0.0, 100.0, false, "-"},       // Kalker C23
  };
  for (const Range& r : ranges) {
    const double x = v[r.col];
    if ((r.lo_open ? x > r.lo : x >= r.lo) && x <= r.hi) continue;
    char buf[256];
    std::snprintf(buf, sizeof buf, ": column %d (%s [%s]): expected a number in %s%g, %g] (got %g)", r.col + 1,
                  kColumnNames[r.col], r.unit, r.lo_open ? "(" : "[", r.lo, r.hi, x);
    throw InputError(path + ":" + std::to_string(lineno) + buf);
  }
}

}  // namespace

GeometryTable::GeometryTable(const std::string& path, const GeometryTableOptions& options)
    : path_(path), options_(options) {
  check_input_file(path, "contact-geometry table");
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open contact-geometry table");
  std::string line;
  int lineno = 0, block_line = 0;
  std::vector<std::vector<double>> cols(12);
  std::vector<int> row_line;  // file line of each row of the block (messages)
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
        throw InputError(path + ":" + std::to_string(row_line[i]) + ": row " + std::to_string(i + 1) +
                         " of the block (starting on line " + std::to_string(block_line) + "): shift " +
                         config::format_number(cols[0][i]) + " after " + config::format_number(cols[0][i - 1]) +
                         ": the shift grid is not uniform (rows must be sorted by shift with a constant step, here " +
                         config::format_number(h) + ")");
    std::vector<double> raw(n * kCols);
    for (std::size_t i = 0; i < n; ++i)
      for (int k = 0; k < kCols; ++k) raw[i * kCols + std::size_t(k)] = cols[std::size_t(k + 1)][i];
    Block b;
    b.s_min = cols[0].front();
    b.s_max = cols[0].back();
    if (options_.smoothing > 0.0) {
      const double node = std::max(options_.node_step, h), half = std::max(options_.smoothing, h);
      b.fit = contact::SmoothColumns::fit_noisy(raw, n, kCols, b.s_min, h, node, half);
    } else {
      b.fit = contact::SmoothColumns::interpolate(raw, n, kCols, b.s_min, h);
    }
    if (blocks_.empty()) {
      rows_ = n;
      raw_step_ = h;
    }
    blocks_.push_back(std::move(b));
    for (auto& c : cols) c.clear();
    row_line.clear();
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
      if (!std::isfinite(v[k]))
        throw InputError(path + ":" + std::to_string(lineno) + ": column " + std::to_string(k + 1) + " (" +
                         kColumnNames[k] + "): expected a finite number");
      cols[std::size_t(k)].push_back(v[k]);
    }
    row_line.push_back(lineno);
    check_row(path, lineno, v);
  }
  finish_block();
  if (blocks_.empty()) throw InputError(path + ": no table rows");
  s_min_ = blocks_.front().s_min;
  s_max_ = std::min(-s_min_, blocks_.front().s_max);
  if (!(s_max_ > 0.0))
    throw InputError(path + ": the first block must cover shifts on both sides of zero (the table is used "
                     "symmetrically for the two wheels)");
  const ContactPointGeometry c = main_point(0.0);
  r0_ = c.rolling_radius;
  l0_ = c.lateral;
}

void GeometryTable::evaluate(double s, double yaw, WheelGeometry& out) const {
  (void)yaw;  // the table does not depend on yaw
  out.n = 0;
  double v[kCols];
  for (std::size_t k = 0; k < blocks_.size(); ++k) {
    const Block& b = blocks_[k];
    if (k > 0 && (s < b.s_min || s > b.s_max)) continue;  // this point does not exist at this shift (no load)
    b.fit.eval(std::clamp(s, b.s_min, b.s_max), v);
    ContactPointGeometry& p = out.p[out.n++];
    p = ContactPointGeometry{};
    p.N0 = v[kN0];
    p.contact_angle = v[kDelta];
    p.semi_a = v[kSemiA];
    p.semi_b = v[kSemiB];
    p.lateral = v[kLateral];
    p.rolling_radius = v[kRadius];
    p.C11 = v[kC11];
    p.C22 = v[kC22];
    p.C23 = v[kC23];
    p.q0 = v[kQ0];
    if (out.n == WheelGeometry::kMaxPoints) break;
  }
}

bool GeometryTable::rigid_pose(double y, double yaw, RigidPose& out) const {
  (void)yaw;
  const Block& b = blocks_.front();
  double L[kCols], dL[kCols], R[kCols], dR[kCols];
  b.fit.eval(std::clamp(y, b.s_min, b.s_max), L, dL);
  b.fit.eval(std::clamp(-y, b.s_min, b.s_max), R, dR);
  const double num = L[kRadius] - R[kRadius], den = L[kLateral] + R[kLateral];
  const double dnum = dL[kRadius] + dR[kRadius], dden = dL[kLateral] - dR[kLateral];  // d/dy (right wheel at -y)
  out = RigidPose{};
  out.roll = num / den;
  out.droll_dy = dnum / den - num * dden / (den * den);
  return true;
}

std::string GeometryTable::deviation_report() const {
  static const char* names[kCols] = {"N0", "contact angle", "a", "b", "lateral position", "rolling radius",
                                     "C11", "C22", "C23", "z_c", "q0"};
  std::string s;
  const auto& d = blocks_.front().fit.deviation();
  for (int k = 0; k < kCols && k < int(d.size()); ++k) {
    char buf[128];
    std::snprintf(buf, sizeof buf, "%s%s %.3g at %.3f mm", s.empty() ? "" : "; ", names[k], d[std::size_t(k)].max_abs,
                  d[std::size_t(k)].at * 1e3);
    s += buf;
  }
  return s;
}

std::string GeometryTable::describe() const {
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "table %s (%d contact point(s), %zu rows at %.3g mm, shift %.2f .. %.2f mm; smoothed: local quadratic "
                "half-width %.3g mm, nodes every %.3g mm)",
                path_.c_str(), blocks(), rows_, raw_step_ * 1e3, s_min_ * 1e3, s_max_ * 1e3,
                options_.smoothing * 1e3, std::max(options_.node_step, raw_step_) * 1e3);
  return buf;
}

}  // namespace railsim::engine
