// Three operations of SUNDIALS' sparse matrix that CVODE and ARKODE call at
// every linear-solver set-up (A = 0, B = A, A = c A + I), compiled with our
// optimisation flags and installed into a matrix's operation table (SUNDIALS 6
// user guide, sec. 10.1: a SUNMatrix's operations may be replaced; our clone
// installs them too, so the integrators' saved Jacobian has them).
//
// Why: as for serial_vector_ops.hpp, Debian bookworm's SUNDIALS 6.4.1 is built
// without optimisation; these three took 1.9 % of the ERRI profiles run's
// instructions (callgrind, lateral model, KLU).
//
// Results are bitwise those of the library: the same arithmetic (c a, then + 1
// on the diagonal) and the same layout after each operation (entries past the
// used ones zero). The cases that need storage to grow (a diagonal entry
// missing, a copy into a smaller matrix) are left to the library's functions.
#pragma once

#include <sundials/sundials_matrix.h>

namespace railsim::engine {

// Replace clone, zero, copy and scaleaddi of sparse matrix A (SUNSparseMatrix).
void install_sparse_matrix_ops(SUNMatrix A);

}  // namespace railsim::engine
