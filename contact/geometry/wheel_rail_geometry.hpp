// Wheel-rail contact geometry of a wheelset on a straight track: profile
// placement and the rigid contact search.
//
// Frames and signs (../shared/docs/architecture.md): track frame x forward,
// y to the LEFT, z UP. Wheelset pose: lateral shift y (positive to the left),
// vertical position z of the axle centre, roll phi about x (positive lifts the
// left wheel), yaw psi about z (positive turns the front to the left).
// Wheel point in wheelset axes X_w = (r sin(theta), sigma (d + s), -r cos(theta))
// with sigma = +1 left / -1 right, s the wheel-profile lateral coordinate (field
// side positive), d = flange_back/2 - back_face, r = r0 + F(s); track position
// P = (0, y, z) + Rz(psi) Rx(phi) X_w.
// Yaw: the contact locus method -- for each wheel circle the point whose
// surface normal has no longitudinal component (the only candidates for contact
// with a rail that is straight along x): sin(theta) cos(psi) -
// sin(psi) sin(phi) cos(theta) = -r'(y_w) cos(phi) sin(psi) (e.g. Shabana,
// Zaazaa & Sugiyama 2008, "Railroad vehicle dynamics", ch. 4).
// Rigid contact: the minimum VERTICAL gap between the locus and the rail; at a
// minimum the slopes agree, so the normals coincide. Every other local minimum
// whose gap is below SearchOptions::second_gap_max is reported too (two-point
// contact, with its gap). Placement: gauge measured gauge_depth below the top of
// the (canted) rail; flange back faces flange_back apart; wheel profile origin
// (tape circle, radius r0) at back_face from the back face.
// Per contact: rolling radius r, contact angle delta = rotation about the track
// x axis from +z to the contact normal (the rail's outward normal), so tread
// contact on the left wheel is slightly positive, flange contact on the left
// wheel large positive and on the right wheel large negative (CONTACT's sign for
// its left/right configurations). Relative curvatures (physics-reference 1.1):
// A = cos(gamma_w) / (2 r) with gamma_w = atan(dF/ds) the wheel slope,
// B = (kappa_rail - kappa_wheel)/2 with the signed profile curvatures
// (convex rail crown positive, concave wheel tread positive). The normal gap
// around the point is approximated by vertical gap x cos(delta) measured along
// the contact plane (exact to second order).
// Units SI (m, rad).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "contact/geometry/profile.hpp"
#include "core/content_hash.hpp"

namespace railsim::contact {

enum class Side { left = 0, right = 1 };

struct TrackSetup {
  double gauge = 1.435;        // [m] between gauge points of the rails
  double gauge_depth = 0.014;  // [m] below the top of the rail where the gauge is measured
  double flange_back = 1.360;  // [m] distance between the flange back faces
  double back_face = -0.070;   // [m] wheel-profile y of the flange back face
  double r0 = 0.46;            // [m] wheel radius at the profile origin (tape circle)
  double inclination = 0.0;    // [rad] rail cant applied to the rail profile (atan(1/40)); 0 = none
  // Throws InputError naming the field and its allowed range.
  void validate() const;
};

// Rail inclination as text: "1/40" -> atan(1/40); "none" or "0" -> 0; a plain
// number is a slope in [0, 0.2]. InputError naming `where` otherwise.
double parse_inclination(const std::string& text, const std::string& where);

struct SearchOptions {
  double second_gap_max = 1.0e-4;  // [m] report extra local minima with gap below this
  double wheel_step = 5.0e-5;      // [m] wheel sampling step (arc length) before refinement
  double flange_margin = 3.0e-3;   // [m] contact closer than this to the flange tip = climbing (out of range)
  double rail_step = 5.0e-6;       // [m] rail height grid step
};

struct ContactPoint {
  double x = 0.0, y = 0.0, z = 0.0;  // position in the track frame [m]
  double y_wheel = 0.0;              // wheel-profile lateral coordinate (field side +) [m]
  double y_rail = 0.0;               // rail-profile lateral coordinate, file axes (field side +) [m]
  double radius = 0.0;               // wheel-circle radius at the point [m]
  double height = 0.0;               // height of the point below the axle centre, r cos(theta) [m]
                                     // (theta: angle of the point ahead of the lowest point of its
                                     // wheel circle, nonzero under yaw; CONTACT's rolling radius)
  double angle = 0.0;                // contact angle [rad] (see header)
  double A = 0.0, B = 0.0;           // relative curvatures [1/m]
  double gap = 0.0;                  // undeformed normal gap [m] (0 for the touching point)
};

// A local minimum of one wheel's vertical gap, with the depth of its basin:
// the lower of the two ridges (gap maxima) that separate it from the adjacent
// minima, minus its own gap (infinite when it is the only minimum). A basin's
// depth falls to zero where the minimum merges with a ridge and vanishes (a
// saddle-node of the gap function), e.g. where the touching point leaves the
// flange root for the flank.
struct ContactCandidate {
  ContactPoint point;  // gap: undeformed normal gap (0 for the touching point)
  double vertical_gap = 0.0;  // [m]
  double depth = 0.0;         // [m], vertical
};

struct WheelContact {
  static constexpr int kMaxPoints = 3;
  int n = 0;                                // number of points (>= 1)
  std::array<ContactPoint, kMaxPoints> p;  // p[0] = smallest gap, then increasing gap
};

struct WheelsetContact {
  double y = 0.0, yaw = 0.0, roll = 0.0;
  std::array<double, 2> z{};  // axle-centre height that makes each wheel touch [m] (equal when roll is solved)
  std::array<WheelContact, 2> wheel;  // [Side]
};

// Undeformed normal gap across the contact plane around a point: q lateral in the
// contact plane (positive towards track +y projected), h(q) >= 0, and the local
// longitudinal curvature A(q).
struct GapProfile {
  double angle = 0.0;      // contact angle of the plane [rad]
  std::vector<double> q;   // [m], uniform
  std::vector<double> h;   // [m]
  std::vector<double> A;   // [1/m]
};

class WheelRailGeometry {
 public:
  WheelRailGeometry(const Profile& wheel, const Profile& rail, const TrackSetup& setup,
                    const SearchOptions& options = {});

  // Wheelset at shift y and yaw: roll and height such that both wheels touch.
  // InputError when |y| or |yaw| is out of range or the profiles stop touching
  // inside their defined ranges (flange climbing off the profile ends).
  WheelsetContact solve(double y, double yaw = 0.0) const;
  // Prescribed roll: each wheel lowered on its own until it touches (as CONTACT
  // does for a half-wheelset with prescribed roll).
  WheelsetContact at_roll(double y, double yaw, double roll) const;
  // Contacts of one wheel at a given axle height (gaps not shifted).
  WheelContact wheel_contacts(Side side, double y, double z, double roll, double yaw) const;
  // Every local minimum of one wheel's vertical gap up to gap_max above the
  // smallest (vertical gaps measured from the smallest), ordered along the wheel
  // profile (increasing y_wheel). No limit on their number.
  std::vector<ContactCandidate> candidates(Side side, double y, double z, double roll, double yaw,
                                           double gap_max) const;
  // The point of one wheel's contact locus at wheel-profile chord parameter t
  // (no search): position, radius and height, the rail's normal angle and the
  // relative curvatures there; gap = the normal gap at axle height z
  // (vertical gap x cos(angle)). Strip-wise contact tables sample this.
  ContactPoint point_at(Side side, double t, double y, double z, double roll, double yaw) const {
    return make_point(side, t, y, z, roll, yaw);
  }
  // Range of the wheel-profile chord parameter that can touch a rail from above
  // (the flange back face excluded) [m].
  double wheel_t_min() const { return samples_.front().t; }
  double wheel_t_max() const { return samples_.back().t; }
  const Profile& wheel_profile() const { return wheel_; }
  // Minimum vertical gap of one wheel with the axle centre at height z.
  double min_gap(Side side, double y, double z, double roll, double yaw) const;
  // Gap profile around point `p` of wheel `side` at the given pose (n points over +-halfwidth).
  GapProfile gap_profile(Side side, const ContactPoint& p, double y, double z, double roll, double yaw,
                         double halfwidth, int n) const;

  const TrackSetup& setup() const { return setup_; }
  const SearchOptions& options() const { return options_; }
  double rail_offset() const { return rail_offset_; }  // rail-profile origin |y| in the track [m]
  double nominal_height() const { return setup_.r0; }  // reference axle height (rail origin at z = 0)

 private:
  struct WheelSample {
    double t, s, F, Fs;  // chord parameter, lateral, radius increase, dF/ds
  };
  struct LocusPoint {
    double x, y, z, gap, height;
  };
  LocusPoint locus(Side side, double s, double F, double Fs, double y, double z, double cr, double sr, double cy,
                   double sy) const;
  double rail_depth(double u) const;  // rail z (down) at placed-profile lateral u; +inf outside
  double rail_t(double u) const;
  double refine(Side side, std::size_t k, double y, double z, double roll, double yaw, double& t_out) const;
  // The wheel's vertical gap at every sample (g) and the indices of its local
  // minima, neighbours not separated by a rise of 10 nm merged.
  std::vector<std::size_t> gap_minima(Side side, double y, double z, double roll, double yaw,
                                      std::vector<double>& g) const;
  void check_pose(double y, double yaw) const;
  ContactPoint make_point(Side side, double t, double y, double z, double roll, double yaw) const;

  TrackSetup setup_;
  SearchOptions options_;
  Profile wheel_, rail_;  // rail already rotated by the inclination
  double d_ = 0.0;            // wheel-profile origin |y_w| in wheelset axes
  double tip_ = 0.0;          // wheel-profile y of the flange tip (largest z)
  double rail_offset_ = 0.0;  // rail-profile origin |y| in the track
  std::vector<WheelSample> samples_;
  double u0_ = 0.0, du_ = 0.0;
  std::vector<double> rail_z_, rail_tgrid_;
};

// The common start of a geometry table's cache key (contact_table.hpp,
// strip_contact_table.hpp): the table's format magic, both profiles' content
// hashes and the track set-up (gauge, gauge depth, flange back, back face,
// r0, inclination), in that order; each table adds its grid and options.
ContentHash geometry_cache_hash(const void* magic, std::size_t magic_size, const Profile& wheel, const Profile& rail,
                                const WheelRailGeometry& geometry);

}  // namespace railsim::contact
