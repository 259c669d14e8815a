// Profile reading and validation (see profile.hpp for the coordinate conventions).
#include "contact/geometry/profile.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/content_hash.hpp"
#include "core/data_dir.hpp"
#include "core/errors.hpp"
#include "core/input_file.hpp"

namespace railsim::contact {

namespace {

// Largest plausible lateral extent of a profile [m] (a rail head is about
// 70 mm, a wheel 130-150 mm wide; below 10 mm the profile is refused as too
// short).
constexpr double kMaxProfileWidth = 0.5;

[[noreturn]] void fail(const std::string& where, const std::string& what) { throw InputError(where + ": " + what); }

std::string where_line(const std::string& source, const std::vector<int>& lines, std::size_t i) {
  if (i < lines.size() && lines[i] > 0) return source + ":" + std::to_string(lines[i]);
  return source + " (point " + std::to_string(i + 1) + ")";
}

std::string fmt_mm(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g mm", v * 1e3);
  return buf;
}

// Proper crossing of segments p1p2 and p3p4 (shared end points do not count).
bool segments_cross(double y1, double z1, double y2, double z2, double y3, double z3, double y4, double z4) {
  auto orient = [](double ay, double az, double by, double bz, double cy, double cz) {
    return (by - ay) * (cz - az) - (bz - az) * (cy - ay);
  };
  const double d1 = orient(y3, z3, y4, z4, y1, z1);
  const double d2 = orient(y3, z3, y4, z4, y2, z2);
  const double d3 = orient(y1, z1, y2, z2, y3, z3);
  const double d4 = orient(y1, z1, y2, z2, y4, z4);
  return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

std::string lower(std::string s) {
  for (auto& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// Parse up to 3 numbers from a line split at blanks/commas/semicolons/tabs.
std::vector<double> numbers_of(const std::string& line, bool& ok) {
  std::string s = line;
  for (auto& c : s)
    if (c == ',' || c == ';' || c == '\t') c = ' ';
  std::istringstream is(s);
  std::vector<double> v;
  std::string tok;
  ok = true;
  while (is >> tok) {
    char* end = nullptr;
    const double x = std::strtod(tok.c_str(), &end);
    if (end == tok.c_str() || *end != '\0' || !std::isfinite(x)) {
      ok = false;
      return v;
    }
    v.push_back(x);
  }
  return v;
}

struct RawProfile {
  std::vector<double> y, z;
  std::vector<int> lines;
  double unit = 0.0;  // metres per file unit, 0 = unknown
  std::string unit_from;  // where the unit was declared (for messages)
  bool mirror_y = false, mirror_z = false;
};

RawProfile read_simpack(const std::string& path, std::istream& in) {
  RawProfile raw;
  std::string line;
  int lineno = 0;
  bool in_points = false;
  while (std::getline(in, line)) {
    ++lineno;
    const auto bang = line.find('!');
    std::string s = trim(bang == std::string::npos ? line : line.substr(0, bang));
    if (s.empty()) continue;
    if (s == "point.begin") {
      in_points = true;
      continue;
    }
    if (s == "point.end") {
      in_points = false;
      continue;
    }
    if (in_points) {
      bool ok = false;
      const auto v = numbers_of(s, ok);
      if (!ok || v.size() < 2 || v.size() > 3)
        fail(path + ":" + std::to_string(lineno), "expected 'y z [weight]' numbers in the point list, got '" + s + "'");
      raw.y.push_back(v[0]);
      raw.z.push_back(v[1]);
      raw.lines.push_back(lineno);
      continue;
    }
    const auto eq = s.find('=');
    if (eq == std::string::npos) continue;
    const std::string key = trim(s.substr(0, eq));
    const std::string val = trim(s.substr(eq + 1));
    if (key == "units.len.f") {
      const double f = std::strtod(val.c_str(), nullptr);
      if (!(f > 0.0) || !std::isfinite(f))
        fail(path + ":" + std::to_string(lineno), "key 'units.len.f': expected a positive number (got '" + val + "')");
      raw.unit = 1.0 / f;
      raw.unit_from = "key 'units.len.f' on line " + std::to_string(lineno);
    } else if (key == "mirror.y" || key == "mirror.z") {
      if (val != "0" && val != "1")
        fail(path + ":" + std::to_string(lineno), "key '" + key + "': expected 0 (no mirroring) or 1 (got '" + val + "')");
      (key == "mirror.y" ? raw.mirror_y : raw.mirror_z) = val == "1";
    } else if (key == "shift.y" || key == "shift.z" || key == "rotate") {
      // SIMPACK's processing steps 2 and 3; railsim applies only the mirroring
      // and the unit: a non-zero value would be ignored silently.
      char* end = nullptr;
      const double v = std::strtod(val.c_str(), &end);
      if (end == val.c_str() || v != 0.0)
        fail(path + ":" + std::to_string(lineno), "key '" + key + "' = " + val +
                                                      ": railsim does not apply SIMPACK's shift and rotation (only "
                                                      "mirror.y, mirror.z and units.len.f); apply it to the points or "
                                                      "set it to 0");
    }
  }
  if (raw.unit == 0.0) {
    raw.unit = 1e-3;  // SIMPACK default length unit: mm (CONTACT's too)
    raw.unit_from = "the SIMPACK default (no key 'units.len.f')";
  }
  return raw;
}

RawProfile read_columns(const std::string& path, std::istream& in) {
  RawProfile raw;
  std::string line;
  int lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    std::string s = trim(line);
    if (s.empty()) continue;
    if (s[0] == '#' || s[0] == '%' || s[0] == '!') {
      const std::string l = lower(s);
      if (l.find("units") != std::string::npos) {
        if (l.find("mm") != std::string::npos) raw.unit = 1e-3;
        else if (l.find(" m") != std::string::npos || ends_with(l, ":m")) raw.unit = 1.0;
        raw.unit_from = "the 'units' line " + std::to_string(lineno);
      }
      continue;
    }
    bool ok = false;
    const auto v = numbers_of(s, ok);
    if (!ok) {
      if (raw.y.empty()) {  // header line: look for units in the column names
        const std::string l = lower(s);
        if (l.find("_mm") != std::string::npos || l.find("[mm]") != std::string::npos ||
            l.find("(mm)") != std::string::npos)
          raw.unit = 1e-3;
        else if (l.find("_m") != std::string::npos || l.find("[m]") != std::string::npos ||
                 l.find("(m)") != std::string::npos)
          raw.unit = 1.0;
        raw.unit_from = "the column names on line " + std::to_string(lineno);
        continue;
      }
      fail(path + ":" + std::to_string(lineno), "expected two numbers 'y, z', got '" + s + "'");
    }
    if (v.size() != 2) fail(path + ":" + std::to_string(lineno), "expected two numbers 'y, z', got '" + s + "'");
    raw.y.push_back(v[0]);
    raw.z.push_back(v[1]);
    raw.lines.push_back(lineno);
  }
  return raw;
}

const char* kind_name(ProfileKind k) { return k == ProfileKind::wheel ? "wheel" : "rail"; }

}  // namespace

Profile::Profile(ProfileKind kind, std::string source, std::vector<double> y, std::vector<double> z,
                 std::vector<int> lines)
    : kind_(kind), source_(std::move(source)), y_(std::move(y)), z_(std::move(z)) {
  const std::size_t n = y_.size();
  if (z_.size() != n) fail(source_, "y and z point counts differ");
  if (!lines.empty() && lines.size() != n) lines.clear();
  constexpr std::size_t kMinPoints = 10;
  constexpr double kMinWidth = 0.010;  // [m]
  if (n < kMinPoints)
    fail(source_, std::string("too short ") + kind_name(kind_) + " profile: " + std::to_string(n) +
                      " points, at least " + std::to_string(kMinPoints) + " required");
  const double width = *std::max_element(y_.begin(), y_.end()) - *std::min_element(y_.begin(), y_.end());
  if (width < kMinWidth)
    fail(source_, std::string("too short ") + kind_name(kind_) + " profile: lateral extent " + fmt_mm(width) +
                      ", at least 10 mm required");
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(y_[i]) || !std::isfinite(z_[i])) fail(where_line(source_, lines, i), "non-finite coordinate");
  // Duplicated points (consecutive points closer than 1 nm).
  for (std::size_t i = 1; i < n; ++i)
    if (std::hypot(y_[i] - y_[i - 1], z_[i] - z_[i - 1]) < 1e-9)
      fail(where_line(source_, lines, i), "duplicated profile point (same as the previous point, " +
                                              fmt_mm(y_[i]) + ", " + fmt_mm(z_[i]) + ")");
  // Self-intersection: any two non-adjacent segments crossing. Segment j
  // can meet segment i only while some later point lies at or left of
  // segment i's right end: the suffix minimum of y ends the search (linear
  // for a profile sorted in y; it was quadratic, 34 s for 320,000 points).
  std::vector<double> y_min_from(n);
  for (std::size_t k = n; k-- > 0;) y_min_from[k] = k + 1 < n ? std::min(y_[k], y_min_from[k + 1]) : y_[k];
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const double ymin_i = std::min(y_[i], y_[i + 1]), ymax_i = std::max(y_[i], y_[i + 1]);
    for (std::size_t j = i + 2; j + 1 < n; ++j) {
      if (y_min_from[j] > ymax_i) break;  // every later segment lies right of segment i
      if (std::max(y_[j], y_[j + 1]) < ymin_i || std::min(y_[j], y_[j + 1]) > ymax_i) continue;
      if (segments_cross(y_[i], z_[i], y_[i + 1], z_[i + 1], y_[j], z_[j], y_[j + 1], z_[j + 1]))
        fail(where_line(source_, lines, j),
             "self-intersecting profile: the segment starting here crosses the segment starting at " +
                 where_line(source_, lines, i));
    }
  }
  // Sorted: y non-decreasing along the profile (vertical parts allowed).
  constexpr double kBackTol = 1e-7;  // [m]
  for (std::size_t i = 1; i < n; ++i)
    if (y_[i] < y_[i - 1] - kBackTol)
      fail(where_line(source_, lines, i), "profile points are not sorted: y goes back from " + fmt_mm(y_[i - 1]) +
                                              " to " + fmt_mm(y_[i]) +
                                              " (lateral coordinates must increase along the profile)");
  spline_ = ParametricSpline(y_, z_);
}

Profile Profile::rotated(double angle, const std::string& new_source) const {
  std::vector<double> y(y_.size()), z(z_.size());
  const double c = std::cos(angle), s = std::sin(angle);
  for (std::size_t i = 0; i < y_.size(); ++i) {
    y[i] = y_[i] * c + z_[i] * s;
    z[i] = -y_[i] * s + z_[i] * c;
  }
  // A rotation can make an almost vertical side step back in y: keep only the
  // part visible from above (drop leading/trailing points that go backwards).
  std::size_t b = 0, e = y.size();
  while (b + 1 < e && y[b + 1] < y[b]) ++b;
  while (e - 1 > b && y[e - 1] < y[e - 2]) --e;
  return Profile(kind_, new_source.empty() ? source_ + " (rotated)" : new_source, std::vector<double>(y.begin() + static_cast<long>(b), y.begin() + static_cast<long>(e)),
                 std::vector<double>(z.begin() + static_cast<long>(b), z.begin() + static_cast<long>(e)));
}

unsigned long long Profile::content_hash() const {
  ContentHash h;
  h.value(kind_ == ProfileKind::wheel ? 1 : 0);
  h.bytes(y_.data(), y_.size() * sizeof(double));
  h.bytes(z_.data(), z_.size() * sizeof(double));
  return h.value();
}

std::string shipped_profile_dir() {
  if (const char* env = std::getenv("RAILSIM_PROFILE_DIR"); env && *env) return env;
  return railsim::data_path("profiles");
}

std::string profile_width_warning(const Profile& p) {
  if (p.y().empty()) return {};
  const double width = p.y().back() - p.y().front();  // points ordered by increasing y
  const bool wheel = p.kind() == ProfileKind::wheel;
  const double lo = wheel ? kUsualWheelWidthMin : kUsualRailWidthMin;
  if (width >= lo && width <= kUsualProfileWidthMax) return {};
  char buf[256];
  std::snprintf(buf, sizeof buf, "%s profile %.1f mm wide: legal but implausible (usual %g-%g mm for a %s)",
                kind_name(p.kind()), width * 1e3, lo * 1e3, kUsualProfileWidthMax * 1e3, wheel ? "wheel" : "rail");
  return p.source() + ": " + buf;
}

std::string shipped_profile_names() {
  return "S1002 (wheel), UIC60 (rail, upright), UIC60_MBench (rail, canted 1/40), UIC60_true (rail, upright, CONTACT testbank)";
}

bool is_shipped_profile_name(const std::string& name) {
  const std::string l = lower(name);
  return l == "s1002" || l == "uic60" || l == "uic60_mbench" || l == "uic60_true";
}

Profile read_profile(const std::string& path_or_name, ProfileKind kind, const ProfileReadOptions& options) {
  // 0 means "from the file"; otherwise metres per file unit, from a micrometre to a metre.
  if (!(options.unit == 0.0 || (std::isfinite(options.unit) && options.unit >= 1e-6 && options.unit <= 1.0))) {
    char given[32];
    std::snprintf(given, sizeof given, "%g", options.unit);
    fail(path_or_name, std::string("unit option = ") + given +
                           ": expected 0 (the unit from the file) or metres per file unit in [1e-6, 1] "
                           "(1e-3 for mm, 1 for m)");
  }
  std::string path = path_or_name;
  const std::string lname = lower(path_or_name);
  if (lname == "s1002") path = shipped_profile_dir() + "/MBench_S1002_v3.prw";
  else if (lname == "uic60" || lname == "uic60_mbench") path = shipped_profile_dir() + "/MBench_UIC60_v3.prr";
  else if (lname == "uic60_true") path = shipped_profile_dir() + "/uic60_true.prr";
  if (lname == "s1002" && kind != ProfileKind::wheel) fail(path_or_name, "S1002 is a wheel profile, not a rail profile");
  if ((lname == "uic60" || lname == "uic60_mbench" || lname == "uic60_true") && kind != ProfileKind::rail)
    fail(path_or_name, "UIC60 is a rail profile, not a wheel profile");

  std::error_code ec;
  if (std::filesystem::exists(path, ec)) check_input_file(path, std::string(kind_name(kind)) + " profile");
  std::ifstream in(path);
  if (!in)
    fail(path, std::string("cannot open ") + kind_name(kind) + " profile (give a file or one of the names: " +
                   shipped_profile_names() + ")");
  const std::string ext = lower(path.size() >= 4 ? path.substr(path.size() - 4) : path);
  // SIMPACK's extensions say the kind: a rail (.prr) read as the wheel gave a
  // wheel without a flange and a message about flange climbing.
  if ((ext == ".prr" && kind == ProfileKind::wheel) || (ext == ".prw" && kind == ProfileKind::rail))
    fail(path, std::string("a SIMPACK ") + (ext == ".prr" ? "rail" : "wheel") + " profile (" + ext +
                   ") given as the " + kind_name(kind) + " profile");
  RawProfile raw = (ext == ".prw" || ext == ".prr") ? read_simpack(path, in) : read_columns(path, in);
  if (options.unit > 0.0) {
    raw.unit = options.unit;
    raw.unit_from = "the unit option";
  }
  // No points first: an empty file was refused for its unknown length unit.
  if (raw.y.empty()) fail(path, std::string("no profile points found in the ") + kind_name(kind) + " profile");
  if (raw.unit == 0.0)
    fail(path, "length unit unknown: name the columns y_mm,z_mm or y_m,z_m, add a '# units: mm' line, or give the unit option");
  if (options.z_up) raw.mirror_z = !raw.mirror_z;
  if (options.mirror_y) raw.mirror_y = !raw.mirror_y;
  for (std::size_t i = 0; i < raw.y.size(); ++i) {
    raw.y[i] *= raw.unit * (raw.mirror_y ? -1.0 : 1.0);
    raw.z[i] *= raw.unit * (raw.mirror_z ? -1.0 : 1.0);
  }
  {
    // A profile in millimetres declared as metres (or the reverse) is 1000
    // times too wide (narrow): refuse it naming the declared unit.
    const auto [ymin, ymax] = std::minmax_element(raw.y.begin(), raw.y.end());
    const double width = *ymax - *ymin;
    if (std::isfinite(width) && width > kMaxProfileWidth) {
      char buf[128];
      std::snprintf(buf, sizeof buf, "lateral extent %.6g mm, more than the plausible %g mm", width * 1e3,
                    kMaxProfileWidth * 1e3);
      fail(path, std::string(buf) + " of a " + kind_name(kind) + " profile with the length unit " +
                     (raw.unit == 1.0 ? std::string("m") : raw.unit == 1e-3 ? std::string("mm")
                                                                             : std::to_string(raw.unit) + " m") +
                     " from " + (raw.unit_from.empty() ? std::string("the file") : raw.unit_from) +
                     ": are the numbers in another unit?");
    }
  }
  // z points down (toward the rail): a wheel's flange tip is its largest z,
  // inside the profile. A file with z up shows the flange as an interior
  // minimum 10 mm or more above both ends while the largest z is an end:
  // refused (it was read as a wheel without a flange, conicity 0.018).
  if (kind == ProfileKind::wheel) {
    const auto [zmin, zmax] = std::minmax_element(raw.z.begin(), raw.z.end());
    const double z0 = raw.z.front(), z1 = raw.z.back();
    const bool max_at_end = zmax == raw.z.begin() || zmax == raw.z.end() - 1;
    if (max_at_end && *zmin < std::min(z0, z1) - 0.010)
      fail(path, "the wheel profile's flange points up: z has an interior minimum " + fmt_mm(std::min(z0, z1) - *zmin) +
                     " beyond both ends and its largest value at an end; railsim's z points down, toward the "
                     "rail (negate z in the file, or read it with z up)");
  }
  // A wheel's flange (largest z) must lie at negative y (field side positive).
  if (kind == ProfileKind::wheel) {
    const auto imax = static_cast<std::size_t>(std::max_element(raw.z.begin(), raw.z.end()) - raw.z.begin());
    const double ymid = 0.5 * (*std::min_element(raw.y.begin(), raw.y.end()) + *std::max_element(raw.y.begin(), raw.y.end()));
    if (raw.y[imax] > ymid)
      for (auto& v : raw.y) v = -v;
  }
  // Order by increasing y.
  if (raw.y.size() >= 2 && raw.y.front() > raw.y.back()) {
    std::reverse(raw.y.begin(), raw.y.end());
    std::reverse(raw.z.begin(), raw.z.end());
    std::reverse(raw.lines.begin(), raw.lines.end());
  }
  Profile p(kind, path, std::move(raw.y), std::move(raw.z), std::move(raw.lines));
  // "UIC60": the Manchester-benchmark UIC60 (canted 1/40 in its file) turned
  // upright, so that --inclination 1/40 reproduces the benchmark set-up exactly.
  if (lname == "uic60") return p.rotated(-std::atan(1.0 / 40.0), "UIC60 (MBench_UIC60_v3.prr turned upright by -1/40)");
  return p;
}

}  // namespace railsim::contact
