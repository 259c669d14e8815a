// The sparse matrix operations railsim installs (engine/integrators/
// sparse_matrix_ops.cpp) leave bitwise the matrices SUNDIALS' own leave: A = c
// A + I with the diagonal in the pattern and without it (the library's path),
// B = A into a large enough and into a too small matrix, A = 0; and a clone
// carries them.
#include <catch2/catch.hpp>

#include <sundials/sundials_context.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include <algorithm>
#include <cstring>
#include <random>
#include <vector>

#include "engine/integrators/sparse_matrix_ops.hpp"

namespace {

struct Context {
  SUNContext ctx = nullptr;
  Context() { SUNContext_Create(nullptr, &ctx); }
  ~Context() { SUNContext_Free(&ctx); }
};

// An n x n CSC matrix with about a third of its entries set, the diagonal
// included or not, random values; nnz_room >= the entries used.
SUNMatrix random_matrix(SUNContext ctx, int n, bool diagonal, sunindextype room, unsigned seed, bool ours) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  std::bernoulli_distribution pick(0.33);
  std::vector<sunindextype> p{0}, r;
  std::vector<double> v;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const bool on = i == j ? (diagonal || j % 5 != 2) : pick(rng);
      if (!on) continue;
      r.push_back(i);
      v.push_back(u(rng));
    }
    p.push_back(sunindextype(r.size()));
  }
  SUNMatrix A = SUNSparseMatrix(n, n, std::max<sunindextype>(room, sunindextype(r.size())), CSC_MAT, ctx);
  if (ours) railsim::engine::install_sparse_matrix_ops(A);
  std::copy(p.begin(), p.end(), SM_INDEXPTRS_S(A));
  std::copy(r.begin(), r.end(), SM_INDEXVALS_S(A));
  std::copy(v.begin(), v.end(), SM_DATA_S(A));
  return A;
}

bool same(SUNMatrix a, SUNMatrix b) {
  if (SM_NNZ_S(a) != SM_NNZ_S(b) || SM_NP_S(a) != SM_NP_S(b)) return false;
  const auto nnz = std::size_t(SM_NNZ_S(a)), np = std::size_t(SM_NP_S(a)) + 1;
  return std::memcmp(SM_DATA_S(a), SM_DATA_S(b), nnz * sizeof(double)) == 0 &&
         std::memcmp(SM_INDEXVALS_S(a), SM_INDEXVALS_S(b), nnz * sizeof(sunindextype)) == 0 &&
         std::memcmp(SM_INDEXPTRS_S(a), SM_INDEXPTRS_S(b), np * sizeof(sunindextype)) == 0;
}

}  // namespace

TEST_CASE("sparse matrix operations: bitwise those of SUNDIALS", "[integrators][sunmatrix]") {
  Context c;
  for (bool diagonal : {true, false}) {
    for (int n : {1, 7, 50}) {
      CAPTURE(diagonal, n);
      const sunindextype room = sunindextype(n) * n;
      for (double k : {-0.37, 1.0, 0.0, 2.5e-3}) {
        SUNMatrix lib = random_matrix(c.ctx, n, diagonal, room, 11u + unsigned(n), false);
        SUNMatrix our = random_matrix(c.ctx, n, diagonal, room, 11u + unsigned(n), true);
        CHECK(SUNMatScaleAddI(k, lib) == SUNMAT_SUCCESS);
        CHECK(SUNMatScaleAddI(k, our) == SUNMAT_SUCCESS);
        CHECK(same(lib, our));
        SUNMatDestroy(lib);
        SUNMatDestroy(our);
      }
      // Copy into a matrix with room and into one too small (grown by the library).
      for (sunindextype target_room : {room, sunindextype(1)}) {
        CAPTURE(target_room);
        SUNMatrix src_lib = random_matrix(c.ctx, n, diagonal, room, 5u, false);
        SUNMatrix src_our = random_matrix(c.ctx, n, diagonal, room, 5u, true);
        SUNMatrix dst_lib = random_matrix(c.ctx, n, true, target_room, 9u, false);
        SUNMatrix dst_our = random_matrix(c.ctx, n, true, target_room, 9u, true);
        CHECK(SUNMatCopy(src_lib, dst_lib) == SUNMAT_SUCCESS);
        CHECK(SUNMatCopy(src_our, dst_our) == SUNMAT_SUCCESS);
        CHECK(same(dst_lib, dst_our));
        CHECK(SUNMatZero(dst_lib) == SUNMAT_SUCCESS);
        CHECK(SUNMatZero(dst_our) == SUNMAT_SUCCESS);
        CHECK(same(dst_lib, dst_our));
        for (SUNMatrix m : {src_lib, src_our, dst_lib, dst_our}) SUNMatDestroy(m);
      }
    }
  }
}

TEST_CASE("sparse matrix operations: a clone carries them", "[integrators][sunmatrix]") {
  Context c;
  SUNMatrix A = random_matrix(c.ctx, 6, true, 36, 3u, true);
  SUNMatrix B = SUNMatClone(A);
  REQUIRE(B != nullptr);
  CHECK(B->ops->scaleaddi == A->ops->scaleaddi);
  CHECK(B->ops->copy == A->ops->copy);
  SUNMatrix plain = random_matrix(c.ctx, 6, true, 36, 3u, false);
  CHECK(B->ops->scaleaddi != plain->ops->scaleaddi);
  for (SUNMatrix m : {A, B, plain}) SUNMatDestroy(m);
}
