// Wheel-rail forces of a wheelset, both models; see wheelset_contact.hpp.
#include "engine/wheel_rail/wheelset_contact.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "contact/hertz.hpp"
#include "engine/wheel_rail/creepages.hpp"
#include "engine/wheel_rail/strip_patches.hpp"
#include "engine/wheel_rail/wear_number.hpp"

namespace railsim::engine {

namespace {

// Normal load of a point for a normal approach change dq (the law of the header).
inline double point_load(const ContactPointGeometry& c, double dq, double* dN_ddq = nullptr) {
  const double ratio = 1.0 + (dq - c.gap) / c.q0;
  if (!(ratio > 0.0)) {
    if (dN_ddq) *dN_ddq = 0.0;
    return 0.0;
  }
  const double sr = std::sqrt(ratio);
  if (dN_ddq) *dN_ddq = 1.5 * c.weight * c.N0 * sr / c.q0;
  return c.weight * c.N0 * ratio * sr;
}

// Sum of the vertical load components of a wheel's points at vertical approach w.
double vertical_sum(const WheelGeometry& g, const double* ct, double w, double* N, double* dsum) {
  double s = 0.0, ds = 0.0;
  for (int k = 0; k < g.n; ++k) {
    const double cd = std::cos(g.p[k].contact_angle);
    double dN = 0.0;
    N[k] = point_load(g.p[k], w * cd, &dN);
    s += N[k] * ct[k];
    ds += dN * cd * ct[k];
  }
  if (dsum) *dsum = ds;
  return s;
}

// Fills the reference state of points that have none (cones: the static load
// and approach of the wheelset).
inline void complete_point(ContactPointGeometry& c, double N0, double q0) {
  if (!(c.N0 > 0.0 && c.q0 > 0.0)) {
    c.N0 = N0;
    c.q0 = q0;
  }
}

// The wheelset has left the geometry's range. When the wheel toward which it
// moved has a flange on the way (contact angle above 50 degrees between half
// the range and its edge) it has climbed past its flange: a derailment. Otherwise no physics takes a
// wheelset there (a blow-up of the integration or an absurd input): a
// numerical failure that says what to change.
void range_failure(const Model& model, Data& d, int w, const WheelsetKinematics& k, double ymax) {
  const Wheelset& ws = model.wheelsets[w];
  const ContactGeometry& geo = *ws.geometry;
  char buf[480];
  if (!(std::abs(k.psi) <= geo.max_yaw())) {
    std::snprintf(buf, sizeof buf,
                  "wheelset '%s': yaw %.4g mrad exceeds the contact geometry's range of %.4g mrad (shift %.4g mm) "
                  "[model: %s wheelset]; if the vehicle is not derailing, extend the geometry's max_yaw",
                  ws.name.c_str(), k.psi * 1e3, geo.max_yaw() * 1e3, k.y * 1e3, wheelset_model_name(model.wheelset_model));
    d.leave_range(buf);
    return;
  }
  // The steepest contact angle the wheel toward which it moved meets between
  // half the range and the range's edge: a flanged wheel (above 50 degrees on
  // the way) has been lifted over its flank to get there.
  const double edge = std::min(std::abs(k.y), 0.999 * geo.max_shift());
  ContactPointGeometry c;
  double steepest = 0.0;
  for (int i = 0; i <= 40 && std::isfinite(k.y); ++i) {
    const ContactPointGeometry p = geo.main_point(0.5 * edge * (1.0 + i / 40.0));
    if (p.contact_angle > steepest) {
      steepest = p.contact_angle;
      c = p;
    }
  }
  const bool flange = std::isfinite(k.y) && steepest > 50.0 * M_PI / 180.0;
  if (flange) {
    std::snprintf(buf, sizeof buf,
                  "derailment: wheelset '%s' climbed past its flange (lateral shift %.4g mm relative to the track, "
                  "beyond the geometry's %.4g mm; flank angle on the way %.1f deg) [model: %s wheelset]",
                  ws.name.c_str(), k.y * 1e3, ymax * 1e3, c.contact_angle * 180.0 / M_PI,
                  wheelset_model_name(model.wheelset_model));
    d.derail(buf);
  } else {
    std::snprintf(buf, sizeof buf,
                  "wheelset '%s': lateral shift %.4g mm relative to the track exceeds the admissible %.4g mm of "
                  "the contact geometry, without flange contact [model: %s wheelset]: the run left the model's "
                  "range (a growing oscillation on a geometry without flange, or an integration blow-up), not a "
                  "derailment; widen the geometry (max_lateral_shift, profiles), or reduce max_step or the "
                  "tolerances",
                  ws.name.c_str(), k.y * 1e3, ymax * 1e3, wheelset_model_name(model.wheelset_model));
    d.leave_range(buf);
  }
}

// Strip gaps beyond this never carry load (approaches stay below ~0.3 mm) [m].
constexpr double kStripGapCutoff = 1.5e-3;
// The strips fetched are those up to a gap that can still be loaded (the
// approach plus what the roll beyond the rigid pose adds at the wheel's
// farthest strip), at most kStripGapCutoff: the loads are the same as with
// every strip up to kStripGapCutoff, at a fraction of the cost. The lateral
// model fetches up to kLateralFirstCutoff (its lever arms need exactly 0.2 mm)
// and again up to kStripGapCutoff when the solved approach reaches that gap
// (flange contact; 0.3 mm before 2026-12-04: the coach's ERRI run gives the
// same bytes 11 % faster, curve_twist within 0.2 % of Y's range).
constexpr double kLateralFirstCutoff = 0.2e-3;
constexpr double kStripLateralReach = 0.2;  // strips' lateral positions lie within l0 -+ this [m]

// Patches of a distributed-contact wheel as points with their loads: the
// equivalent Hertz ellipse at the patch's own load (N0 = N).
void patches_to_points(const StripLoads& L, const contact::Material& m, WheelGeometry& g, double* N) {
  g.n = L.n;
  for (int p = 0; p < L.n; ++p) {
    g.p[p] = L.patch[p];
    N[p] = L.N[p];
    ContactPointGeometry& c = g.p[p];
    if (c.semi_a > 0 && c.semi_b > 0 && N[p] > 0) {  // curvature B that gives this ellipse under N (Hertz)
      const contact::HertzPatch h = contact::hertz_from_semi_axes(c.semi_a, c.semi_b, N[p], m);
      c.A = h.A;
      c.B = h.B;
    }
    c.N0 = N[p];
  }
}

// The lateral model's quasi-static load of a wheel fell to zero: it cannot
// lift a wheel (the full model can). Always false.
bool lateral_loss_of_contact(Data& d, const Wheelset& ws, int i, double Q) {
  char buf[320];
  std::snprintf(buf, sizeof buf,
                "wheelset '%s', %s wheel: loss of contact (vertical load %.4g N) [model: lateral wheelset, "
                "quasi-static loads; use the full wheelset model for wheel lift]",
                ws.name.c_str(), i == 0 ? "left" : "right", Q);
  d.leave_range(buf);
  return false;
}

// Normal loads from strips: full model, from the wheel's approach; lateral
// model, the approach that carries the quasi-static load.
bool distributed_loads(const Model& model, Data& d, int w, const WheelsetKinematics& k, contact::StripSet* strips,
                       WheelGeometry* g, double (*N)[WheelGeometry::kMaxPoints], double* Qlat) {
  const Wheelset& ws = model.wheelsets[w];
  const ContactGeometry& geo = *ws.geometry;
  const BodyMotion& m = d.motion[ws.body];
  const double Es = geo.contact_modulus();
  const contact::Material& mat = model.coupling.options().material;
  StripLoads L;
  if (model.wheelset_model == WheelsetModel::full) {
    RigidPose ref;  // the approach and roll are measured from the rigid pose
    geo.rigid_pose(k.y, k.psi, ref);
    const double cn = model.coupling.options().normal_damping;
    for (int i = 0; i < 2; ++i) {
      const int side = i == 0 ? 1 : -1;
      const double zr = d.rail[std::size_t(w)].vertical[i];
      const double zr_rate = d.rail[std::size_t(w)].vertical_rate[i];
      const double wi = ws.static_approach[i] - (m.q[kVert] - zr - ref.height);
      const double dphi = side * (k.phi - ref.roll);
      // Largest w - dphi a over the wheel's strips, a within l0 -+ kStripLateralReach.
      const double reach = wi - dphi * (dphi > 0.0 ? geo.l0() - kStripLateralReach : geo.l0() + kStripLateralReach);
      geo.strips(side * k.y, side * k.psi, std::min(kStripGapCutoff, reach + 1e-6), strips[i]);
      strip_loads(strips[i], wi, dphi, 0.0, Es, L, true, model.patch_shape);
      patches_to_points(L, mat, g[i], N[i]);
      if (cn > 0.0) {
        const double rate0 = m.v[kVert] - zr_rate - ref.dheight_dy * k.ydot;
        double Ntot = 0.0;
        for (int p = 0; p < g[i].n; ++p) Ntot += N[i][p];
        for (int p = 0; p < g[i].n; ++p) {
          const ContactPointGeometry& c = g[i].p[p];
          const double rate = rate0 + side * c.lateral * (k.phidot - ref.droll_dy * k.ydot);
          N[i][p] = std::max(0.0, N[i][p] - cn * (N[i][p] / Ntot) * rate * std::cos(c.contact_angle));
        }
      }
    }
    return true;
  }
  // Lateral model: lever arms of the vertical equilibrium from each wheel's
  // strips near the touching point, weighted (1 - gap/0.2 mm)^2 (continuous in
  // the shift, unlike the touching strip alone; the load's own centre would
  // need the loads first).
  const GenForce& F = d.force[ws.body];
  const double S = -F[kVert];
  const double D = -F[kRoll] + geo.r0() * F[kLat];
  double a[2];
  for (int i = 0; i < 2; ++i) {
    const int side = i == 0 ? 1 : -1;
    geo.strips(side * k.y, side * k.psi, kLateralFirstCutoff, strips[i]);
    const contact::StripSet& set = strips[i];
    // Sums in four lanes over whole groups of strips (vectorised), the rest
    // in the first; 1 / 0.2 mm = 5000 1/m.
    constexpr int kLanes = 4;
    double nu[kLanes] = {}, de[kLanes] = {};
    auto add = [&](int j, int l) __attribute__((always_inline)) {
      const double u = std::max(0.0, 1.0 - set.gap[j] * 5e3);
      nu[l] += u * u * set.lateral[j];
      de[l] += u * u;
    };
    int j = 0;
    for (; j + kLanes <= set.n; j += kLanes)
      for (int l = 0; l < kLanes; ++l) add(j + l, l);
    for (; j < set.n; ++j) add(j, 0);
    const double num = (nu[0] + nu[1]) + (nu[2] + nu[3]), den = (de[0] + de[1]) + (de[2] + de[3]);
    if (den > 0.0) {
      a[i] = num / den;
      continue;
    }
    // No strip within 0.2 mm: the nearest one's position (else the nominal).
    double vmin = 1e9;
    a[i] = geo.l0();
    for (int q = 0; q < set.n; ++q)
      if (set.gap[q] < vmin) {
        vmin = set.gap[q];
        a[i] = set.lateral[q];
      }
  }
  Qlat[0] = (S * a[1] + D) / (a[0] + a[1]);
  Qlat[1] = (S * a[0] - D) / (a[0] + a[1]);
  for (int i = 0; i < 2; ++i) {
    if (!(Qlat[i] > 0.0)) return lateral_loss_of_contact(d, ws, i, Qlat[i]);
    // Loaded strips have gap < w cos(delta) <= w: fetched unless w reached the cutoff.
    double* warm = d.warm_start ? &d.approach_warm_start[2 * std::size_t(w) + std::size_t(i)] : nullptr;
    if (strip_approach_for_load(strips[i], Qlat[i], 0.0, Es, L, model.patch_shape, warm) >= kLateralFirstCutoff) {
      const int side = i == 0 ? 1 : -1;
      geo.strips(side * k.y, side * k.psi, kStripGapCutoff, strips[i]);
      strip_approach_for_load(strips[i], Qlat[i], 0.0, Es, L, model.patch_shape, warm);
    }
    patches_to_points(L, mat, g[i], N[i]);
  }
  return true;
}

}  // namespace

double share_wheel_load(const WheelGeometry& g_in, double Q, double phi_side, double N0_default, double q0_default,
                        double* N) {
  if (g_in.n == 1) {  // one point: N = Q / cos(theta); the approach from its law
    ContactPointGeometry c = g_in.p[0];
    complete_point(c, N0_default, q0_default);
    const double ct = std::cos(c.contact_angle + phi_side);
    N[0] = Q / ct;
    if (!(c.weight * c.N0 > 0.0 && c.q0 > 0.0)) return 0.0;
    return (c.q0 * (std::cbrt((N[0] * N[0]) / (c.weight * c.weight * c.N0 * c.N0)) - 1.0) + c.gap) /
           std::cos(c.contact_angle);
  }
  WheelGeometry g = g_in;
  for (int k = 0; k < g.n; ++k) complete_point(g.p[k], N0_default, q0_default);
  double ct[WheelGeometry::kMaxPoints];
  for (int k = 0; k < g.n; ++k) ct[k] = std::cos(g.p[k].contact_angle + phi_side);
  // Bracket: lo, every point unloaded (sum 0 < Q); hi, large enough for the
  // stiffest point alone to carry Q.
  double lo = 0.0, hi = 0.0;
  bool any = false;
  for (int k = 0; k < g.n; ++k) {
    const ContactPointGeometry& c = g.p[k];
    const double cd = std::cos(c.contact_angle);
    lo = std::min(lo, (c.gap - c.q0) / cd);
    if (c.weight > 1e-3 && ct[k] > 1e-3) {
      const double w = (c.q0 * (std::pow(Q / (ct[k] * c.weight * c.N0), 2.0 / 3.0) - 1.0) + c.gap) / cd;
      hi = any ? std::min(hi, w) : w;
      any = true;
    }
  }
  if (!any) {  // no point can carry a load
    for (int k = 0; k < g.n; ++k) N[k] = 0.0;
    return 0.0;
  }
  double w = hi;
  for (int it = 0; it < 60; ++it) {
    double ds = 0.0;
    const double f = vertical_sum(g, ct, w, N, &ds) - Q;
    if (std::abs(f) <= 1e-11 * Q) return w;
    (f > 0.0 ? hi : lo) = w;
    const double next = ds > 0.0 ? w - f / ds : 0.5 * (lo + hi);
    w = (next > lo && next < hi) ? next : 0.5 * (lo + hi);
  }
  vertical_sum(g, ct, w, N, nullptr);
  return w;
}

void wheelset_kinematics(const Model& model, Data& d, int w) {
  if (!model.kinematic_roll) return;
  const Wheelset& ws = model.wheelsets[w];
  BodyMotion& m = d.motion[ws.body];
  const double y = m.q[kLat] - d.rail[std::size_t(w)].lateral;
  const double ydot = m.v[kLat] - d.rail[std::size_t(w)].lateral_rate;
  const ContactGeometry& geo = *ws.geometry;
  if (!(std::abs(y) < geo.max_shift())) return;  // wheelset_forces reports it
  RigidPose pose;
  if (!geo.rigid_pose(y, m.q[kYaw], pose)) {
    // Knife-edge rails: (r_L - r_R)/(a_L + a_R), derivative by centred differences.
    auto roll = [&](double yy) {
      const ContactPointGeometry l = geo.main_point(yy), r = geo.main_point(-yy);
      return (l.rolling_radius - r.rolling_radius) / (l.lateral + r.lateral);
    };
    const double h = 1e-6, lim = geo.max_shift();
    const double y0 = std::clamp(y, -lim + h, lim - h);
    pose.roll = roll(y0);
    pose.droll_dy = (roll(y0 + h) - roll(y0 - h)) / (2 * h);
  }
  m.q[kRoll] = pose.roll;
  m.v[kRoll] = pose.droll_dy * ydot;
}

bool wheelset_forces(const Model& model, Data& d, int w, const double* x, double* xdot) {
  const long invalid_before = d.invalid_contact_calls;
  const Wheelset& ws = model.wheelsets[w];
  const RigidBody& body = model.bodies[ws.body];
  const BodyMotion& m = d.motion[ws.body];
  const TrackSample& T = d.track[ws.body];
  GenForce& F = d.force[ws.body];
  const ContactGeometry& geo = *ws.geometry;
  const bool full = model.wheelset_model == WheelsetModel::full;

  const RailPosition& rail = d.rail[std::size_t(w)];
  WheelsetKinematics k;
  k.V = d.V;
  k.Omega = d.V / geo.r0() + (ws.beta_state >= 0 ? x[ws.beta_state] : 0.0);
  k.kappa = T.curvature;
  k.y = m.q[kLat] - rail.lateral;
  k.ydot = m.v[kLat] - rail.lateral_rate;
  k.psi = m.q[kYaw];
  k.psidot = m.v[kYaw];
  k.phi = m.q[kRoll];  // full: state; lateral: kinematic roll (0 when switched off)
  k.phidot = m.v[kRoll];
  const double ymax = model.max_lateral_shift > 0 ? model.max_lateral_shift : geo.max_shift();
  if (!(std::abs(k.y) <= ymax) || !(std::abs(k.psi) <= geo.max_yaw())) {
    range_failure(model, d, w, k, ymax);
    return false;
  }

  // Geometry of both wheels, once: points with Hertz laws, or strips.
  const bool distributed = geo.distributed();
  WheelGeometry g[2];
  contact::StripSet* strips = d.strips.data();  // two, scratch
  double N[2][WheelGeometry::kMaxPoints] = {};
  double Qlat[2] = {0.0, 0.0};
  for (int i = 0; i < 2; ++i) {
    const int side = i == 0 ? 1 : -1;
    if (distributed) continue;  // strips fetched with the loads (distributed_loads)
    geo.evaluate(side * k.y, side * k.psi, g[i]);
    for (int p = 0; p < g[i].n; ++p) complete_point(g[i].p[p], ws.static_load[i], ws.hertz_q0[i]);
  }

  // Normal loads.
  if (distributed) {
    if (!distributed_loads(model, d, w, k, strips, g, N, Qlat)) return false;
  } else if (full) {
    RigidPose ref;
    if (!geo.reference_follows_shift()) geo.rigid_pose(k.y, k.psi, ref);
    for (int i = 0; i < 2; ++i) {
      const int side = i == 0 ? 1 : -1;
      const double dz0 = m.q[kVert] - rail.vertical[i] - ref.height;
      const double dz0_rate = m.v[kVert] - rail.vertical_rate[i] - ref.dheight_dy * k.ydot;
      const double cn = model.coupling.options().normal_damping;
      for (int p = 0; p < g[i].n; ++p) {
        const ContactPointGeometry& c = g[i].p[p];
        const double cd = std::cos(c.contact_angle);
        const double dz = dz0 + side * c.lateral * (k.phi - ref.roll);
        double Np = point_load(c, (ws.static_approach[i] - dz) * cd);
        if (cn > 0.0 && Np > 0.0) {  // viscous normal damping while in contact, never pulling
          const double rate = dz0_rate + side * c.lateral * (k.phidot - ref.droll_dy * k.ydot);
          Np = std::max(0.0, Np - c.weight * cn * rate * cd);
        }
        N[i][p] = Np;
      }
    }
  } else {
    // Quasi-static vertical equilibrium; lever arms from the load-weighted
    // lateral positions (two passes: main points, then the shared loads).
    const double S = -F[kVert];
    const double D = -F[kRoll] + geo.r0() * F[kLat];
    double a[2] = {g[0].p[0].lateral, g[1].p[0].lateral};
    const int passes = (g[0].n > 1 || g[1].n > 1) ? 2 : 1;
    for (int pass = 0; pass < passes; ++pass) {
      Qlat[0] = (S * a[1] + D) / (a[0] + a[1]);
      Qlat[1] = (S * a[0] - D) / (a[0] + a[1]);
      for (int i = 0; i < 2; ++i) {
        const int side = i == 0 ? 1 : -1;
        if (!(Qlat[i] > 0.0)) return lateral_loss_of_contact(d, ws, i, Qlat[i]);
        share_wheel_load(g[i], Qlat[i], side * k.phi, ws.static_load[i], ws.hertz_q0[i], N[i]);
        if (pass + 1 < passes) {
          double num = 0.0, den = 0.0;
          for (int p = 0; p < g[i].n; ++p) {
            const double v = N[i][p] * std::cos(g[i].p[p].contact_angle + side * k.phi);
            num += v * g[i].p[p].lateral;
            den += v;
          }
          if (den > 0.0) a[i] = num / den;
        }
      }
    }
  }

  // Creep forces, resolution, sums.
  const bool track_angles = geo.angles_in_track_frame();
  double Fy_sum = 0, Fz_sum = 0, Mx_sum = 0, Mz_sum = 0, My_sum = 0;
  for (int i = 0; i < 2; ++i) {
    const int side = i == 0 ? 1 : -1;
    if (full) {
      k.z = m.q[kVert] - rail.vertical[i];
      k.zdot = m.v[kVert] - rail.vertical_rate[i];
    }
    WheelOutput& out = d.wheel[2 * w + i];
    out = WheelOutput{};
    double Nmax = -1.0;
    bool valid = true;
    const char* reason = "";
    for (int p = 0; p < g[i].n; ++p) {
      const ContactPointGeometry& c = g[i].p[p];
      const double Np = N[i][p];
      if (p > 0 && !(Np > 0.0)) continue;  // open point
      const double cd = std::cos(c.contact_angle);
      const double a = c.lateral, r = c.rolling_radius;
      const contact::Creepages cr = wheel_creepages(k, c, side);
      PatchState* rec =  // the reporting evaluation keeps each loaded patch's input (contact audit)
          d.record_patches && Np > 1.0 ? &d.patch[(2 * w + i) * WheelGeometry::kMaxPoints + out.patches++] : nullptr;
      const contact::ContactForces cf = model.coupling.forces(c, Np, ws.static_load[i], cr, d.V,
                                                              d.workspace[2 * w + i].get(), rec ? &rec->input : nullptr);
      if (rec) rec->forces = cf, rec->point = p, rec->contact_angle = c.contact_angle;
      const double th = c.contact_angle + (track_angles ? 0.0 : side * k.phi);
      const double ct = std::cos(th), st = std::sin(th);
      const double X = cf.Fx - cf.Fy * k.psi * cd;
      const double Y = cf.Fx * k.psi + cf.Fy * ct - side * Np * st - side * c.flange_force;
      const double Z = side * cf.Fy * st + Np * ct;
      Fy_sum += Y;
      Fz_sum += Z;
      Mx_sum += side * a * Z + r * Y;
      Mz_sum += -side * a * (X + Y * k.psi) + c.lead * Y + cf.Mz * ct;
      My_sum += -r * (X + Y * k.psi);
      out.Q += Z;
      out.N += Np;
      out.Y += Y;
      out.Fx += cf.Fx;
      out.Fy += cf.Fy;
      out.Mz += cf.Mz;
      out.Tgamma += point_wear_number(cf, cr);
      if (Np > Nmax) {  // creepages and position of the most loaded point
        Nmax = Np;
        out.creep = cr;
        out.contact_y = m.q[kLat] + side * a;
        out.contact_angle = c.contact_angle;
        out.rolling_radius = r;
        out.contact_lead = c.lead;
      }
      if (!cf.valid) {
        valid = false;
        reason = cf.reason;
      }
    }
    if (!full) out.Q = Qlat[i];
    if (out.N > 10.0 * ws.static_load[i]) {  // no physics loads a wheel like this: the numerics broke down
      char buf[320];
      std::snprintf(buf, sizeof buf,
                    "wheelset '%s', %s wheel: normal load %.4g kN is more than ten times its static %.4g kN "
                    "[model: %s wheelset]: the contact or the integration broke down; reduce max_step or the "
                    "tolerances, or check the scenario",
                    ws.name.c_str(), i == 0 ? "left" : "right", out.N * 1e-3, ws.static_load[i] * 1e-3,
                    wheelset_model_name(model.wheelset_model));
      d.fail(buf);
      return false;
    }
    if (!(out.N > 0)) {
      valid = false;
      reason = "loss of contact (wheel lift)";
    }
    out.valid = valid;
    out.reason = reason;
    if (!valid) {  // counted per wheel
      if (d.invalid_contact_calls == 0) d.first_invalid_reason = reason;  // allocation only once
      ++d.invalid_contact_calls;
    }
  }
  WheelsetContactRecord inc;
  inc.lat = Fy_sum;
  inc.yaw = Mz_sum;
  inc.full = full;
  if (full) {
    const double Iy = body.inertia.y();
    inc.vert = Fz_sum;
    inc.roll = Mx_sum + Iy * k.Omega * (k.psidot + d.V * k.kappa);  // absolute yaw rate (frame turns at V kappa)
    inc.yaw_gyro = -Iy * k.Omega * k.phidot;
  }
  add_contact_forces(inc, F);
  if (ws.beta_state >= 0) xdot[ws.beta_state] = My_sum / body.inertia.y();
  if (d.record_contact) {  // kept for replay (data.hpp)
    WheelsetContactRecord& rec = d.contact_record[std::size_t(w)];
    rec = inc;
    rec.spin_rate = ws.beta_state >= 0 ? xdot[ws.beta_state] : 0.0;
    rec.wheel[0] = d.wheel[2 * std::size_t(w)];
    rec.wheel[1] = d.wheel[2 * std::size_t(w) + 1];
    rec.invalid_calls = d.invalid_contact_calls - invalid_before;
  }
  return true;
}

}  // namespace railsim::engine
