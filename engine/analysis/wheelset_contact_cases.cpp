// Wheelset-level contact for given poses; see wheelset_contact_cases.hpp.
#include "engine/analysis/wheelset_contact_cases.hpp"

#include <boost/math/tools/roots.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "contact/geometry/profile.hpp"
#include "contact/geometry/strip_contact_table.hpp"
#include "contact/hertz.hpp"
#include "core/errors.hpp"
#include "engine/wheel_rail/creepages.hpp"
#include "engine/wheel_rail/strip_patches.hpp"

namespace railsim::engine {

namespace {

constexpr double kStripGap = 0.6e-3;  // strips kept up to this normal gap [m] (loads stay far below)

std::string num(double v) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

}  // namespace

namespace {
// Where position k was given ("FILE:LINE: key 'positions[k]'", else "position k").
std::string where_of(const std::vector<WheelsetContactPosition>& positions, std::size_t k) {
  return positions[k].where.empty() ? "position " + std::to_string(k) : positions[k].where;
}

// One position: both wheels' contact points, normal loads and creep forces.
WheelsetContactResult solve_position(const WheelsetContactSetup& s, const contact::WheelRailGeometry& geo,
                                     const contact::TangentialModel& model, contact::TangentialWorkspace* ws,
                                     double Es, const WheelsetContactPosition& pos);
}  // namespace

std::vector<WheelsetContactResult> wheelset_contact(const WheelsetContactSetup& s,
                                                    const std::vector<WheelsetContactPosition>& positions) {
  if (!(s.speed > 0.0 && std::isfinite(s.speed))) throw InputError("wheelset contact: speed must be positive");
  if (!(s.strip >= 2e-5 && s.strip <= 2e-3))
    throw InputError("wheelset contact: strip width " + num(s.strip) + " m: expected a value in [2e-5, 2e-3] m");
  // A set-up error names the case file and the key (or the set-up as a whole).
  const std::string at = s.where.empty() ? std::string() : s.where + ": ";
  auto located = [&](const std::string& key, auto&& make) {
    try {
      return make();
    } catch (const InputError& e) {
      throw InputError(at + (key.empty() ? std::string() : "key '" + key + "': ") + e.what());
    }
  };
  const contact::Profile wheel =
      located("wheel", [&] { return contact::read_profile(s.wheel, contact::ProfileKind::wheel); });
  const contact::Profile rail =
      located("rail", [&] { return contact::read_profile(s.rail, contact::ProfileKind::rail); });
  located("", [&] { s.track.validate(); return 0; });
  const contact::WheelRailGeometry geo = located("", [&] { return contact::WheelRailGeometry(wheel, rail, s.track); });
  // The centred wheelset must sit on the rails: when it cannot, the set-up is
  // wrong (gauge, flange back, back face, a rail profile given as the wheel),
  // not the positions, which would each be blamed for it.
  try {
    (void)geo.solve(0.0, 0.0);
  } catch (const InputError& e) {
    throw InputError(at + "wheel " + s.wheel + " on rail " + s.rail + " with gauge " + num(s.track.gauge) +
                     " m, flange_back " + num(s.track.flange_back) + " m, back_face " + num(s.track.back_face) +
                     " m, inclination " + num(s.track.inclination) + " rad: the centred wheelset cannot sit on the "
                     "rails (" + e.what() + "): check the gauge and flange-back spacing and the profiles");
  }
  auto model = contact::make_tangential_model(s.model, s.model_options);
  auto ws = model->make_workspace();
  const double Es = s.material.combined_modulus();
  // The flange's steepest point: the largest contact angle of the left
  // wheel's rigid contact over the shift toward its flange at zero yaw (0.1 mm
  // steps up to where the search finds the flange tip); the right wheel is its
  // mirror image.
  double steepest = 0.0, y_steepest = 0.0;
  for (double y = 0.0; y <= 0.03; y += 1e-4) {
    contact::WheelsetContact c;
    try {
      c = geo.solve(y, 0.0);
    } catch (const InputError&) {
      break;
    }
    const double angle = c.wheel[std::size_t(contact::Side::left)].p[0].angle;
    if (angle > steepest) {
      steepest = angle;
      y_steepest = y;
    }
  }
  std::vector<WheelsetContactResult> out;
  for (std::size_t k = 0; k < positions.size(); ++k) {
    try {
      out.push_back(solve_position(s, geo, *model, ws.get(), Es, positions[k]));
      WheelsetContactResult& r = out.back();
      for (int i = 0; i < 2; ++i) {
        const double sg = i == 0 ? 1.0 : -1.0;
        double flange = 0.0;  // the steepest flange-side angle of the wheel's patches
        for (const auto& P : r.wheel[i].patches) flange = std::max(flange, sg * P.contact_angle);
        constexpr double kDeg = M_PI / 180.0;
        if (sg * r.position.y > y_steepest + 1e-4 && flange < steepest - 0.5 * kDeg) {
          r.wheel[i].climbing = true;
          r.warnings.push_back(where_of(positions, k) + ": the " + (i == 0 ? "left" : "right") +
                               " wheel is climbing its flange: shifted " + num(std::abs(r.position.y) * 1e3) +
                               " mm, past the flange's steepest point (" + num(steepest / kDeg) + " deg at " +
                               num(y_steepest * 1e3) + " mm, zero yaw), it touches at " + num(flange / kDeg) +
                               " deg (Nadal's limit falls with the angle: a running wheelset derails here)");
        }
        // A patch the tangential model solved outside its validity domain (the
        // model's own flag: mim_table's a/b held at the table's edge, MIM not
        // converged, large spin for CHOPAYA, ...): its forces may be far off.
        std::string flagged;
        for (std::size_t j = 0; j < r.wheel[i].patches.size(); ++j) {
          const WheelsetContactPatch& P = r.wheel[i].patches[j];
          if (P.forces.valid) continue;
          flagged += std::string(flagged.empty() ? "" : "; ") + "patch " + std::to_string(j + 1) + " (N = " +
                     num(P.N) + " N, a/b = " + num(P.b > 0.0 ? P.a / P.b : NAN) + "): " + P.forces.reason;
        }
        if (!flagged.empty())
          r.warnings.push_back(where_of(positions, k) + ": the " + (i == 0 ? "left" : "right") + " wheel's forces " +
                               "are outside the validity domain of model " + s.model + ": " + flagged);
      }
    } catch (const InputError& e) {  // a position outside what the geometry can solve (e.g. on the flange tip)
      throw InputError(where_of(positions, k) + ": " + e.what());
    } catch (const NumericalError& e) {  // a solver that did not converge: numerical, named the same way
      throw NumericalError(where_of(positions, k) + ": " + e.what());
    }
  }
  return out;
}

namespace {

WheelsetContactResult solve_position(const WheelsetContactSetup& s, const contact::WheelRailGeometry& geo,
                                     const contact::TangentialModel& model, contact::TangentialWorkspace* ws,
                                     double Es, const WheelsetContactPosition& pos) {
  {
    // At least 1 N (as the case file's range): 1e-6 N gave a 37 nm patch
    // (a/b 200) that took MIM 39 s and 730 MB.
    if (!(pos.Fz >= 1.0 && pos.Fz <= 1e6))
      throw InputError("wheelset contact: position y = " + num(pos.y) + " m: Fz " + num(pos.Fz) +
                       " N: expected a value in [1, 1e6] N per wheel");
    WheelsetContactResult r;
    r.position = pos;
    const contact::WheelsetContact c = pos.has_roll ? geo.at_roll(pos.y, pos.yaw, pos.roll) : geo.solve(pos.y, pos.yaw);
    r.roll = c.roll;
    // Strips of each wheel at its touching height (engine sign of the angle:
    // > 0 tilts the normal toward the track centre); they do not depend on
    // the rolling speed, so a free axle's search reuses them.
    contact::StripSet sets[2];
    for (int i = 0; i < 2; ++i) {
      const contact::Side side = i == 0 ? contact::Side::left : contact::Side::right;
      const double sg = i == 0 ? 1.0 : -1.0;
      contact::StripSet& set = sets[i];
      set.width = s.strip;
      int index = 0;
      for (double t = geo.wheel_t_min(); t <= geo.wheel_t_max(); t += s.strip, ++index) {
        const contact::ContactPoint p = geo.point_at(side, t, pos.y, c.z[std::size_t(i)], c.roll, pos.yaw);
        if (!(std::isfinite(p.gap) && p.gap < kStripGap)) continue;
        if (set.n == contact::StripSet::kMax)
          throw InputError("wheelset contact: more than " + std::to_string(contact::StripSet::kMax) +
                           " strips near the contact at y = " + num(pos.y) + " m: use a wider strip (option strip)");
        contact::StripPoint q;
        q.index = index;
        q.gap = std::max(0.0, p.gap);
        q.angle = sg * p.angle;
        q.lateral = sg * (p.y - pos.y);
        q.lead = p.x * std::cos(pos.yaw) + (p.y - pos.y) * std::sin(pos.yaw);  // wheelset frame
        q.height = p.height;
        q.A = p.A;
        q.f = contact::StripContactTable::winkler_factor(p.B / p.A);
        q.y_wheel = p.y_wheel;
        set.add(q);
      }
      if (set.n == 0)
        throw InputError("wheelset contact: y = " + num(pos.y) + " m, yaw = " + num(pos.yaw) + " rad: the " +
                         (i == 0 ? "left" : "right") + " wheel does not meet its rail");
    }
    // Both wheels' patches and forces with the axle rolling at Omega.
    auto solve_wheels = [&](double Omega) {
      r.omega = Omega;
      for (int i = 0; i < 2; ++i) {
        const double sg = i == 0 ? 1.0 : -1.0;
        const contact::StripSet& set = sets[i];
        // The wheelset rolling steadily (no rates).
        WheelsetKinematics k;
        k.V = s.speed;
        k.Omega = Omega;
        k.y = pos.y;
        k.psi = pos.yaw;
        k.phi = c.roll;
        // The wheel's patches, creep forces and total force on the rail when the
        // normal loads' vertical components add up to Qn.
        auto wheel_forces = [&](double Qn, WheelsetContactWheel& W) {
          StripLoads L;
          W = WheelsetContactWheel{};
          W.approach = strip_approach_for_load(set, Qn, 0.0, Es, L);
          double X = 0, Y = 0, Z = 0;
          for (int p = 0; p < L.n; ++p) {
            WheelsetContactPatch P;
            ContactPointGeometry g = L.patch[p];
            P.N = L.N[p];
            P.contact_angle = sg * g.contact_angle;  // track frame: the right wheel's flange < 0, as `railsim geometry`
            P.rolling_radius = g.rolling_radius;
            P.a = g.semi_a;
            P.b = g.semi_b;
            P.y_track = pos.y + sg * g.lateral;
            P.x_track = g.lead * std::cos(pos.yaw) - sg * g.lateral * std::sin(pos.yaw);  // back to the track frame
            // The profile positions of the patch centre: the strip nearest to its lateral position.
            double best = 1e9;
            for (int j = 0; j < set.n; ++j)
              if (std::abs(set.lateral[j] - g.lateral) < best) {
                best = std::abs(set.lateral[j] - g.lateral);
                P.y_wheel = set.y_wheel[j];
              }
            P.y_rail = sg * P.y_track - geo.rail_offset();  // placed (inclined) rail profile, field side positive
            P.creep = wheel_creepages(k, g, int(sg));
            contact::ContactInput in;
            if (P.a > 0 && P.b > 0) in.patch = contact::hertz_from_semi_axes(P.a, P.b, P.N, s.material);
            in.patch.Fz = P.N;
            in.creep = P.creep;
            in.material = s.material;
            in.rolling_speed = s.speed;
            P.forces = model.solve(in, ws);
            const double ct = std::cos(g.contact_angle), st = std::sin(g.contact_angle);
            X += P.forces.Fx - P.forces.Fy * pos.yaw * ct;
            Y += P.forces.Fx * pos.yaw + P.forces.Fy * ct - sg * P.N * st;
            Z += sg * P.forces.Fy * st + P.N * ct;
            W.patches.push_back(P);
          }
          W.Fx = -X;  // the wheel on the rail
          W.Fy = -Y;
          W.Fz = -Z;
        };
        // The prescribed Fz is the wheel's total vertical force, creep forces
        // included (as in CONTACT's wheelset problems): in flange contact the
        // lateral creep force carries a large part of it (mu tan(delta) of the
        // normal part at 66 deg), so the normal part is found by the secant
        // method on Z(Qn) - Fz, from Qn = Fz.
        WheelsetContactWheel& W = r.wheel[i];
        double q0 = pos.Fz;
        wheel_forces(q0, W);
        double g0 = -W.Fz - pos.Fz;
        double q1 = std::max(0.05 * pos.Fz, pos.Fz - g0);
        bool converged = std::abs(g0) <= 1e-9 * pos.Fz;
        for (int it = 0; it < 50 && !converged; ++it) {
          wheel_forces(q1, W);
          const double g1 = -W.Fz - pos.Fz;
          if (std::abs(g1) <= 1e-9 * pos.Fz) {
            converged = true;
            break;
          }
          double q2 = (g1 != g0) ? q1 - g1 * (q1 - q0) / (g1 - g0) : q1 - g1;
          q2 = std::clamp(q2, 0.5 * q1, 2.0 * q1);  // keep the normal part positive and the step bounded
          q0 = q1;
          g0 = g1;
          q1 = q2;
        }
        if (!converged) {
          // Self-locking flange: the vertical force of a patch is N (cos(delta) - (|Fy| / N) sin(delta)) with
          // |Fy| <= mu N, so for mu < cot(delta) it grows with N past any Fz; at mu >= cot(delta) (0.36 at
          // 70 deg) a lateral creep force pulling the wheel down the flange can outweigh the normal force's
          // lift at every N, and no normal load carries Fz (mu 1 at 66.7 deg, found by a probe). The pose
          // has no solution with this friction: an input error naming mu and the range that always solves.
          double delta = 0.0;  // the steepest patch of the wheel (engine sign: > 0 on the flange)
          for (const auto& P : W.patches) delta = std::max(delta, sg * P.contact_angle);
          const double mu = s.material.mu;
          if (delta > 0.0 && mu * std::tan(delta) >= 1.0 && -W.Fz < pos.Fz)  // short of Fz: held down
            throw InputError("wheelset contact: y = " + num(pos.y) + " m, yaw = " + num(pos.yaw) + " rad: the " +
                             (i == 0 ? "left" : "right") + " wheel's vertical force " + num(pos.Fz) +
                             " N is not reached: its flange contact at " + num(delta * 180.0 / M_PI) +
                             " deg is self-locking with key 'material.mu' " + num(mu) +
                             " (the lateral creep force pulls the wheel down the flange more than the normal "
                             "force lifts it, at any normal load); a contact of this angle carries any load for mu "
                             "in (0, " + num(1.0 / std::tan(delta)) + ") (cot of the angle), or change the "
                             "position's yaw");
          throw NumericalError("wheelset contact: y = " + num(pos.y) + " m, yaw = " + num(pos.yaw) + " rad: the " +
                               (i == 0 ? "left" : "right") + " wheel's vertical force " + num(pos.Fz) +
                               " N is not reached (the normal-load iteration did not converge)");
        }
      }
    };
    const double nominal = pos.has_omega ? pos.omega : s.speed / s.track.r0;
    if (!pos.free_rolling) {
      solve_wheels(nominal);
      return r;
    }
    // A free axle: no torque about it from the creep forces, sum Fx r = 0 over
    // every patch of both wheels (the vehicle models' free axle rotation,
    // engine/model.hpp). The torque rises with Omega (xi falls); within
    // +-10 % of V / r0 every patch slides fully one way or the other.
    auto torque = [&](double Omega) {
      solve_wheels(Omega);
      double t = 0.0;
      for (const auto& w : r.wheel)
        for (const auto& P : w.patches) t += P.forces.Fx * P.rolling_radius;
      return t;
    };
    const double lo = 0.9 * nominal, hi = 1.1 * nominal;
    const double tlo = torque(lo), thi = torque(hi);
    if (!(tlo < 0.0 && thi > 0.0))
      throw NumericalError("wheelset contact: y = " + num(pos.y) + " m, yaw = " + num(pos.yaw) +
                           " rad: no free-rolling speed within +-10 % of V / r0 (axle torque of the creep forces " +
                           num(tlo) + " .. " + num(thi) + " N m)");
    std::uintmax_t iters = 60;
    const auto root = boost::math::tools::toms748_solve(torque, lo, hi, tlo, thi,
                                                        boost::math::tools::eps_tolerance<double>(40), iters);
    solve_wheels(0.5 * (root.first + root.second));
    return r;
  }
}

}  // namespace

}  // namespace railsim::engine
