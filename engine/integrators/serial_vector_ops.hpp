// The element-wise operations of SUNDIALS' serial N_Vector (z = a x + b y,
// c x, |x|, 1/x, the weighted RMS norm, ...), compiled with our optimisation
// flags and installed into a serial vector's operation table (SUNDIALS 6 user
// guide, sec. 9.1: an N_Vector's operations may be replaced one by one; clones
// copy the table, so CVODE's and ARKODE's internal vectors inherit them).
//
// Why: Debian bookworm's libsundials-cvode6 / -arkode5 (6.4.1+dfsg1-3) are
// built without optimisation (every argument goes through the stack, ~20
// instructions per vector element). On the coach's 50 states these operations
// took 14 % of a run's instructions (callgrind, ERRI profiles run, lateral
// model), more than the integrator's own logic.
//
// Results are bitwise those of the library: each operation does the same
// arithmetic in the same order (z = a (x + y) where the library takes that
// branch, a == b; a (x - y) for a == -b; sums in index order, no
// reassociation); a test compares every installed operation with the
// library's on random vectors, aliasing included.
#pragma once

#include <nvector/nvector_serial.h>

namespace railsim::engine {

// Replace the hot operations of serial vector v (N_VNew_Serial) with ours;
// its clones made afterwards inherit them.
void install_serial_vector_ops(N_Vector v);

}  // namespace railsim::engine
