// Full wheelset model; see wheelset_full.hpp.
#include "engine/wheelset_full.hpp"

#include <cmath>
#include <cstdio>

#include "engine/creepages.hpp"

namespace railsim::engine {

bool wheelset_full_forces(const Model& model, Data& d, int w, const double* x, double* xdot) {
  const Wheelset& ws = model.wheelsets[w];
  const RigidBody& body = model.bodies[ws.body];
  const BodyMotion& m = d.motion[ws.body];
  const TrackSample& T = d.track[ws.body];
  GenForce& F = d.force[ws.body];
  const ContactGeometry& geo = *ws.geometry;

  const double ya = 0.5 * (T.lat_left + T.lat_right);
  const double dya = 0.5 * (T.dlat_left + T.dlat_right);
  const double beta = x[ws.beta_state];
  WheelsetKinematics k;
  k.V = d.V;
  k.Omega = d.V / geo.r0() + beta;
  k.kappa = T.curvature;
  k.y = m.q[kLat] - ya;
  k.ydot = m.v[kLat] - d.V * dya;
  k.phi = m.q[kRoll];
  k.phidot = m.v[kRoll];
  k.psi = m.q[kYaw];
  k.psidot = m.v[kYaw];
  const double ymax = model.max_lateral_shift > 0 ? model.max_lateral_shift : geo.max_shift();
  if (!(std::abs(k.y) <= ymax)) {
    char buf[256];
    std::snprintf(buf, sizeof buf,
                  "wheelset '%s': lateral shift %.4g mm relative to the track exceeds the admissible %.4g mm "
                  "(contact geometry range / derailment) [model: full wheelset]",
                  ws.name.c_str(), k.y * 1e3, ymax * 1e3);
    d.fail(buf);
    return false;
  }
  double Fy_sum = 0, Fz_sum = 0, Mx_sum = 0, Mz_sum = 0, My_sum = 0;
  const int npts = geo.points();
  for (int i = 0; i < 2; ++i) {
    const int side = i == 0 ? 1 : -1;
    const double zr = i == 0 ? T.vert_left : T.vert_right;
    const double dzr = i == 0 ? T.dvert_left : T.dvert_right;
    k.z = m.q[kVert] - zr;
    k.zdot = m.v[kVert] - d.V * dzr;
    WheelOutput& out = d.wheel[2 * w + i];
    out = WheelOutput{};
    double Nmax = -1.0;
    bool valid = true;
    const char* reason = "";
    for (int p = 0; p < npts; ++p) {
      WheelContact c;
      geo.evaluate_point(side * k.y, p, c);
      if (p > 0 && !(c.N0 > 0)) continue;  // point absent at this shift
      const double cd = std::cos(c.contact_angle);
      const double a = c.lateral, r = c.rolling_radius;
      double dq = -(k.z + side * a * k.phi) * cd;
      double N0 = ws.static_load[i], q0 = ws.hertz_q0[i];
      if (c.N0 > 0 && c.q0 > 0) {  // table: DYTSI's reference state at this shift
        N0 = c.N0;
        q0 = c.q0;
      } else {
        dq += (r - geo.r0()) * cd;
      }
      const double ratio = 1.0 + (dq - c.gap) / q0;
      const double N = ratio > 0 ? N0 * ratio * std::sqrt(ratio) : 0.0;
      const contact::Creepages cr = wheel_creepages(k, c, side);
      const contact::ContactForces cf =
          model.coupling.forces(c, N, ws.static_load[i], cr, d.V, d.workspace[2 * w + i].get());
      const double th = c.contact_angle + side * k.phi;
      const double ct = std::cos(th), st = std::sin(th);
      const double X = cf.Fx - cf.Fy * k.psi * cd;
      const double Y = cf.Fx * k.psi + cf.Fy * ct - side * N * st - side * c.flange_force;
      const double Z = side * cf.Fy * st + N * ct;
      Fy_sum += Y;
      Fz_sum += Z;
      Mx_sum += side * a * Z + r * Y;
      Mz_sum += -side * a * (X + Y * k.psi) + cf.Mz * ct;
      My_sum += -r * (X + Y * k.psi);
      // Wheel outputs: sums over the points; creepages and position of the most loaded point.
      out.Q += Z;
      out.N += N;
      out.Y += Y;
      out.Fx += cf.Fx;
      out.Fy += cf.Fy;
      out.Mz += cf.Mz;
      if (N > Nmax) {
        Nmax = N;
        out.creep = cr;
        out.contact_y = m.q[kLat] + side * a;
        out.contact_angle = c.contact_angle;
        out.rolling_radius = r;
      }
      if (!cf.valid) {
        valid = false;
        reason = cf.reason;
      }
    }
    if (!(out.N > 0)) {
      valid = false;
      reason = "loss of contact (wheel lift)";
    }
    out.valid = valid;
    out.reason = reason;
    if (!valid) {
      if (d.invalid_contact_calls == 0) d.first_invalid_reason = reason;
      ++d.invalid_contact_calls;
    }
  }
  const double Iy = body.inertia.y();
  F[kLat] += Fy_sum;
  F[kVert] += Fz_sum;
  F[kRoll] += Mx_sum + Iy * k.Omega * (k.psidot + d.V * k.kappa);  // absolute yaw rate (frame turns at V kappa)
  F[kYaw] += Mz_sum - Iy * k.Omega * k.phidot;
  xdot[ws.beta_state] = My_sum / Iy;
  return true;
}

}  // namespace railsim::engine
