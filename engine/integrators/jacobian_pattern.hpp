// Sparsity pattern of the vehicle model's Jacobian and a colouring of its
// columns for finite differences (Curtis, Powell & Reid 1974, "On the
// estimation of sparse Jacobian matrices", IMA J. Appl. Math. 13: columns
// that share no row can be perturbed together, one right-hand side per colour).
//
// Structure, from the model alone: a body's states (positions, velocities,
// spin perturbation) depend on each other; bodies joined by a force element
// (spring-damper, bump stop, anti-roll bar, yaw damper) depend on each other's
// states; a yaw damper's elongation state couples its two bodies. Wheel-rail
// contact couples a wheelset only to the track (no states). Rows dq/dt = v are
// exact (only the v column; the diagonal is always in the pattern, as the
// sparse Newton matrix I - gamma J needs it). The pattern is an over-estimate within those
// blocks (a whole block is taken as nonzero); colouring is greedy in column
// order.
#pragma once

#include <vector>

#include "engine/model.hpp"

namespace railsim::engine {

struct JacobianPattern {
  int n = 0;
  std::vector<int> colptr;  // CSC, n + 1 entries
  std::vector<int> rowind;  // row of each nonzero, sorted within a column
  std::vector<int> color;   // colour of each column
  int colors = 0;
  std::vector<char> kinematic_row;  // row i is dq/dt = v (exact)
  std::vector<int> kinematic_col;   // its v column
  int nonzeros() const { return static_cast<int>(rowind.size()); }
};

JacobianPattern jacobian_pattern(const Model& model);

}  // namespace railsim::engine
