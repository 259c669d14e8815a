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

#include "engine/integrator.hpp"

namespace railsim::engine {

// A Model + Data as the ODE seen by the integrators. The assembled Jacobian
// uses the exact kinematic rows (d(dq/dt)/dv = I) and forward differences of
// the force rows.
class ModelOde final : public OdeSystem {
 public:
  ModelOde(const Model& model, Data& data);
  int size() const override { return model_.n_states; }
  bool rhs(double t, const double* x, double* xdot) override;
  std::string failure_message() const override;
  bool jacobian(double t, const double* x, const double* fx, double* J) override;

 private:
  const Model& model_;
  Data& data_;
  std::vector<double> xp_, fp_;
  std::vector<char> kinematic_row_;  // row i is dq/dt = v (exact)
  std::vector<int> kinematic_col_;   // its velocity column
};

}  // namespace railsim::engine
