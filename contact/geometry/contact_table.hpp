// Contact table: the rigid contact geometry of a wheelset (zero yaw) tabulated
// versus lateral shift y, computed once by WheelRailGeometry::solve, cached on
// disk keyed by its inputs and interpolated at run time without allocation.
//
// Columns per row (SI: m, rad, 1/m): y, roll, z, then per side (left, right)
// and per point slot (0 = touching point, 1 = second point of two-point
// contact, NaN when absent): present, y (track), y_wheel, y_rail, radius,
// angle, A, B, gap. Interpolation is linear in y, point by point: a point of
// one row and one of the next are the same point when they lie within 1 mm of
// each other on the wheel, whatever their slots (the slots swap where the
// second point becomes the touching one, and the interpolated touching point
// then changes where the interpolated gaps cross); a point without a partner
// (a jump of the contact point, tread <-> flange, with no second point) is
// taken from the nearest row, so jumps are never averaged away. Points come
// out ordered by vertical gap; between rows the first one's gap may be > 0.
// Cache: file contact_table_<16 hex digits>.bin in the cache folder; the key is
// an FNV-1a hash of a format version, both profiles' points, the track set-up,
// the y grid and the search options. Default folder: core/cache_dir.hpp
// ($RAILSIM_CACHE_DIR, $XDG_CACHE_HOME/railsim, ~/.cache/railsim). Written
// atomically (core/atomic_file.hpp); a corrupt or mismatching file is rebuilt.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "contact/geometry/wheel_rail_geometry.hpp"

namespace railsim::contact {

struct TableGrid {
  double y_min = -0.012;  // [m]
  double y_max = 0.012;   // [m]
  double y_step = 1e-4;   // [m]
  void validate() const;  // InputError with the allowed ranges
};

// One interpolated table entry (plain data, no allocation).
struct TableSample {
  double y = 0.0, roll = 0.0, z = 0.0;
  std::array<WheelContact, 2> wheel;  // [Side]; p[0] main, p[1] second (n tells)
};

class ContactTable {
 public:
  // Column layout.
  static constexpr int kPointFields = 9;  // present, y, y_wheel, y_rail, radius, angle, A, B, gap
  static constexpr int kSlots = 2;
  static constexpr int kColumns = 3 + 2 * kSlots * kPointFields;

  // Build (no cache).
  static ContactTable build(const WheelRailGeometry& geometry, const TableGrid& grid);
  // Load from the cache or build and store. `cache_dir` empty = default folder.
  // `key_extra` is mixed into the key (e.g. the profile hashes).
  static ContactTable cached(const WheelRailGeometry& geometry, const Profile& wheel, const Profile& rail,
                             const TableGrid& grid, const std::string& cache_dir, bool* loaded_from_cache = nullptr);
  static std::string default_cache_dir();
  static unsigned long long cache_key(const WheelRailGeometry& geometry, const Profile& wheel, const Profile& rail,
                                      const TableGrid& grid);

  // Interpolated sample at y (no allocation). Throws InputError outside [y_min, y_max].
  void lookup(double y, TableSample& out) const;
  // Row access.
  std::size_t rows() const { return rows_; }
  double value(std::size_t row, int column) const { return data_[row * kColumns + static_cast<std::size_t>(column)]; }
  const TableGrid& grid() const { return grid_; }
  static std::vector<std::string> column_names();

 private:
  void fill(std::size_t row, const WheelsetContact& c);
  void unpack(const double* row_a, const double* row_b, double w, TableSample& out) const;
  TableGrid grid_;
  std::size_t rows_ = 0;
  std::vector<double> data_;
};

}  // namespace railsim::contact
