// Flexible track under each wheelset: where the rails are that the wheels
// touch, and how they move (a lumped "moving track" model: the track mass
// travels with its wheelset, as in the track models of general multibody
// codes; Knothe & Grassie 1993, "Modelling of railway track and
// vehicle/track interaction at high frequencies", VSD 22, sec. 3 for the
// lumped track and its full-track resonance).
//
// Without it the rails are rigid and follow the track geometry exactly: a
// kink in the vertical alignment (a twist ramp's end) is a step of the rail's
// vertical velocity under a rolling wheel, an impact on the Hertz spring
// (the coach's full model on curve_twist: one sample of Y/Q 1.41, the wheel
// unloading to zero for 1 ms). With it the track geometry (alignment and
// irregularities) is the line the track's support follows, and the rail
// under the wheels is a mass on a spring and damper to that line:
//
//   lateral, one per wheelset (both rails and the sleepers between them):
//     m_y y_t'' = -k_y (y_t - y_s) - c_y (y_t' - V y_s') - (Y_L + Y_R)
//   vertical, one per wheel (the rail and its share of the sleepers):
//     m_z z_i'' = -k_z (z_i - z_s,i) - c_z (z_i' - V z_s,i') - (Q_i - Q0_i)
//
// y_s = (y_L + y_R)/2 the track's lateral geometry at the wheelset (alignment
// and gauge irregularities: the wheelset sees the mean of its two rails, as
// on rigid track), z_s,i the vertical geometry of rail i, s-derivatives
// times V for their rates; Y_i, Q_i the lateral and vertical forces of rail i
// on its wheel (data.hpp WheelOutput), Q0_i the static vertical wheel load:
// the states are deviations from the static deflection under the static
// load, so x = 0 is still the equilibrium on straight track. The wheelset's
// lateral shift in the contact is then q_y - y_t, and wheel i's rail height
// z_i (rate z_i') instead of the geometry's z_s,i.
// The lateral wheelset model keeps its quasi-static vertical loads (they do
// not depend on the rails' height): it gets the lateral part only.
//
// The rail's bending (vertical.bending_stiffness EI > 0): a rail is a beam on
// an elastic foundation, and over a support whose height follows the track
// geometry z_s it lies along z_s convolved with the beam's influence line
// (Hetenyi 1946, the infinite beam on a Winkler foundation):
//   z_r(s) = int G(s - u) z_s(u) du,  G(x) = (beta/2) e^{-beta|x|} (cos beta x + sin beta|x|),
// int G = 1, transfer function 1 / (1 + (Omega / beta)^4 / 4) at wavenumber
// Omega; beta = (k_f / 4 EI)^{1/4} for the foundation modulus k_f, and the
// lumped stiffness is the beam's under a point load, k_z = 2 k_f / beta, so
// beta = (k_z / 8 EI)^{1/3}. The kink of a linear twist ramp is then spread
// over about pi / beta (2.8 m for UIC60 on ballast) as real rails spread it.
// This treats the vertical geometry as the support's (designed defects,
// settlement); a measured rail-head geometry is already the rail's and
// should be given without it (the kernel halves a wavelength of
// 2 pi / (beta 2^{1/2}) = 4 m).
// Equations and states are ours; parameter values are the scenario's
// (scenario.hpp `track_flexibility`). Units SI; y to the left, z up.
#pragma once

#include <vector>

#include "engine/model.hpp"

namespace railsim::engine {

struct Data;

// The vertical geometry of both rails smoothed by the rail's bending (above),
// tabulated once over the track every `step` metres (trapezoidal convolution
// with G, truncated at |x| = 8 / beta, normalised), cubic Hermite between
// nodes on the values and the equally convolved slopes.
class SmoothedRailGeometry {
 public:
  SmoothedRailGeometry(const TrackReference& track, double length, double beta, double step = 0.05);
  // Height of rail i (0 left, 1 right) and its slope d/ds at distance s (clamped to the track).
  void at(double s, double z[2], double dz[2]) const;
  double beta() const { return beta_; }

 private:
  double beta_ = 0.0, h_ = 0.0, length_ = 0.0;
  std::vector<double> z_[2], dz_[2];
};

// beta of the rail on its foundation from the lumped vertical stiffness and EI.
double rail_foundation_beta(double stiffness, double bending_stiffness);

// Where the rails of every wheelset are (Data::rail): from the track geometry
// (rigid track) or from the track states; and where their supports hold them.
void rail_positions(const Model& model, Data& d, const double* x);

// The track states' derivatives of wheelset w, once its wheel forces are in
// Data::wheel (after wheelset_forces) and Data::rail is this evaluation's
// (after rail_positions).
void track_flexibility_rates(const Model& model, const Data& d, int w, const double* x, double* xdot);

}  // namespace railsim::engine
