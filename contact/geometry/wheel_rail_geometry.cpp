// Rigid wheel-rail contact search (see wheel_rail_geometry.hpp for frames,
// signs and sources).
#include "contact/geometry/wheel_rail_geometry.hpp"

#include <algorithm>
#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/errors.hpp"
#include "core/input_file.hpp"

namespace railsim::contact {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();

double sigma_of(Side side) { return side == Side::left ? 1.0 : -1.0; }
const char* side_name(Side side) { return side == Side::left ? "left" : "right"; }

std::string num(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

// Signed curvature of a parametric curve (y(t), z(t)).
double curvature(const CurvePoint& c) {
  const double n2 = c.dy * c.dy + c.dz * c.dz;
  return (c.dy * c.ddz - c.dz * c.ddy) / (n2 * std::sqrt(n2));
}
}  // namespace

double parse_inclination(const std::string& text, const std::string& where) {
  if (text == "none" || text == "0") return 0.0;
  const auto slash = text.find('/');
  char* end = nullptr;
  if (slash != std::string::npos) {
    const std::string a = text.substr(0, slash), b = text.substr(slash + 1);
    // Whole texts only (an embedded NUL ended the number early) and finite
    // numbers (1/inf and 1/1e400 read as slope 0).
    const double num = std::strtod(a.c_str(), &end);
    const bool ok_a = !a.empty() && end == a.c_str() + a.size() && std::isfinite(num);
    const double den = std::strtod(b.c_str(), &end);
    const bool ok_b = !b.empty() && end == b.c_str() + b.size() && std::isfinite(den);
    if (ok_a && ok_b && num >= 0 && den > 0 && num / den <= 0.2) return std::atan(num / den);
  } else {
    const double v = std::strtod(text.c_str(), &end);
    if (!text.empty() && end == text.c_str() + text.size() && std::isfinite(v) && v >= 0 && v <= 0.2)
      return std::atan(v);
  }
  // (The text as quote_input shows it: a NUL in it would end the message.)
  throw InputError(where + " '" + quote_input(text) +
                   "': expected 1/N (e.g. 1/40, 1/20), a slope in [0, 0.2], or none");
}

void TrackSetup::validate() const {
  auto check = [](double v, double lo, double hi, const char* name, const char* unit, bool lo_open = false) {
    if (!(std::isfinite(v) && (lo_open ? v > lo : v >= lo) && v <= hi))
      throw InputError(std::string("track set-up: '") + name + "': expected a value in " + (lo_open ? "(" : "[") +
                       num(lo) + ", " + num(hi) + "] " + unit + " (got " + num(v) + ")");
  };
  check(gauge, 0.5, 2.5, "gauge", "m");
  // (0 is the top itself: no gauge-side point lies above it, the gauge could not be placed.)
  check(gauge_depth, 0.0, 0.05, "gauge_depth", "m", true);
  check(flange_back, 0.4, 2.4, "flange_back", "m");
  check(back_face, -0.2, 0.0, "back_face", "m");
  check(r0, 0.1, 1.5, "r0 (nominal rolling radius)", "m");
  check(inclination, -0.2, 0.2, "inclination", "rad");
  if (flange_back >= gauge) throw InputError("track set-up: 'flange_back' must be smaller than 'gauge'");
}

WheelRailGeometry::WheelRailGeometry(const Profile& wheel, const Profile& rail, const TrackSetup& setup,
                                     const SearchOptions& options)
    : setup_(setup),
      options_(options),
      wheel_(wheel),
      rail_(setup.inclination != 0.0 ? rail.rotated(setup.inclination) : rail) {
  setup_.validate();
  if (wheel.kind() != ProfileKind::wheel) throw InputError(wheel.source() + ": expected a wheel profile");
  if (rail.kind() != ProfileKind::rail) throw InputError(rail.source() + ": expected a rail profile");
  if (!(options_.wheel_step > 0 && options_.rail_step > 0 && options_.second_gap_max >= 0))
    throw InputError("contact search options: steps must be positive and second_gap_max non-negative");
  d_ = 0.5 * setup_.flange_back - setup_.back_face;
  tip_ = wheel_.y()[static_cast<std::size_t>(std::max_element(wheel_.z().begin(), wheel_.z().end()) - wheel_.z().begin())];

  // Wheel samples, uniform in chord length.
  const auto& ws = wheel_.spline();
  const auto nw = static_cast<std::size_t>(std::ceil(ws.length() / options_.wheel_step)) + 1;
  samples_.reserve(nw);
  for (std::size_t i = 0; i < nw; ++i) {
    const double t = std::min(ws.length(), static_cast<double>(i) * options_.wheel_step);
    const CurvePoint c = ws.eval(t);
    if (c.dy <= 1e-6) continue;  // vertical part (flange back face): cannot touch from above
    samples_.push_back({t, c.y, c.z, c.dz / c.dy});
  }
  if (samples_.size() < 10) throw InputError(wheel.source() + ": wheel profile has no usable tread");

  // Rail height grid (upper envelope, depth z down), uniform in u.
  const auto& rs = rail_.spline();
  const double umin = *std::min_element(rail_.y().begin(), rail_.y().end());
  const double umax = *std::max_element(rail_.y().begin(), rail_.y().end());
  du_ = options_.rail_step;
  u0_ = umin;
  const auto nu = static_cast<std::size_t>(std::floor((umax - umin) / du_)) + 1;
  rail_z_.assign(nu, kInf);
  rail_tgrid_.assign(nu, 0.0);
  const double dt = 0.5 * du_;
  const auto nt = static_cast<std::size_t>(std::ceil(rs.length() / dt)) + 1;
  CurvePoint prev = rs.eval(0.0);
  double tprev = 0.0;
  for (std::size_t i = 1; i < nt; ++i) {
    const double t = std::min(rs.length(), static_cast<double>(i) * dt);
    const CurvePoint c = rs.eval(t);
    const double ua = std::min(prev.y, c.y), ub = std::max(prev.y, c.y);
    const auto ka = static_cast<long>(std::ceil((ua - u0_) / du_));
    const auto kb = static_cast<long>(std::floor((ub - u0_) / du_));
    for (long k = std::max(0L, ka); k <= std::min(kb, static_cast<long>(nu) - 1); ++k) {
      const double u = u0_ + static_cast<double>(k) * du_;
      const double w = ub > ua ? (u - prev.y) / (c.y - prev.y) : 0.0;
      const double zz = prev.z + w * (c.z - prev.z);
      if (zz < rail_z_[static_cast<std::size_t>(k)]) {
        rail_z_[static_cast<std::size_t>(k)] = zz;
        rail_tgrid_[static_cast<std::size_t>(k)] = tprev + w * (t - tprev);
      }
    }
    prev = c;
    tprev = t;
  }
  // Gauge point: first point from the gauge side at gauge_depth below the top.
  const double ztop = *std::min_element(rail_z_.begin(), rail_z_.end());
  const double zg = ztop + setup_.gauge_depth;
  double ug = kInf;
  for (std::size_t k = 1; k < nu; ++k) {
    if (rail_z_[k - 1] >= zg && rail_z_[k] < zg) {
      const double w = (rail_z_[k - 1] - zg) / (rail_z_[k - 1] - rail_z_[k]);
      ug = u0_ + (static_cast<double>(k - 1) + w) * du_;
      break;
    }
  }
  if (!std::isfinite(ug))
    throw InputError(rail.source() + ": the rail profile does not reach " + num(setup_.gauge_depth * 1e3) +
                     " mm below its top on the gauge side, where 'gauge_depth' measures the gauge (cannot place it by "
                     "gauge)");
  rail_offset_ = 0.5 * setup_.gauge - ug;
}

double WheelRailGeometry::rail_depth(double u) const {
  const double f = (u - u0_) / du_;
  if (!(f >= 0.0)) return kInf;
  const auto k = static_cast<std::size_t>(f);
  if (k + 1 >= rail_z_.size()) return kInf;
  const double w = f - static_cast<double>(k);
  return rail_z_[k] + w * (rail_z_[k + 1] - rail_z_[k]);
}

double WheelRailGeometry::rail_t(double u) const {
  const double f = std::clamp((u - u0_) / du_, 0.0, static_cast<double>(rail_z_.size() - 1) - 1e-9);
  const auto k = static_cast<std::size_t>(f);
  const double w = f - static_cast<double>(k);
  double t = rail_tgrid_[k] + w * (rail_tgrid_[k + 1] - rail_tgrid_[k]);
  // Newton on y(t) = u for the exact spline parameter.
  for (int it = 0; it < 4; ++it) {
    const CurvePoint c = rail_.spline().eval(t);
    if (std::abs(c.dy) < 1e-9) break;
    t -= (c.y - u) / c.dy;
  }
  return t;
}

WheelRailGeometry::LocusPoint WheelRailGeometry::locus(Side side, double s, double F, double Fs, double y, double z,
                                                       double cr, double sr, double cy, double sy) const {
  const double sg = sigma_of(side);
  const double r = setup_.r0 + F;
  double st = 0.0, ct = 1.0;
  if (sy != 0.0) {
    const double a = cy, b = sy * sr, c = -(sg * Fs) * cr * sy;
    const double h = std::hypot(a, b);
    const double th = std::atan2(b, a) + std::asin(std::clamp(c / h, -1.0, 1.0));
    st = std::sin(th);
    ct = std::cos(th);
  }
  const double Xw = r * st, Yw = sg * (d_ + s), Zw = -r * ct;
  const double Y1 = Yw * cr - Zw * sr;
  const double Z1 = Yw * sr + Zw * cr;
  LocusPoint p;
  p.height = r * ct;
  p.x = Xw * cy - Y1 * sy;
  p.y = y + Xw * sy + Y1 * cy;
  p.z = z + Z1;
  const double u = sg * p.y - rail_offset_;
  p.gap = p.z + rail_depth(u);
  return p;
}

double WheelRailGeometry::refine(Side side, std::size_t k, double y, double z, double roll, double yaw,
                                 double& t_out) const {
  const double cr = std::cos(roll), sr = std::sin(roll), cy = std::cos(yaw), sy = std::sin(yaw);
  const double lo = samples_[k == 0 ? 0 : k - 1].t;
  const double hi = samples_[std::min(k + 1, samples_.size() - 1)].t;
  const auto& ws = wheel_.spline();
  auto f = [&](double t) {
    const CurvePoint c = ws.eval(t);
    const double Fs = c.dy > 1e-9 ? c.dz / c.dy : 1e9;
    return locus(side, c.y, c.z, Fs, y, z, cr, sr, cy, sy).gap;
  };
  std::uintmax_t iters = 60;
  const auto r = boost::math::tools::brent_find_minima(f, lo, hi, 40, iters);
  t_out = r.first;
  return r.second;
}

double WheelRailGeometry::min_gap(Side side, double y, double z, double roll, double yaw) const {
  const double cr = std::cos(roll), sr = std::sin(roll), cy = std::cos(yaw), sy = std::sin(yaw);
  double gmin = kInf;
  std::size_t kmin = 0;
  for (std::size_t k = 0; k < samples_.size(); ++k) {
    const auto& w = samples_[k];
    const double g = locus(side, w.s, w.F, w.Fs, y, z, cr, sr, cy, sy).gap;
    if (g < gmin) {
      gmin = g;
      kmin = k;
    }
  }
  if (!std::isfinite(gmin)) return kInf;
  double t = 0.0;
  return std::min(gmin, refine(side, kmin, y, z, roll, yaw, t));
}

ContactPoint WheelRailGeometry::make_point(Side side, double t, double y, double z, double roll, double yaw) const {
  const double sg = sigma_of(side);
  const CurvePoint c = wheel_.spline().eval(t);
  const double Fs = c.dy > 1e-9 ? c.dz / c.dy : 1e9;
  const double kw = curvature(c);
  const LocusPoint lp = locus(side, c.y, c.z, Fs, y, z, std::cos(roll), std::sin(roll), std::cos(yaw), std::sin(yaw));
  const double u = sg * lp.y - rail_offset_;
  const CurvePoint rc = rail_.spline().eval(rail_t(u));
  const double slope = rc.dz / rc.dy;  // dz_rail/du (depth)
  const double kr = curvature(rc);
  ContactPoint p;
  p.x = lp.x;
  p.y = lp.y;
  p.z = lp.z;
  p.y_wheel = c.y;
  const double ca = std::cos(setup_.inclination), sa = std::sin(setup_.inclination);
  p.y_rail = rc.y * ca - rc.z * sa;
  p.radius = setup_.r0 + c.z;
  p.height = lp.height;
  p.angle = std::atan(-sg * slope);
  p.A = 1.0 / (2.0 * p.radius * std::sqrt(1.0 + Fs * Fs));
  p.B = 0.5 * (kr - kw);
  p.gap = lp.gap * std::cos(p.angle);
  return p;
}

std::vector<std::size_t> WheelRailGeometry::gap_minima(Side side, double y, double z, double roll, double yaw,
                                                       std::vector<double>& g) const {
  const double cr = std::cos(roll), sr = std::sin(roll), cy = std::cos(yaw), sy = std::sin(yaw);
  const std::size_t n = samples_.size();
  g.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const auto& w = samples_[k];
    g[k] = locus(side, w.s, w.F, w.Fs, y, z, cr, sr, cy, sy).gap;
  }
  // Local minima, then merge neighbours not separated by a real rise (10 nm).
  std::vector<std::size_t> mins;
  for (std::size_t k = 0; k < n; ++k) {
    if (!std::isfinite(g[k])) continue;
    const double gl = k > 0 ? g[k - 1] : kInf;
    const double gr = k + 1 < n ? g[k + 1] : kInf;
    if (g[k] < gl && g[k] <= gr) mins.push_back(k);
  }
  constexpr double kProminence = 1e-8;  // [m] humps lower than this are spline noise
  std::vector<std::size_t> kept;
  for (std::size_t m : mins) {
    if (!kept.empty()) {
      const std::size_t a = kept.back();
      const double peak = *std::max_element(g.begin() + static_cast<long>(a), g.begin() + static_cast<long>(m) + 1);
      if (peak - std::max(g[a], g[m]) < kProminence) {
        if (g[m] < g[a]) kept.back() = m;
        continue;
      }
    }
    kept.push_back(m);
  }
  return kept;
}

WheelContact WheelRailGeometry::wheel_contacts(Side side, double y, double z, double roll, double yaw) const {
  std::vector<double> g;
  const std::vector<std::size_t> kept = gap_minima(side, y, z, roll, yaw, g);
  WheelContact wc;
  if (kept.empty()) return wc;
  struct Cand {
    double gap, t;
  };
  std::vector<Cand> cands;
  for (std::size_t k : kept) {
    double t = 0.0;
    const double gg = refine(side, k, y, z, roll, yaw, t);
    cands.push_back({std::min(gg, g[k]), gg <= g[k] ? t : samples_[k].t});
  }
  std::sort(cands.begin(), cands.end(), [](const Cand& a, const Cand& b) { return a.gap < b.gap; });
  for (const auto& cnd : cands) {
    if (wc.n == WheelContact::kMaxPoints) break;
    if (wc.n > 0 && cnd.gap - cands.front().gap > options_.second_gap_max) break;
    wc.p[static_cast<std::size_t>(wc.n++)] = make_point(side, cnd.t, y, z, roll, yaw);
  }
  return wc;
}

std::vector<ContactCandidate> WheelRailGeometry::candidates(Side side, double y, double z, double roll, double yaw,
                                                            double gap_max) const {
  std::vector<double> g;
  const std::vector<std::size_t> kept = gap_minima(side, y, z, roll, yaw, g);
  std::vector<ContactCandidate> out;
  if (kept.empty()) return out;
  // Refined minima and ridges between neighbours.
  std::vector<double> gap(kept.size()), t(kept.size()), ridge(kept.size() + 1, kInf);
  for (std::size_t i = 0; i < kept.size(); ++i) {
    const double gg = refine(side, kept[i], y, z, roll, yaw, t[i]);
    if (gg > g[kept[i]]) t[i] = samples_[kept[i]].t;
    gap[i] = std::min(gg, g[kept[i]]);
    if (i > 0) {
      double peak = -kInf;
      for (std::size_t k = kept[i - 1]; k <= kept[i]; ++k)
        if (std::isfinite(g[k])) peak = std::max(peak, g[k]);
      ridge[i] = peak;
    }
  }
  const double gmin = *std::min_element(gap.begin(), gap.end());
  for (std::size_t i = 0; i < kept.size(); ++i) {
    if (gap[i] - gmin > gap_max) continue;
    ContactCandidate c;
    c.point = make_point(side, t[i], y, z, roll, yaw);
    c.vertical_gap = gap[i] - gmin;
    c.point.gap = c.vertical_gap * std::cos(c.point.angle);
    const double barrier = std::min(ridge[i], ridge[i + 1]);
    c.depth = std::isfinite(barrier) ? std::max(0.0, barrier - gap[i]) : kInf;
    out.push_back(c);
  }
  std::sort(out.begin(), out.end(),
            [](const ContactCandidate& a, const ContactCandidate& b) { return a.point.y_wheel < b.point.y_wheel; });
  return out;
}

void WheelRailGeometry::check_pose(double y, double yaw) const {
  if (!(std::isfinite(y) && std::abs(y) <= 0.05))
    throw InputError("wheelset lateral shift y = " + num(y) + " m: expected a value in [-0.05, 0.05] m");
  if (!(std::isfinite(yaw) && std::abs(yaw) <= 0.1))
    throw InputError("wheelset yaw = " + num(yaw) + " rad: expected a value in [-0.1, 0.1] rad");
}

namespace {
// The pose as the messages name it: "wheelset lateral shift y = 0.012 m", with
// the yaw when it is not zero and the roll when the caller gave it.
std::string pose_text(double y, double yaw, const double* given_roll = nullptr) {
  std::string t = "wheelset lateral shift y = " + num(y) + " m";
  if (yaw != 0.0) t += ", yaw = " + num(yaw) + " rad";
  if (given_roll) t += ", roll = " + num(*given_roll) + " rad (given)";
  return t;
}

// The points of one wheel checked for range; the message (built only on
// failure) names the pose, with the roll when the caller gave it.
void check_points(const WheelContact& wc, Side side, double y, double yaw, const double* given_roll, double wheel_lo,
                  double wheel_hi, double tip, double margin) {
  const auto pose = [&] { return pose_text(y, yaw, given_roll); };
  if (wc.n == 0)
    throw InputError(pose() + ": the " + side_name(side) + " wheel does not meet its rail (out of range)");
  constexpr double kMargin = 1e-3;
  for (int i = 0; i < wc.n; ++i) {
    const auto& p = wc.p[static_cast<std::size_t>(i)];
    if (p.y_wheel < wheel_lo + kMargin || p.y_wheel > wheel_hi - kMargin)
      throw InputError(pose() + " is out of range: the " + side_name(side) +
                       " wheel touches within 1 mm of the end of its profile (y_wheel = " + num(p.y_wheel * 1e3) +
                       " mm); flange climbing or wheel off the rail");
    if (i == 0 && std::abs(p.y_wheel - tip) < margin)
      throw InputError(pose() + " is out of range: the " + side_name(side) + " wheel rides on its flange tip (contact " +
                       num(std::abs(p.y_wheel - tip) * 1e3) + " mm from the tip): flange climbing");
  }
}
}  // namespace

WheelsetContact WheelRailGeometry::solve(double y, double yaw) const {
  check_pose(y, yaw);
  auto f = [&](double roll) { return min_gap(Side::left, y, 0.0, roll, yaw) - min_gap(Side::right, y, 0.0, roll, yaw); };
  double lo = -0.05, hi = 0.05;
  const double flo = f(lo), fhi = f(hi);
  if (!(std::isfinite(flo) && std::isfinite(fhi) && flo < 0.0 && fhi > 0.0))
    throw InputError("wheelset lateral shift y = " + num(y) + " m, yaw = " + num(yaw) +
                     " rad: no roll angle in [-0.05, 0.05] rad puts both wheels on their rails (out of range)");
  std::uintmax_t iters = 80;
  const auto r = boost::math::tools::toms748_solve(f, lo, hi, flo, fhi, boost::math::tools::eps_tolerance<double>(48),
                                                   iters);
  const double roll = 0.5 * (r.first + r.second);
  WheelsetContact ws;
  ws.y = y;
  ws.yaw = yaw;
  ws.roll = roll;
  const double z = -0.5 * (min_gap(Side::left, y, 0.0, roll, yaw) + min_gap(Side::right, y, 0.0, roll, yaw));
  ws.z = {z, z};
  for (Side s : {Side::left, Side::right}) {
    ws.wheel[static_cast<std::size_t>(s)] = wheel_contacts(s, y, z, roll, yaw);
    check_points(ws.wheel[static_cast<std::size_t>(s)], s, y, yaw, nullptr, wheel_.y().front(), wheel_.y().back(),
                 tip_, options_.flange_margin);
  }
  return ws;
}

WheelsetContact WheelRailGeometry::at_roll(double y, double yaw, double roll) const {
  check_pose(y, yaw);
  if (!(std::isfinite(roll) && std::abs(roll) <= 0.1))
    throw InputError("wheelset roll = " + num(roll) + " rad: expected a value in [-0.1, 0.1] rad");
  WheelsetContact ws;
  ws.y = y;
  ws.yaw = yaw;
  ws.roll = roll;
  for (Side s : {Side::left, Side::right}) {
    const auto i = static_cast<std::size_t>(s);
    const double g = min_gap(s, y, 0.0, roll, yaw);
    if (!std::isfinite(g))
      throw InputError(pose_text(y, yaw, &roll) + ": the " + std::string(side_name(s)) +
                       " wheel does not meet its rail (out of range)");
    ws.z[i] = -g;
    ws.wheel[i] = wheel_contacts(s, y, ws.z[i], roll, yaw);
    check_points(ws.wheel[i], s, y, yaw, &roll, wheel_.y().front(), wheel_.y().back(), tip_,
                 options_.flange_margin);
  }
  return ws;
}

GapProfile WheelRailGeometry::gap_profile(Side side, const ContactPoint& p, double y, double z, double roll,
                                          double yaw, double halfwidth, int n) const {
  if (n < 3 || !(halfwidth > 0)) throw InputError("gap profile: need n >= 3 points and a positive half-width");
  const double cr = std::cos(roll), sr = std::sin(roll), cy = std::cos(yaw), sy = std::sin(yaw);
  const std::size_t m = samples_.size();
  std::vector<double> ly(m), lz(m), la(m);
  for (std::size_t k = 0; k < m; ++k) {
    const auto& w = samples_[k];
    const LocusPoint lp = locus(side, w.s, w.F, w.Fs, y, z, cr, sr, cy, sy);
    const double sgn = sigma_of(side);  // make the locus increasing in y
    ly[k] = sgn * lp.y;
    lz[k] = lp.z;
    la[k] = 1.0 / (2.0 * (setup_.r0 + w.F) * std::sqrt(1.0 + w.Fs * w.Fs));
  }
  GapProfile gp;
  gp.angle = p.angle;
  const double sg = sigma_of(side);
  const double ca = std::cos(p.angle);
  for (int j = 0; j < n; ++j) {
    const double q = -halfwidth + 2.0 * halfwidth * j / (n - 1);
    const double yq = sg * (p.y + q * ca);  // in increasing-locus coordinates
    const auto it = std::upper_bound(ly.begin(), ly.end(), yq);
    double h = kInf, A = 0.0;
    if (it != ly.begin() && it != ly.end()) {
      const auto k = static_cast<std::size_t>(it - ly.begin()) - 1;
      const double w = (yq - ly[k]) / (ly[k + 1] - ly[k]);
      const double zw = lz[k] + w * (lz[k + 1] - lz[k]);
      A = la[k] + w * (la[k + 1] - la[k]);
      const double u = yq - rail_offset_;
      h = (zw + rail_depth(u)) * ca;
    }
    gp.q.push_back(q);
    gp.h.push_back(h);
    gp.A.push_back(A);
  }
  return gp;
}

ContentHash geometry_cache_hash(const void* magic, std::size_t magic_size, const Profile& wheel, const Profile& rail,
                                const WheelRailGeometry& geometry) {
  ContentHash f;
  f.bytes(magic, magic_size);
  f.value(wheel.content_hash());
  f.value(rail.content_hash());
  const TrackSetup& s = geometry.setup();
  for (double v : {s.gauge, s.gauge_depth, s.flange_back, s.back_face, s.r0, s.inclination}) f.value(v);
  return f;
}

}  // namespace railsim::contact
