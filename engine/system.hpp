// System assembly: the right-hand side x' = f(t, x) of a Model.
//
// f: unpack the state into body motions, add for every body the track-frame
// inertial and gravity loads (track_frame.hpp), every force element
// (spring_damper, bump_stop, yaw_damper, anti_roll_bar) and the wheel-rail
// forces of every wheelset (wheelset_lateral.hpp / wheelset_full.hpp), then
// divide by the generalised masses (diagonal inertia in track axes).
// Elements between two bodies act on the motions expressed in the track frame
// at the vehicle reference distance (Data::vehicle_motion: own motion plus
// the offset of the body's track frame, track_frame.hpp frame_offset), so that
// in curves they see the change of heading, versine and cant between bodies;
// elements to the track act on the body's motion in its own frame.
//
// finalize_model() assigns the state indices, computes the static
// equilibrium of the suspension under gravity (linear statics, K q = F_g, with
// the wheelsets resting on the rails), stores the spring preloads that hold
// that equilibrium and the static wheel loads. After it, x = 0 is the
// equilibrium on straight, level, perfect track.
#pragma once

#include "engine/data.hpp"
#include "engine/model.hpp"

namespace railsim::engine {

void finalize_model(Model& model);

// Evaluate f; false (with data.failure set) when the physics broke down
// (NaN, wheel lift-off, lateral shift beyond the geometry). No allocation.
bool rhs(const Model& model, Data& data, double t, const double* x, double* xdot);

// Same, throwing NumericalError on failure.
void rhs_or_throw(const Model& model, Data& data, double t, const double* x, double* xdot);

}  // namespace railsim::engine

#include "engine/integrators/integrator.hpp"
#include "engine/integrators/jacobian_pattern.hpp"

namespace railsim::engine {

// A Model + Data as the ODE seen by the integrators. The assembled Jacobian
// uses the exact kinematic rows (d(dq/dt)/dv = I) and forward differences of
// the force rows, one right-hand side per colour of the model's sparsity
// pattern (jacobian_pattern.hpp), dense or in the pattern's CSC order.
class ModelOde final : public OdeSystem {
 public:
  ModelOde(const Model& model, Data& data);
  int size() const override { return model_.n_states; }
  bool rhs(double t, const double* x, double* xdot) override;
  std::string failure_message() const override;
  bool jacobian(double t, const double* x, const double* fx, double* J) override;
  void tolerances(const IntegratorOptions& options, double* atol) const override;
  bool pattern(std::vector<int>& colptr, std::vector<int>& rowind) const override;
  bool sparse_jacobian(double t, const double* x, const double* fx, double* values) override;
  const JacobianPattern& sparsity() const { return pattern_; }

 private:
  // Colour by colour: perturb, evaluate, and hand each column's rows to `put(k, value)`
  // (k the nonzero's index in the pattern).
  template <class Put>
  bool coloured_differences(double t, const double* x, const double* fx, Put put);
  const Model& model_;
  Data& data_;
  JacobianPattern pattern_;
  std::vector<double> xp_, fp_, h_;
  // Contact replay (Data::reuse_contact): reuse_[c * wheelsets + w] = 1 when
  // colour c perturbs no state wheelset w's contact reads; the evaluation the
  // records belong to (the last rhs() that succeeded).
  std::vector<unsigned char> reuse_;
  bool recorded_ = false;
  double recorded_t_ = 0.0;
  std::vector<double> recorded_x_;
  // Data::approach_warm_start before the recorded evaluation (every colour's
  // solves start there, as the recorded one did: the differences are then
  // those of one function of the state) and the latest (restored after).
  std::vector<double> recorded_warm_, latest_warm_;
  std::vector<double> f0_;  // the evaluation at (t, x) when made here
};

}  // namespace railsim::engine
