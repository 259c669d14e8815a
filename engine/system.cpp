// System assembly and right-hand side; see system.hpp.
#include "engine/system.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>

#include "core/errors.hpp"
#include "engine/wheel_rail/strip_patches.hpp"
#include "engine/wheel_rail/track_flexibility.hpp"
#include "engine/wheel_rail/wheelset_contact.hpp"

namespace railsim::engine {
namespace {

// Elements between two bodies act on the motions in the common reference frame
// (Data::vehicle_motion); an element attached to the track (body -1) acts on the
// body's motion relative to its own track frame.
template <class Element>
const std::vector<BodyMotion>& element_motion(const Element& e, const Data& d) {
  return e.body_a < 0 || e.body_b < 0 ? d.motion : d.vehicle_motion;
}

void element_forces(const Model& model, Data& d, const double* x, double* xdot) {
  for (const auto& e : model.springs) apply_spring_damper(e, element_motion(e, d), d.force);
  for (const auto& e : model.bump_stops) apply_bump_stop(e, element_motion(e, d), d.force);
  for (const auto& e : model.anti_roll_bars) apply_anti_roll_bar(e, element_motion(e, d), d.force);
  for (const auto& e : model.yaw_dampers) {
    const double rate = apply_yaw_damper(e, x ? x[e.state] : 0.0, element_motion(e, d), d.force);
    if (xdot) xdot[e.state] = rate;
  }
}

void assign_states(Model& model) {
  int n = 0;
  model.state_names.clear();
  for (auto& b : model.bodies) {
    for (int k = 0; k < kNumDof; ++k)
      if (b.active[k]) {
        b.q_index[k] = n++;
        model.state_names.push_back(b.name + "." + dof_name(k));
      }
    for (int k = 0; k < kNumDof; ++k)
      if (b.active[k]) {
        b.v_index[k] = n++;
        model.state_names.push_back(b.name + "." + dof_name(k) + "_rate");
      }
    if (b.wheelset >= 0 && (model.wheelset_model == WheelsetModel::full || model.free_axle_rotation)) {
      model.wheelsets[b.wheelset].beta_state = n++;
      model.state_names.push_back(b.name + ".spin_perturbation");
    }
  }
  for (auto& e : model.yaw_dampers) {
    e.state = n++;
    model.state_names.push_back(e.name + ".damper_elongation");
  }
  // Flexible track (wheel_rail/track_flexibility.hpp): position and rate of
  // the track's lateral mass per wheelset and of each rail's vertical mass
  // (full wheelset model only: the lateral model's loads are quasi-static).
  const TrackFlexibility& tf = model.track_flexibility;
  for (auto& w : model.wheelsets) {
    w.track_lateral_state = w.rail_vertical_state[0] = w.rail_vertical_state[1] = -1;
    if (tf.lateral.active) {
      w.track_lateral_state = n;
      n += 2;
      model.state_names.push_back(w.name + ".track_lateral");
      model.state_names.push_back(w.name + ".track_lateral_rate");
    }
    if (tf.vertical.active && model.wheelset_model == WheelsetModel::full)
      for (int i = 0; i < 2; ++i) {
        w.rail_vertical_state[i] = n;
        n += 2;
        const std::string rail = w.name + (i == 0 ? ".left" : ".right") + "_rail_vertical";
        model.state_names.push_back(rail);
        model.state_names.push_back(rail + "_rate");
      }
  }
  model.n_states = n;
}

}  // namespace

void finalize_model(Model& model) {
  if (!model.track) throw InputError("model '" + model.vehicle_name + "': no track");
  for (auto& w : model.wheelsets)
    if (!w.geometry) throw InputError("wheelset '" + w.name + "': no contact geometry");
  if (model.wheelset_model == WheelsetModel::full)
    for (auto& w : model.wheelsets) {
      auto& b = model.bodies[w.body];
      b.active = {true, true, true, false, true};
    }
  assign_states(model);

  // --- static equilibrium of the suspension (linear statics) -----------------
  // Free DOFs: the active DOFs of every body that is not a wheelset.
  std::vector<std::pair<int, int>> free;
  for (std::size_t b = 0; b < model.bodies.size(); ++b)
    if (model.bodies[b].wheelset < 0)
      for (int k = 0; k < kNumDof; ++k)
        if (model.bodies[b].active[k]) free.emplace_back(int(b), k);
  for (auto& e : model.springs) e.preload.setZero();
  Data d(model);
  const int nf = static_cast<int>(free.size());
  Eigen::VectorXd qstar = Eigen::VectorXd::Zero(nf);
  if (nf > 0) {
    Eigen::MatrixXd K(nf, nf);
    Eigen::VectorXd Fg(nf);
    auto forces_at = [&](const Eigen::VectorXd& q, Eigen::VectorXd& out) {
      for (auto& m : d.motion) m = BodyMotion{};
      for (auto& f : d.force) f.fill(0.0);
      for (int j = 0; j < nf; ++j) d.motion[free[j].first].q[free[j].second] = q[j];
      for (const auto& e : model.springs) apply_spring_damper(e, d.motion, d.force);
      for (const auto& e : model.anti_roll_bars) apply_anti_roll_bar(e, d.motion, d.force);
      for (int j = 0; j < nf; ++j) out[j] = d.force[free[j].first][free[j].second];
    };
    Eigen::VectorXd q = Eigen::VectorXd::Zero(nf), col(nf);
    for (int j = 0; j < nf; ++j) {
      q.setZero();
      q[j] = 1.0;
      forces_at(q, col);
      K.col(j) = -col;
    }
    Fg.setZero();
    for (int j = 0; j < nf; ++j)
      if (free[j].second == kVert) Fg[j] = -model.bodies[free[j].first].mass * kGravity;
    Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(K);
    qstar = cod.solve(Fg);
    const double res = (K * qstar - Fg).norm();
    if (!(res <= 1e-6 * (Fg.norm() + 1.0))) {
      std::string names;
      for (int j = 0; j < nf; ++j)
        if (free[j].second == kVert) names += (names.empty() ? "" : ", ") + model.bodies[free[j].first].name;
      throw InputError("vehicle '" + model.vehicle_name +
                       "': the suspension cannot carry the weight (no static equilibrium; check the vertical "
                       "springs of: " + names + ")");
    }
  }
  // Preloads: the element forces at the equilibrium configuration.
  for (auto& m : d.motion) m = BodyMotion{};
  for (int j = 0; j < nf; ++j) d.motion[free[j].first].q[free[j].second] = qstar[j];
  for (auto& e : model.springs) {
    Eigen::Vector3d dd, vv;
    relative_motion(d.motion, e.body_a, e.r_a, e.body_b, e.r_b, dd, vv);
    e.preload = -e.k.cwiseProduct(dd);
  }
  // Anti-roll bars carry no static moment on a symmetric vehicle; a residual
  // roll moment from an asymmetric layout is left to the springs.

  // Static wheel loads: forces on each wheelset at x = 0.
  for (auto& m : d.motion) m = BodyMotion{};
  for (auto& f : d.force) f.fill(0.0);
  for (const auto& e : model.springs) apply_spring_damper(e, d.motion, d.force);
  for (auto& w : model.wheelsets) {
    const auto& b = model.bodies[w.body];
    GenForce F = d.force[w.body];
    F[kVert] -= b.mass * kGravity;
    ContactPointGeometry c[2];
    c[0] = c[1] = w.geometry->main_point(0.0);
    const double S = -F[kVert], D = -F[kRoll] + w.geometry->r0() * F[kLat];
    const double aL = c[0].lateral, aR = c[1].lateral;
    const double Q[2] = {(S * aR + D) / (aL + aR), (S * aL - D) / (aL + aR)};
    for (int i = 0; i < 2; ++i) {
      if (!(Q[i] > 0))
        throw InputError("vehicle '" + model.vehicle_name + "': wheelset '" + w.name +
                         "' has no positive static wheel load");
      w.static_load[i] = Q[i] / std::cos(c[i].contact_angle);
      w.static_vertical_load[i] = Q[i];
    }
    // Vertical approach that carries the static load (full model), from the
    // geometry's own load law at the centred position.
    for (int i = 0; i < 2; ++i) {
      if (w.geometry->distributed()) {
        contact::StripSet s;
        w.geometry->strips(0.0, 0.0, 1.5e-3, s);
        StripLoads L;
        w.static_approach[i] = strip_approach_for_load(s, Q[i], 0.0, w.geometry->contact_modulus(), L);
        continue;
      }
      WheelGeometry g;
      w.geometry->evaluate(0.0, 0.0, g);
      double N[WheelGeometry::kMaxPoints];
      w.static_approach[i] = share_wheel_load(g, Q[i], 0.0, w.static_load[i], w.hertz_q0[i], N);
    }
  }
  model.finalized = true;
}

bool rhs(const Model& model, Data& d, double t, const double* x, double* xdot) {
  ++d.rhs_calls;
  d.failed = d.derailed = d.left_range = false;  // a failure belongs to this evaluation only (trial steps may be rejected)
  d.t = t;
  d.V = model.speed.speed(t);
  d.s = model.speed.distance(t);
  const std::size_t nb = model.bodies.size();
  for (std::size_t b = 0; b < nb; ++b) {
    const RigidBody& body = model.bodies[b];
    BodyMotion& m = d.motion[b];
    for (int k = 0; k < kNumDof; ++k) {
      m.q[k] = body.q_index[k] >= 0 ? x[body.q_index[k]] : 0.0;
      m.v[k] = body.v_index[k] >= 0 ? x[body.v_index[k]] : 0.0;
    }
    GenForce& f = d.force[b];
    f.fill(0.0);
    if (body.wheelset >= 0) model.track->sample(d.s + body.position.x(), d.track[b]);
    else model.track->sample_alignment(d.s + body.position.x(), d.track[b]);
    const FrameLoads L = frame_loads(d.track[b], d.V, body.mass, body.inertia.z());
    f[kLat] += L.Fy;
    f[kVert] += L.Fz;
    f[kYaw] += L.Mz;
  }
  rail_positions(model, d, x);
  if (model.wheelset_model == WheelsetModel::lateral)
    for (std::size_t w = 0; w < model.wheelsets.size(); ++w) wheelset_kinematics(model, d, int(w));
  model.track->sample_alignment(d.s, d.reference);
  for (std::size_t b = 0; b < nb; ++b) {
    const RigidBody& body = model.bodies[b];
    const BodyMotion off = frame_offset(d.reference, d.track[b], body.position.y(), body.position.z(), d.V);
    BodyMotion& vm = d.vehicle_motion[b];
    for (int k = 0; k < kNumDof; ++k) {
      vm.q[k] = d.motion[b].q[k] + off.q[k];
      vm.v[k] = d.motion[b].v[k] + off.v[k];
    }
  }
  element_forces(model, d, x, xdot);
  for (std::size_t w = 0; w < model.wheelsets.size(); ++w) {
    const Wheelset& ws = model.wheelsets[w];
    if (d.reuse_contact && d.reuse_contact[w]) {  // replay (data.hpp): the same contribution, the same bits
      const WheelsetContactRecord& rec = d.contact_record[w];
      add_contact_forces(rec, d.force[ws.body]);
      if (ws.beta_state >= 0) xdot[ws.beta_state] = rec.spin_rate;
      d.wheel[2 * w] = rec.wheel[0];
      d.wheel[2 * w + 1] = rec.wheel[1];
      if (rec.invalid_calls > 0 && d.invalid_contact_calls == 0)
        d.first_invalid_reason = rec.wheel[0].valid ? rec.wheel[1].reason : rec.wheel[0].reason;
      d.invalid_contact_calls += rec.invalid_calls;
    } else if (!wheelset_forces(model, d, int(w), x, xdot)) {
      return false;
    }
    track_flexibility_rates(model, d, int(w), x, xdot);
  }
  for (std::size_t b = 0; b < nb; ++b) {
    const RigidBody& body = model.bodies[b];
    for (int k = 0; k < kNumDof; ++k) {
      if (body.q_index[k] < 0) continue;
      xdot[body.q_index[k]] = x[body.v_index[k]];
      xdot[body.v_index[k]] = d.force[b][k] / body.generalised_mass(k);
    }
  }
  for (int i = 0; i < model.n_states; ++i)
    if (!std::isfinite(xdot[i])) {
      char buf[256];
      std::snprintf(buf, sizeof buf, "non-finite derivative of state '%s' (state value %g)",
                    model.state_names[i].c_str(), x[i]);
      d.fail(buf);
      return false;
    }
  return true;
}

void rhs_or_throw(const Model& model, Data& d, double t, const double* x, double* xdot) {
  if (!rhs(model, d, t, x, xdot)) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "t = %.6g s, s = %.6g m: ", t, model.speed.distance(t));
    throw NumericalError(std::string(buf) + d.failure + " (vehicle '" + model.vehicle_name + "')");
  }
}

}  // namespace railsim::engine

namespace railsim::engine {

ModelOde::ModelOde(const Model& model, Data& data)
    : model_(model), data_(data), pattern_(jacobian_pattern(model)), xp_(model.n_states), fp_(model.n_states),
      h_(model.n_states), recorded_x_(model.n_states), recorded_warm_(data.approach_warm_start),
      latest_warm_(data.approach_warm_start), f0_(model.n_states) {
  // The states a wheelset's contact reads: its own (positions, rates, spin
  // perturbation) and its track's; in the lateral model also every state the
  // forces of the elements on the wheelset read (its wheel loads follow from
  // them): the columns with a nonzero in the wheelset's rate rows. A colour
  // that perturbs none of them can take the wheelset's recorded contact.
  const JacobianPattern& p = pattern_;
  const std::size_t nw = model.wheelsets.size();
  reuse_.assign(std::size_t(p.colors) * nw, 1);
  std::vector<char> reads(std::size_t(model.n_states));
  for (std::size_t w = 0; w < nw; ++w) {
    const Wheelset& ws = model.wheelsets[w];
    const RigidBody& b = model.bodies[std::size_t(ws.body)];
    std::fill(reads.begin(), reads.end(), 0);
    for (int k = 0; k < kNumDof; ++k)
      for (int i : {b.q_index[k], b.v_index[k]})
        if (i >= 0) reads[std::size_t(i)] = 1;
    if (ws.beta_state >= 0) reads[std::size_t(ws.beta_state)] = 1;
    for (int i : ws.track_states())
      if (i >= 0) reads[std::size_t(i)] = reads[std::size_t(i) + 1] = 1;
    if (model.wheelset_model == WheelsetModel::lateral)
      for (int j = 0; j < p.n; ++j)
        for (int k = p.colptr[std::size_t(j)]; k < p.colptr[std::size_t(j) + 1]; ++k)
          for (int dof = 0; dof < kNumDof; ++dof)
            if (b.v_index[dof] >= 0 && p.rowind[std::size_t(k)] == b.v_index[dof]) reads[std::size_t(j)] = 1;
    for (int j = 0; j < p.n; ++j)
      if (reads[std::size_t(j)]) reuse_[std::size_t(p.color[std::size_t(j)]) * nw + w] = 0;
  }
}

bool ModelOde::rhs(double t, const double* x, double* xdot) {
  recorded_warm_ = data_.approach_warm_start;  // (the same size: no allocation)
  data_.record_contact = true;
  recorded_ = engine::rhs(model_, data_, t, x, xdot);
  data_.record_contact = false;
  if (recorded_) {
    recorded_t_ = t;
    std::copy(x, x + model_.n_states, recorded_x_.begin());
  }
  return recorded_;
}

std::string ModelOde::failure_message() const {
  char buf[96];
  std::snprintf(buf, sizeof buf, "t = %.6g s, s = %.6g m: ", data_.t, data_.s);
  return std::string(buf) + data_.failure + " (vehicle '" + model_.vehicle_name + "', " +
         wheelset_model_name(model_.wheelset_model) + " wheelset model)";
}

void ModelOde::tolerances(const IntegratorOptions& o, double* atol) const {
  OdeSystem::tolerances(o, atol);
  // Flexible track: a rate's tolerance is the position's times the mass's
  // angular frequency on its support (the rate error that moves the mass by
  // atol in 1/omega). At atol itself (1e-7 m/s) the rails' vertical rates led
  // the coach's local error on curve_twist (90 %, CVODE's estimates; full
  // model) and the run took 18.1k steps, ws1's Q, Y, Y/Q within 4.6 / 4.0 /
  // 2.3 % of their range of a run at rtol 1e-6 / atol 1e-9; with this 13.2k
  // steps and 0.3 / 0.2 / 0.1 %.
  const TrackFlexibility& tf = model_.track_flexibility;
  for (const auto& w : model_.wheelsets) {
    const auto track = w.track_states();
    for (std::size_t k = 0; k < track.size(); ++k) {
      const TrackSupport& t = k == 0 ? tf.lateral : tf.vertical;
      if (track[k] >= 0) atol[track[k] + 1] = atol[track[k]] * std::sqrt(t.stiffness / t.mass);
    }
  }
  if (!(o.atol_contact_modes > 0.0)) return;
  for (const auto& w : model_.wheelsets) {
    const RigidBody& b = model_.bodies[w.body];
    for (int k : {kVert, kRoll})
      if (b.v_index[k] >= 0) atol[b.v_index[k]] = o.atol_contact_modes;
    if (w.beta_state >= 0) atol[w.beta_state] = o.atol_contact_modes;
  }
}

template <class Put>
bool ModelOde::coloured_differences(double t, const double* x, const double* fx, Put put) {
  const int n = model_.n_states;
  const JacobianPattern& p = pattern_;
  for (int j = 0; j < n; ++j) h_[std::size_t(j)] = 1e-7 * std::max(1.0, std::abs(x[j])) + 1e-9;
  // Each colour solves again only the contacts of the wheelsets whose states
  // it perturbs; the others replay the evaluation at (t, x) (the integrator's
  // last one, as a rule; else it is made here, and the differences are taken
  // from it). Every colour's contact solves start from the warm starts the
  // recorded evaluation started from (Data::approach_warm_start), so that the
  // differences are those of one function of the state, to the bit; the
  // latest warm starts are restored after.
  const double* f0 = fx;
  if (!(recorded_ && t == recorded_t_ && std::equal(x, x + n, recorded_x_.begin()))) {
    if (!rhs(t, x, f0_.data())) return false;
    f0 = f0_.data();
  }
  latest_warm_ = data_.approach_warm_start;
  struct RestoreWarmStarts {
    Data& d;
    const std::vector<double>& latest;
    ~RestoreWarmStarts() { d.approach_warm_start = latest; }
  } restore{data_, latest_warm_};
  const std::size_t nw = model_.wheelsets.size();
  for (int c = 0; c < p.colors; ++c) {
    std::copy(x, x + n, xp_.begin());
    bool any = false;
    for (int j = 0; j < n; ++j)
      if (p.color[std::size_t(j)] == c) {
        xp_[std::size_t(j)] = x[j] + h_[std::size_t(j)];
        any = true;
      }
    if (!any) continue;
    data_.reuse_contact = &reuse_[std::size_t(c) * nw];
    data_.approach_warm_start = recorded_warm_;
    const bool ok = engine::rhs(model_, data_, t, xp_.data(), fp_.data());
    data_.reuse_contact = nullptr;
    if (!ok) return false;
    for (int j = 0; j < n; ++j) {
      if (p.color[std::size_t(j)] != c) continue;
      for (int k = p.colptr[std::size_t(j)]; k < p.colptr[std::size_t(j) + 1]; ++k) {
        const int i = p.rowind[std::size_t(k)];
        const double v = p.kinematic_row[std::size_t(i)] ? (p.kinematic_col[std::size_t(i)] == j ? 1.0 : 0.0)
                                                         : (fp_[std::size_t(i)] - f0[i]) / h_[std::size_t(j)];
        put(k, i, j, v);
      }
    }
  }
  return true;
}

bool ModelOde::jacobian(double t, const double* x, const double* fx, double* J) {
  const std::size_t n = std::size_t(model_.n_states);
  std::fill(J, J + n * n, 0.0);
  return coloured_differences(t, x, fx, [&](int, int i, int j, double v) { J[std::size_t(i) + std::size_t(j) * n] = v; });
}

bool ModelOde::pattern(std::vector<int>& colptr, std::vector<int>& rowind) const {
  colptr = pattern_.colptr;
  rowind = pattern_.rowind;
  return true;
}

bool ModelOde::sparse_jacobian(double t, const double* x, const double* fx, double* values) {
  return coloured_differences(t, x, fx, [&](int k, int, int, double v) { values[k] = v; });
}

}  // namespace railsim::engine
