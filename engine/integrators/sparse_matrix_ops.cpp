// Sparse matrix operations built with our flags; see sparse_matrix_ops.hpp.
#include "engine/integrators/sparse_matrix_ops.hpp"

#include <sunmatrix/sunmatrix_sparse.h>

#include <algorithm>

namespace railsim::engine {

namespace {

// Every value, row (column) index and column (row) pointer zero.
int zero(SUNMatrix A) {
  std::fill_n(SM_DATA_S(A), SM_NNZ_S(A), 0.0);
  std::fill_n(SM_INDEXVALS_S(A), SM_NNZ_S(A), sunindextype(0));
  std::fill_n(SM_INDEXPTRS_S(A), SM_NP_S(A) + 1, sunindextype(0));
  return SUNMAT_SUCCESS;
}

// B = A: B zeroed, then A's used entries and pointers copied.
int copy(SUNMatrix A, SUNMatrix B) {
  const sunindextype used = SM_INDEXPTRS_S(A)[SM_NP_S(A)];
  if (SUNMatGetID(B) != SUNMATRIX_SPARSE || SM_SPARSETYPE_S(A) != SM_SPARSETYPE_S(B) ||
      SM_ROWS_S(A) != SM_ROWS_S(B) || SM_COLUMNS_S(A) != SM_COLUMNS_S(B) || SM_NNZ_S(B) < used)
    return SUNMatCopy_Sparse(A, B);  // incompatible, or B must grow: the library's path
  zero(B);
  std::copy_n(SM_DATA_S(A), used, SM_DATA_S(B));
  std::copy_n(SM_INDEXVALS_S(A), used, SM_INDEXVALS_S(B));
  std::copy_n(SM_INDEXPTRS_S(A), SM_NP_S(A), SM_INDEXPTRS_S(B));
  SM_INDEXPTRS_S(B)[SM_NP_S(A)] = used;
  return SUNMAT_SUCCESS;
}

// A = c A + I where every diagonal entry is in A's pattern.
int scale_add_identity(double c, SUNMatrix A) {
  const sunindextype np = SM_NP_S(A);
  const sunindextype* p = SM_INDEXPTRS_S(A);
  const sunindextype* r = SM_INDEXVALS_S(A);
  if (SM_ROWS_S(A) != SM_COLUMNS_S(A)) return SUNMatScaleAddI_Sparse(c, A);
  for (sunindextype j = 0; j < np; ++j)
    if (std::find(r + p[j], r + p[j + 1], j) == r + p[j + 1]) return SUNMatScaleAddI_Sparse(c, A);
  double* v = SM_DATA_S(A);
  for (sunindextype j = 0; j < np; ++j)
    for (sunindextype k = p[j]; k < p[j + 1]; ++k) {
      v[k] *= c;
      if (r[k] == j) v[k] += 1.0;
    }
  return SUNMAT_SUCCESS;
}

// The library's clone (a new matrix with the library's table), then ours installed.
SUNMatrix clone(SUNMatrix A) {
  SUNMatrix B = SUNMatClone_Sparse(A);
  if (B) install_sparse_matrix_ops(B);
  return B;
}

}  // namespace

void install_sparse_matrix_ops(SUNMatrix A) {
  A->ops->clone = clone;
  A->ops->zero = zero;
  A->ops->copy = copy;
  A->ops->scaleaddi = scale_add_identity;
}

}  // namespace railsim::engine
