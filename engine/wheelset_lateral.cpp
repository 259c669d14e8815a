// Lateral wheelset model; see wheelset_lateral.hpp.
#include "engine/wheelset_lateral.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "engine/creepages.hpp"

namespace railsim::engine {

namespace {

// Normal loads of the points of one wheel carrying the vertical load Q by a
// common vertical approach change dw (see the header). Points without a
// reference state (N0, q0) use the main point alone.
constexpr int kMaxPoints = 4;
struct PointLoads {
  int n = 0;
  WheelContact c[kMaxPoints];
  double N[kMaxPoints] = {};
};

double sum_vertical(const PointLoads& p, const double* ct, double dw, double* N, double* dsum) {
  double s = 0.0, ds = 0.0;
  for (int k = 0; k < p.n; ++k) {
    const WheelContact& c = p.c[k];
    const double cd = std::cos(c.contact_angle);
    const double ratio = 1.0 + (dw * cd - c.gap) / c.q0;
    N[k] = ratio > 0.0 ? c.N0 * ratio * std::sqrt(ratio) : 0.0;
    s += N[k] * ct[k];
    if (ratio > 0.0) ds += 1.5 * c.N0 * std::sqrt(ratio) * cd / c.q0 * ct[k];
  }
  if (dsum) *dsum = ds;
  return s;
}

void share_load(PointLoads& p, double Q, double phi_side) {
  double ct[kMaxPoints];
  for (int k = 0; k < p.n; ++k) ct[k] = std::cos(p.c[k].contact_angle + phi_side);
  if (p.n == 1) {
    p.N[0] = Q / ct[0];
    return;
  }
  // Bracket: lo, every point unloaded (sum 0 < Q); hi, the main point alone
  // carrying Q (sum >= Q).
  const WheelContact& m = p.c[0];
  const double cd0 = std::cos(m.contact_angle);
  double lo = 0.0;
  for (int k = 0; k < p.n; ++k) lo = std::min(lo, (p.c[k].gap - p.c[k].q0) / std::cos(p.c[k].contact_angle));
  double hi = (m.q0 * (std::pow(Q / (ct[0] * m.N0), 2.0 / 3.0) - 1.0) + m.gap) / cd0;
  double dw = hi;
  for (int it = 0; it < 60; ++it) {
    double ds = 0.0;
    const double f = sum_vertical(p, ct, dw, p.N, &ds) - Q;
    if (std::abs(f) <= 1e-10 * Q) return;
    (f > 0.0 ? hi : lo) = dw;
    const double next = ds > 0.0 ? dw - f / ds : 0.5 * (lo + hi);
    dw = (next > lo && next < hi) ? next : 0.5 * (lo + hi);
  }
  sum_vertical(p, ct, dw, p.N, nullptr);
}

double kinematic_roll(const ContactGeometry& geo, double y) {
  if (const double rigid = geo.rigid_roll(y); std::isfinite(rigid)) return rigid;
  WheelContact l, r;
  geo.evaluate(y, l);
  geo.evaluate(-y, r);
  return (l.rolling_radius - r.rolling_radius) / (l.lateral + r.lateral);
}
}  // namespace

void wheelset_lateral_kinematics(const Model& model, Data& d, int w) {
  if (!model.kinematic_roll) return;
  const Wheelset& ws = model.wheelsets[w];
  BodyMotion& m = d.motion[ws.body];
  const TrackSample& T = d.track[ws.body];
  const double y = m.q[kLat] - 0.5 * (T.lat_left + T.lat_right);
  const double ydot = m.v[kLat] - d.V * 0.5 * (T.dlat_left + T.dlat_right);
  const ContactGeometry& geo = *ws.geometry;
  const double lim = geo.max_shift();
  if (!(std::abs(y) < lim)) return;  // wheelset_lateral_forces reports it
  const double h = 1e-6;
  const double y0 = std::clamp(y, -lim + h, lim - h);
  const double phi = kinematic_roll(geo, y0);
  const double dphi = (kinematic_roll(geo, y0 + h) - kinematic_roll(geo, y0 - h)) / (2 * h);
  m.q[kRoll] = phi;
  m.v[kRoll] = dphi * ydot;
}

bool wheelset_lateral_forces(const Model& model, Data& d, int w) {
  const Wheelset& ws = model.wheelsets[w];
  const RigidBody& body = model.bodies[ws.body];
  const BodyMotion& m = d.motion[ws.body];
  const TrackSample& T = d.track[ws.body];
  GenForce& F = d.force[ws.body];
  const ContactGeometry& geo = *ws.geometry;

  const double ya = 0.5 * (T.lat_left + T.lat_right);
  const double dya = 0.5 * (T.dlat_left + T.dlat_right);
  WheelsetKinematics k;
  k.V = d.V;
  k.Omega = d.V / geo.r0();
  k.kappa = T.curvature;
  k.y = m.q[kLat] - ya;
  k.ydot = m.v[kLat] - d.V * dya;
  k.psi = m.q[kYaw];
  k.psidot = m.v[kYaw];
  k.phi = m.q[kRoll];      // kinematic roll (0 when switched off)
  k.phidot = m.v[kRoll];
  const double ymax = model.max_lateral_shift > 0 ? model.max_lateral_shift : geo.max_shift();
  if (!(std::abs(k.y) <= ymax)) {
    char buf[256];
    std::snprintf(buf, sizeof buf,
                  "wheelset '%s': lateral shift %.4g mm relative to the track exceeds the admissible %.4g mm "
                  "(contact geometry range / derailment) [model: lateral wheelset]",
                  ws.name.c_str(), k.y * 1e3, ymax * 1e3);
    d.fail(buf);
    return false;
  }
  WheelContact c[2];
  geo.evaluate(k.y, c[0]);
  geo.evaluate(-k.y, c[1]);
  const int npts = std::min(geo.points(), kMaxPoints);
  const double aL = c[0].lateral, aR = c[1].lateral;
  const double S = -F[kVert];
  const double D = -F[kRoll] + geo.r0() * F[kLat];
  const double Q[2] = {(S * aR + D) / (aL + aR), (S * aL - D) / (aL + aR)};
  double Ysum = 0.0, Msum = 0.0;
  for (int i = 0; i < 2; ++i) {
    const int side = i == 0 ? 1 : -1;
    WheelOutput& out = d.wheel[2 * w + i];
    if (!(Q[i] > 0.0)) {
      char buf[256];
      std::snprintf(buf, sizeof buf,
                    "wheelset '%s', %s wheel: loss of contact (vertical load %.4g N) [model: lateral wheelset, "
                    "quasi-static loads; use the full wheelset model for wheel lift]",
                    ws.name.c_str(), i == 0 ? "left" : "right", Q[i]);
      d.fail(buf);
      return false;
    }
    // Points of this wheel: the main one, plus those present with a reference state.
    PointLoads pts;
    pts.c[pts.n++] = c[i];
    const bool multi = npts > 1 && c[i].N0 > 0 && c[i].q0 > 0;
    for (int p = 1; multi && p < npts; ++p) {
      WheelContact cp;
      geo.evaluate_point(side * k.y, p, cp);
      if (cp.N0 > 0 && cp.q0 > 0) pts.c[pts.n++] = cp;
    }
    share_load(pts, Q[i], side * k.phi);
    out = WheelOutput{};
    out.Q = Q[i];
    out.valid = true;
    double Nmax = -1.0;
    for (int p = 0; p < pts.n; ++p) {
      const WheelContact& cp = pts.c[p];
      const double N = pts.N[p];
      if (p > 0 && !(N > 0.0)) continue;  // open second point
      const double cd = std::cos(cp.contact_angle);
      const double th = cp.contact_angle + side * k.phi;
      const double ct = std::cos(th), st = std::sin(th);
      const contact::Creepages cr = wheel_creepages(k, cp, side);
      const contact::ContactForces cf =
          model.coupling.forces(cp, N, ws.static_load[i], cr, d.V, d.workspace[2 * w + i].get());
      const double Y = cf.Fy * ct - side * N * st + cf.Fx * k.psi - side * cp.flange_force;
      const double X = cf.Fx - cf.Fy * k.psi * cd;
      Ysum += Y;
      Msum += -side * cp.lateral * (X + Y * k.psi) + cf.Mz * ct;
      out.N += N;
      out.Y += Y;
      out.Fx += cf.Fx;
      out.Fy += cf.Fy;
      out.Mz += cf.Mz;
      if (N > Nmax) {  // creepages and position of the most loaded point
        Nmax = N;
        out.creep = cr;
        out.contact_y = m.q[kLat] + side * cp.lateral;
        out.contact_angle = cp.contact_angle;
        out.rolling_radius = cp.rolling_radius;
      }
      if (!cf.valid) {
        out.valid = false;
        out.reason = cf.reason;
      }
    }
    if (!out.valid) {  // counted per wheel, as in the full model
      if (d.invalid_contact_calls == 0) d.first_invalid_reason = out.reason;  // allocation only once
      ++d.invalid_contact_calls;
    }
  }
  (void)body;
  F[kLat] += Ysum;
  F[kYaw] += Msum;
  return true;
}

}  // namespace railsim::engine
