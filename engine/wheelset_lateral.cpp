// Lateral wheelset model; see wheelset_lateral.hpp.
#include "engine/wheelset_lateral.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "engine/creepages.hpp"

namespace railsim::engine {

namespace {
double kinematic_roll(const ContactGeometry& geo, double y) {
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
    const double cd = std::cos(c[i].contact_angle);
    const double th = c[i].contact_angle + side * k.phi;
    const double ct = std::cos(th), st = std::sin(th);
    const double N = Q[i] / ct;
    const contact::Creepages cr = wheel_creepages(k, c[i], side);
    const contact::ContactForces cf =
        model.coupling.forces(c[i], N, ws.static_load[i], cr, d.V, d.workspace[2 * w + i].get());
    const double Y = cf.Fy * ct - side * N * st + cf.Fx * k.psi - side * c[i].flange_force;
    const double X = cf.Fx - cf.Fy * k.psi * cd;
    Ysum += Y;
    Msum += -side * c[i].lateral * (X + Y * k.psi) + cf.Mz * ct;
    out.Q = Q[i];
    out.N = N;
    out.Y = Y;
    out.Fx = cf.Fx;
    out.Fy = cf.Fy;
    out.Mz = cf.Mz;
    out.creep = cr;
    out.contact_y = m.q[kLat] + side * c[i].lateral;
    out.contact_angle = c[i].contact_angle;
    out.rolling_radius = c[i].rolling_radius;
    out.valid = cf.valid;
    out.reason = cf.reason;
    if (!cf.valid) {
      if (d.invalid_contact_calls == 0) d.first_invalid_reason = cf.reason;  // allocation only once
      ++d.invalid_contact_calls;
    }
  }
  (void)body;
  F[kLat] += Ysum;
  F[kYaw] += Msum;
  return true;
}

}  // namespace railsim::engine
