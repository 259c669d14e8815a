// Strip-wise wheel-rail contact geometry of a wheelset versus lateral shift y
// and yaw psi, tabulated once from the rigid contact search
// (wheel_rail_geometry.hpp), cached on disk and evaluated at run time without
// allocation: what a vehicle model needs to compute distributed (non-Hertzian,
// multi-patch) normal contact whose loads change continuously when a patch
// opens, closes, or slides through the flange root.
//
// The LEFT wheel's profile is cut into strips of equal arc length (`strip`,
// 1 mm by default) at fixed wheel-profile positions; for every table node
// (y_i, psi_k) the wheelset is placed in its rigid pose (both wheels touching,
// roll and axle height solved; WheelRailGeometry::solve) and, for each strip,
// the point of the wheel's contact locus on it gives:
//   gap     normal gap to the rail at the rigid pose [m] (0 at the touching point;
//           vertical gap x cos(angle): well conditioned also on steep flanks,
//           where the vertical gap changes by ~tan(angle) x the shift),
//   angle   contact angle of the rail's normal there [rad] (left-wheel sign),
//   lateral lateral position from the wheelset centre [m],
//   lead    position ahead of the axle's vertical plane, in the wheelset's
//           frame [m] (yaw; zero at a tread contact below the axle),
//   height  height below the axle, r cos(theta) [m] (CONTACT's rolling radius),
//   A       longitudinal relative curvature [1/m],
//   f       Winkler modulus of the strip per unit E*, kappa / E*, for which a
//           bed of independent strips, n = kappa p ds (p the normal
//           penetration, ds the strip width), carries Hertz's load
//           N = K(A, B) delta^{3/2} when the gap is quadratic: kappa =
//           (3/4) K(A, B) sqrt(B) (integrate (delta - B q^2) dq), a function
//           of B/A times E* (contact/hertz.hpp), B the strip's lateral
//           relative curvature (kappa_rail - kappa_wheel)/2, clipped to
//           [0.01, 100] A (locally conformal or concave gaps).
// Only strips whose gap stays below `gap_store` somewhere near a node are kept
// (per row, with the rows and yaw nodes around it, so that interpolation
// always sees both ends of a cell).
// Interpolation: cubic Hermite in y for every quantity (slopes by centred
// differences, limited as Fritsch & Carlson 1980 so that a cell never
// overshoots its rows: no negative gaps between rows, no cell-scale wiggle),
// so that each is C1 in the shift (issue 13: the rolling radius, lateral
// position, lead, A and f were linear in y before format 04, with slope jumps
// at every 0.1 mm node); between yaw nodes linear in psi^2 for
// the even quantities and in psi^2 for lead/psi (lead is odd in psi: the left
// wheel at -psi is the fore-aft mirror of the left wheel at +psi, so the table
// covers psi >= 0 and is C1 across psi = 0). The rigid pose (roll, axle
// height) is interpolated the same way (Hermite in y).
// Cache: file strip_table_<16 hex digits>.bin keyed by an FNV-1a hash of a
// format version, both profiles, the track set-up and the grid (material-free:
// kappa = E* f). Units SI.
#pragma once

#include <string>
#include <vector>

#include "contact/geometry/wheel_rail_geometry.hpp"

namespace railsim::contact {

struct StripTableGrid {
  double y_min = -0.015, y_max = 0.015, y_step = 1e-4;  // [m]
  double yaw_max = 0.03, yaw_step = 0.005;                // [rad], nodes 0, yaw_step, ... yaw_max
  double strip = 1e-3;                                    // strip width (arc length) [m]
  double gap_store = 2e-3;                                // [m]
  void validate() const;                                  // InputError naming the field and its range
};

// One strip of one wheel (the fields above).
struct StripPoint {
  int index = 0;  // strip index along the wheel profile (consecutive = neighbours)
  double gap = 0, angle = 0, lateral = 0, lead = 0, height = 0, A = 0, f = 0;
  double y_wheel = 0;  // wheel-profile lateral coordinate [m]
};

// Strips of one wheel, increasing index; no allocation. Held as columns
// (structure of arrays) so that StripContactTable::strips() writes each
// interpolated quantity as one vectorised loop and the normal-contact solver
// (engine/wheel_rail/strip_patches.cpp) reads only the columns it needs;
// entries [0, n) are valid (the arrays are not cleared on construction).
struct StripSet {
  static constexpr int kMax = 320;
  int n = 0;
  double width = 0.0;  // strip width [m]
  int index[kMax];
  double gap[kMax], angle[kMax], lateral[kMax], lead[kMax], height[kMax], A[kMax], f[kMax], y_wheel[kMax];
  StripPoint operator[](int j) const {
    return StripPoint{index[j], gap[j], angle[j], lateral[j], lead[j], height[j], A[j], f[j], y_wheel[j]};
  }
  void add(const StripPoint& p) {  // caller checks n < kMax
    set(n++, p);
  }
  void set(int j, const StripPoint& p) {
    index[j] = p.index;
    gap[j] = p.gap;
    angle[j] = p.angle;
    lateral[j] = p.lateral;
    lead[j] = p.lead;
    height[j] = p.height;
    A[j] = p.A;
    f[j] = p.f;
    y_wheel[j] = p.y_wheel;
  }
};

struct StripPose {
  double roll = 0.0, droll_dy = 0.0;      // [rad], [rad/m]
  double height = 0.0, dheight_dy = 0.0;  // axle height above the centred pose [m], [-]
};

class StripContactTable {
 public:
  StripContactTable() = default;
  static StripContactTable build(const WheelRailGeometry& geometry, const StripTableGrid& grid);
  // Load from the cache folder (empty: the default) or build and store.
  static StripContactTable cached(const WheelRailGeometry& geometry, const Profile& wheel, const Profile& rail,
                                  const StripTableGrid& grid, const std::string& cache_dir,
                                  bool* loaded_from_cache = nullptr);

  // Strips of the LEFT wheel at shift y (toward it) and yaw psi whose gap is
  // at most `gap_cutoff`, plus the neighbour on each side of every run of such
  // strips (for the edges of the loaded region). y and |psi| are clamped to
  // the table; callers check in_range().
  void strips(double y, double psi, double gap_cutoff, StripSet& out) const;
  void pose(double y, double psi, StripPose& out) const;
  bool in_range(double y, double psi) const;
  double y_min() const { return grid_.y_min; }
  double y_max() const { return grid_.y_max; }
  double yaw_max() const { return grid_.yaw_max; }
  const StripTableGrid& grid() const { return grid_; }
  int strip_count() const { return strips_total_; }
  // Wheel-profile chord parameter of strip j (WheelRailGeometry::point_at).
  double strip_parameter(int j) const { return t0_ + j * grid_.strip; }
  std::size_t stored_entries() const { return entries_; }

  // Winkler modulus per unit E* for a relative-curvature ratio B/A (see header).
  static double winkler_factor(double B_over_A);
  // Hertz's load-approach constant K = N / delta^{3/2} = E* A^{-1/2} g(B/A):
  // g, and the ratio B/A for a given g (inverse; clamped to [0.01, 100]).
  static double hertz_stiffness_factor(double B_over_A);
  static double ratio_for_stiffness_factor(double g);
  // Hertz's semi-axes relative to the interpenetration semi-axes at the
  // approach delta: a = alpha sqrt(delta/A), b = beta sqrt(delta/B) (both
  // functions of B/A alone; 1/sqrt(2) each for a sphere).
  static void hertz_axis_factors(double B_over_A, double& alpha, double& beta);

 private:
  // One strip at one node: values and limited y-slopes, the cache file's
  // record. In memory the fourteen fields are held as columns (structure of
  // arrays, `cols_`: column c of entry n at cols_[c * entries + n]), so that
  // strips() interpolates each quantity over a run of consecutive strips as
  // one vectorisable loop, and the gap pass reads only the two gap columns.
  struct Entry {
    double gap, dgap, angle, dangle, lateral, dlateral, lead, dlead, height, dheight, A, dA, f, df;
  };
  static constexpr int kLanes = 4;     // strips per vector instruction in strips() (AVX2 doubles)
  static constexpr int kColumns = 14;  // in Entry's order: value, y-slope of gap, angle, lateral, lead, height, A, f
  static constexpr int kGap = 0, kAngle = 1, kLateral = 2, kLead = 3, kHeight = 4, kA = 5, kF = 6;  // quantity q: columns 2q, 2q+1
  const double* column(int c) const { return cols_.data() + std::size_t(c) * entries_; }
  void unpack(const std::vector<Entry>& entries);  // fills gaps_, values_ and the near ranges
  std::vector<Entry> pack() const;                 // the file's records
  struct Row {
    double roll, droll, z, dz;  // rigid pose and y-slopes
    int j0 = 0, j1 = -1;        // stored strip range [j0, j1]
    std::size_t offset = 0;     // into gaps_ and values_
  };
  const Row& row(int k, int i) const { return rows_[std::size_t(k) * std::size_t(ny_) + std::size_t(i)]; }
  // Per node and level L: the hull [j0, j1] of the strips whose gap at the
  // node is at most kNearGap[L] (j1 < j0: none). Between nodes the gap stays
  // within its rows' values (monotone Hermite cells, linear in psi^2), so a
  // strip whose interpolated gap is at most a cutoff <= kNearGap[L] has a
  // node of its cell with a gap at most the cutoff: strips() searches only
  // these hulls. Derived from the entries after a build or a load (not stored).
  static constexpr int kNearLevels = 3;
  static constexpr double kNearGap[kNearLevels] = {0.1e-3, 0.25e-3, 0.5e-3};  // [m]
  struct NearRange {
    int j0 = 0, j1 = -1;
  };
  void index_near_ranges();
  std::vector<NearRange> near_;
  void locate(double y, double psi, int& i, double& t, int& k, double& wpsi, double& apsi) const;

  StripTableGrid grid_;
  int ny_ = 0, nk_ = 0, strips_total_ = 0;
  double t0_ = 0.0;  // chord parameter of strip 0
  std::vector<double> y_wheel_;  // per strip
  std::vector<Row> rows_;
  std::size_t entries_ = 0;
  std::vector<double> cols_;  // kColumns columns of entries_ values
};

}  // namespace railsim::contact
