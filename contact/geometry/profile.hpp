// Wheel and rail profiles: reading (CONTACT/SIMPACK .prw/.prr, two-column CSV),
// validation and smooth evaluation.
//
// Profile coordinates (CONTACT convention, metres):
// - y lateral, positive towards the FIELD side (outside of the track);
// - z positive DOWNWARD: for a wheel, z is the radius increase over the
//   nominal (tape-circle) radius, r = r0 + z; for a rail, z is the depth below
//   the profile origin.
// A wheel's flange therefore lies at negative y (S1002: flange tip at
// y = -55 mm, back face at y = -70 mm). Points are ordered by increasing y.
// Evaluation: parametric natural cubic spline in chord length through the
// points (no smoothing, as CONTACT's reference set-up), giving position, first
// and second derivatives and curvature (profile_spline.hpp).
// Bad input (unsorted, duplicated, self-intersecting, too short) throws
// InputError naming the file and line.
#pragma once

#include <string>
#include <vector>

#include "contact/geometry/profile_spline.hpp"

namespace railsim::contact {

enum class ProfileKind { wheel, rail };

struct ProfileReadOptions {
  // Length of one file unit in metres (0 = from the file: SIMPACK units.len.f,
  // or a CSV header with y_mm/z_mm or y_m/z_m columns).
  double unit = 0.0;
  bool mirror_y = false;  // mirror y after reading (in addition to the file's own flag)
  bool z_up = false;      // CSV only: the file's z axis points upward (flip it)
};

class Profile {
 public:
  // Validates and builds the spline. `lines` gives the file line of every point
  // (for error messages); it may be empty.
  Profile(ProfileKind kind, std::string source, std::vector<double> y, std::vector<double> z,
          std::vector<int> lines = {});

  ProfileKind kind() const { return kind_; }
  const std::string& source() const { return source_; }
  const std::vector<double>& y() const { return y_; }
  const std::vector<double>& z() const { return z_; }
  const ParametricSpline& spline() const { return spline_; }
  // A copy rotated by `angle` [rad] about the x axis through the profile origin,
  // (y, z) -> (y cos a + z sin a, -y sin a + z cos a): a positive angle tilts the
  // top of a rail towards the gauge side (negative y), as a canted rail.
  Profile rotated(double angle, const std::string& new_source = "") const;
  // 64-bit FNV-1a hash of kind and points: part of contact-table cache keys.
  unsigned long long content_hash() const;

 private:
  ProfileKind kind_;
  std::string source_;
  std::vector<double> y_, z_;
  ParametricSpline spline_;
};

// Physics sanity: the usual lateral extent of a profile is 100-200 mm for a
// wheel (S1002 130 mm) and 50-200 mm for a rail (the head of UIC60 74-81 mm,
// a whole section to its 150 mm foot). Outside: a legal but implausible
// profile (cut short, or another unit): a warning text naming the width, the
// file and the usual range; empty when inside.
inline constexpr double kUsualWheelWidthMin = 0.100, kUsualRailWidthMin = 0.050, kUsualProfileWidthMax = 0.200;
std::string profile_width_warning(const Profile& profile);

// Read a profile file (.prw/.prr SIMPACK/CONTACT format, or .csv/.txt two
// columns) or a shipped name (see shipped_profile_names()).
Profile read_profile(const std::string& path_or_name, ProfileKind kind, const ProfileReadOptions& options = {});

// Shipped names: S1002 (wheel, MBench_S1002_v3); UIC60 (the Manchester-benchmark
// rail turned upright by -1/40, to be used with inclination 1/40 or 1/20);
// UIC60_MBench (the same file as given, already canted 1/40: inclination none);
// UIC60_true (CONTACT testbank upright UIC60 with vertical sides). Also
// shipped_profile_names() and the folder that holds them
// ($RAILSIM_PROFILE_DIR, else profiles/ in the data folder, core/data_dir.hpp).
std::string shipped_profile_names();
// Whether `name` (any case) is one of the shipped names above.
bool is_shipped_profile_name(const std::string& name);
std::string shipped_profile_dir();

}  // namespace railsim::contact
