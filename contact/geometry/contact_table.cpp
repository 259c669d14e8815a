// Contact table build, cache and lookup (see contact_table.hpp).
#include "contact/geometry/contact_table.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

#include "core/atomic_file.hpp"
#include "core/cache_dir.hpp"
#include "core/content_hash.hpp"
#include "core/errors.hpp"

namespace railsim::contact {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr char kMagic[8] = {'R', 'S', 'C', 'T', 'A', 'B', '0', '2'};  // bump when the search changes

std::string num(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

}  // namespace

void TableGrid::validate() const {
  if (!(std::isfinite(y_min) && std::isfinite(y_max) && y_min >= -0.05 && y_max <= 0.05 && y_min < y_max))
    throw InputError("contact table: y range [" + num(y_min) + ", " + num(y_max) +
                     "] m: expected -0.05 <= y_min < y_max <= 0.05 m");
  if (!(std::isfinite(y_step) && y_step >= 1e-6 && y_step <= (y_max - y_min)))
    throw InputError("contact table: y step " + num(y_step) + " m: expected a value in [1e-6, y_max - y_min] m");
  if ((y_max - y_min) / y_step > 1e6) throw InputError("contact table: more than 1e6 rows requested");
}

std::vector<std::string> ContactTable::column_names() {
  std::vector<std::string> c = {"y", "roll", "z"};
  const char* fields[kPointFields] = {"n", "y", "y_wheel", "y_rail", "radius", "angle", "A", "B", "gap"};
  for (const char* side : {"left", "right"})
    for (int s = 0; s < kSlots; ++s)
      for (const char* f : fields) c.push_back(std::string(side) + (s == 0 ? "" : "2") + "_" + f);
  return c;
}

void ContactTable::fill(std::size_t row, const WheelsetContact& c) {
  double* d = &data_[row * kColumns];
  d[0] = c.y;
  d[1] = c.roll;
  d[2] = 0.5 * (c.z[0] + c.z[1]);
  int col = 3;
  for (int side = 0; side < 2; ++side) {
    const WheelContact& wc = c.wheel[static_cast<std::size_t>(side)];
    for (int s = 0; s < kSlots; ++s) {
      if (s < wc.n) {
        const ContactPoint& p = wc.p[static_cast<std::size_t>(s)];
        const double v[kPointFields] = {s == 0 ? static_cast<double>(wc.n) : 1.0, p.y, p.y_wheel, p.y_rail, p.radius,
                                        p.angle, p.A, p.B, p.gap};
        for (double x : v) d[col++] = x;
      } else {
        d[col++] = 0.0;
        for (int k = 1; k < kPointFields; ++k) d[col++] = kNaN;
      }
    }
  }
}

ContactTable ContactTable::build(const WheelRailGeometry& geometry, const TableGrid& grid) {
  grid.validate();
  ContactTable t;
  t.grid_ = grid;
  t.rows_ = static_cast<std::size_t>(std::floor((grid.y_max - grid.y_min) / grid.y_step + 1e-9)) + 1;
  t.data_.assign(t.rows_ * kColumns, 0.0);
  for (std::size_t i = 0; i < t.rows_; ++i) {
    const double y = grid.y_min + static_cast<double>(i) * grid.y_step;
    t.fill(i, geometry.solve(y, 0.0));
  }
  return t;
}

std::string ContactTable::default_cache_dir() { return resolve_cache_dir(); }

unsigned long long ContactTable::cache_key(const WheelRailGeometry& geometry, const Profile& wheel,
                                           const Profile& rail, const TableGrid& grid) {
  ContentHash f = geometry_cache_hash(kMagic, sizeof kMagic, wheel, rail, geometry);
  const SearchOptions& o = geometry.options();
  for (double v : {grid.y_min, grid.y_max, grid.y_step, o.second_gap_max, o.wheel_step, o.rail_step, o.flange_margin})
    f.value(v);
  return f.value();
}

ContactTable ContactTable::cached(const WheelRailGeometry& geometry, const Profile& wheel, const Profile& rail,
                                  const TableGrid& grid, const std::string& cache_dir, bool* loaded_from_cache) {
  grid.validate();
  if (loaded_from_cache) *loaded_from_cache = false;
  const std::string dir = cache_dir.empty() ? default_cache_dir() : cache_dir;
  const unsigned long long key = cache_key(geometry, wheel, rail, grid);
  char name[64];
  std::snprintf(name, sizeof name, "contact_table_%016llx.bin", key);
  const std::string path = dir + "/" + name;
  {
    std::ifstream in(path, std::ios::binary);
    if (in) {
      char magic[8];
      unsigned long long k = 0, rows = 0, cols = 0;
      in.read(magic, 8);
      in.read(reinterpret_cast<char*>(&k), sizeof k);
      in.read(reinterpret_cast<char*>(&rows), sizeof rows);
      in.read(reinterpret_cast<char*>(&cols), sizeof cols);
      if (in && std::memcmp(magic, kMagic, 8) == 0 && k == key && cols == kColumns && rows > 0 && rows < 2000000) {
        ContactTable t;
        t.grid_ = grid;
        t.rows_ = rows;
        t.data_.resize(rows * cols);
        in.read(reinterpret_cast<char*>(t.data_.data()), static_cast<std::streamsize>(t.data_.size() * sizeof(double)));
        if (in && in.peek() == std::char_traits<char>::eof()) {
          if (loaded_from_cache) *loaded_from_cache = true;
          return t;
        }
      }
    }
  }
  ContactTable t = build(geometry, grid);
  // The cache is an optimisation: a folder or file that cannot be written
  // leaves the table computed, not an error.
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  try {
    write_file_atomically(path, [&](std::ostream& out) {
      const unsigned long long rows = t.rows_, cols = kColumns;
      out.write(kMagic, 8);
      out.write(reinterpret_cast<const char*>(&key), sizeof key);
      out.write(reinterpret_cast<const char*>(&rows), sizeof rows);
      out.write(reinterpret_cast<const char*>(&cols), sizeof cols);
      out.write(reinterpret_cast<const char*>(t.data_.data()),
                static_cast<std::streamsize>(t.data_.size() * sizeof(double)));
    });
  } catch (const InputError&) {
  }
  return t;
}

void ContactTable::unpack(const double* a, const double* b, double w, TableSample& out) const {
  auto lerp = [w](double x, double y) { return x + w * (y - x); };
  out.roll = lerp(a[1], b[1]);
  out.z = lerp(a[2], b[2]);
  // A point of row a and one of row b are the same point when they lie within
  // 1 mm of each other on the wheel, whatever their slots (the slots swap where
  // the second point becomes the touching one).
  auto same = [](const double* pa, const double* pb) { return std::abs(pa[2] - pb[2]) < 1e-3; };
  for (std::size_t side = 0; side < 2; ++side) {
    const int base = 3 + static_cast<int>(side) * kSlots * kPointFields;
    WheelContact& wc = out.wheel[side];
    wc.n = 0;
    bool used_b[kSlots] = {};
    auto add = [&](const double* pa, const double* pb) {
      if (wc.n == WheelContact::kMaxPoints) return;
      ContactPoint& p = wc.p[static_cast<std::size_t>(wc.n++)];
      if (pa && pb) {
        p.y = lerp(pa[1], pb[1]);
        p.y_wheel = lerp(pa[2], pb[2]);
        p.y_rail = lerp(pa[3], pb[3]);
        p.radius = lerp(pa[4], pb[4]);
        p.angle = lerp(pa[5], pb[5]);
        p.A = lerp(pa[6], pb[6]);
        p.B = lerp(pa[7], pb[7]);
        p.gap = lerp(pa[8], pb[8]);
      } else {  // present in one row only: that row's point, moved with the wheelset
        const double* src = pa ? pa : pb;
        p.y = src[1] + (out.y - (pa ? a[0] : b[0]));
        p.y_wheel = src[2];
        p.y_rail = src[3];
        p.radius = src[4];
        p.angle = src[5];
        p.A = src[6];
        p.B = src[7];
        p.gap = src[8];
      }
      p.x = 0.0;
      p.z = 0.0;
    };
    for (int s = 0; s < kSlots; ++s) {
      const double* pa = a + base + s * kPointFields;
      if (!(pa[0] > 0.0)) continue;
      const double* match = nullptr;
      for (int t = 0; t < kSlots && !match; ++t) {
        const double* pb = b + base + t * kPointFields;
        if (!used_b[t] && pb[0] > 0.0 && same(pa, pb)) {
          match = pb;
          used_b[t] = true;
        }
      }
      if (match) add(pa, match);
      else if (w < 0.5) add(pa, nullptr);  // across a jump: the nearest row
    }
    if (w >= 0.5)
      for (int t = 0; t < kSlots; ++t) {
        const double* pb = b + base + t * kPointFields;
        if (!used_b[t] && pb[0] > 0.0) add(nullptr, pb);
      }
    // Touching point first: order by vertical gap (the search's order).
    std::sort(wc.p.begin(), wc.p.begin() + wc.n, [](const ContactPoint& l, const ContactPoint& r) {
      return l.gap / std::cos(l.angle) < r.gap / std::cos(r.angle);
    });
  }
}

void ContactTable::lookup(double y, TableSample& out) const {
  const double f = (y - grid_.y_min) / grid_.y_step;
  const double last = static_cast<double>(rows_ - 1);
  if (!(f >= -1e-9 && f <= last + 1e-9))
    throw InputError("contact table lookup: y = " + num(y) + " m outside the table range [" + num(grid_.y_min) +
                     ", " + num(grid_.y_min + last * grid_.y_step) + "] m");
  std::size_t k = static_cast<std::size_t>(std::max(0.0, std::min(f, last - 1.0)));
  if (rows_ == 1) k = 0;
  const double w = rows_ == 1 ? 0.0 : std::clamp(f - static_cast<double>(k), 0.0, 1.0);
  out.y = y;
  const double* a = &data_[k * kColumns];
  const double* b = rows_ == 1 ? a : a + kColumns;
  unpack(a, b, w, out);
}

}  // namespace railsim::contact
