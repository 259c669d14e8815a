// The serial vector operations railsim installs (engine/integrators/
// serial_vector_ops.cpp) give bitwise the results of SUNDIALS' own serial
// operations, for every branch of z = a x + b y (a, b = +-1, a = +-b, general),
// with z aliasing x or y, on vectors of several lengths holding values of
// every sign and magnitude.
#include <catch2/catch.hpp>

#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>

#include <cmath>
#include <cstring>
#include <random>
#include <utility>
#include <vector>

#include "engine/integrators/serial_vector_ops.hpp"

namespace {

struct Context {
  SUNContext ctx = nullptr;
  Context() { SUNContext_Create(nullptr, &ctx); }
  ~Context() { SUNContext_Free(&ctx); }
};

// A serial vector, with railsim's operations installed or SUNDIALS' own.
struct Vec {
  N_Vector v;
  Vec(sunindextype n, SUNContext ctx, bool ours) : v(N_VNew_Serial(n, ctx)) {
    if (ours) railsim::engine::install_serial_vector_ops(v);
  }
  ~Vec() { N_VDestroy(v); }
  Vec(const Vec&) = delete;
  Vec& operator=(const Vec&) = delete;
  double* d() const { return NV_DATA_S(v); }
};

void fill(const Vec& x, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> e(-30, 30);
  for (sunindextype i = 0; i < NV_LENGTH_S(x.v); ++i) x.d()[i] = std::ldexp(u(rng), e(rng));
}

bool same_bits(const Vec& a, const Vec& b) {
  return std::memcmp(a.d(), b.d(), sizeof(double) * std::size_t(NV_LENGTH_S(a.v))) == 0;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

TEST_CASE("serial vector operations: bitwise those of SUNDIALS, every branch and aliasing", "[integrators][nvector]") {
  Context c;
  std::mt19937 rng(7);
  const std::vector<std::pair<double, double>> coefficients = {
      {1, 1},     {1, -1},    {-1, 1},   {-1, -1},   {1, 2.5},  {2.5, 1}, {-1, 0.3}, {0.3, -1},
      {0.7, 0.7}, {0.7, -0.7}, {-0.7, 0.7}, {0.3, 1.9}, {0, 2},  {2, 0},   {1e-300, -3e5}};
  for (sunindextype n : {1, 2, 7, 50, 101}) {
    CAPTURE(n);
    Vec x0(n, c.ctx, false), y0(n, c.ctx, false), z0(n, c.ctx, false);
    Vec x1(n, c.ctx, true), y1(n, c.ctx, true), z1(n, c.ctx, true);
    const auto reset = [&] {
      fill(x0, rng);
      fill(y0, rng);
      fill(z0, rng);
      std::memcpy(x1.d(), x0.d(), sizeof(double) * std::size_t(n));
      std::memcpy(y1.d(), y0.d(), sizeof(double) * std::size_t(n));
      std::memcpy(z1.d(), z0.d(), sizeof(double) * std::size_t(n));
    };
    for (const auto& [a, b] : coefficients) {
      CAPTURE(a, b);
      reset();
      N_VLinearSum_Serial(a, x0.v, b, y0.v, z0.v);
      N_VLinearSum(a, x1.v, b, y1.v, z1.v);
      CHECK(same_bits(z0, z1));
      reset();  // z = y (CVODE's y <- a x + y)
      N_VLinearSum_Serial(a, x0.v, b, y0.v, y0.v);
      N_VLinearSum(a, x1.v, b, y1.v, y1.v);
      CHECK(same_bits(y0, y1));
      reset();  // z = x
      N_VLinearSum_Serial(a, x0.v, b, y0.v, x0.v);
      N_VLinearSum(a, x1.v, b, y1.v, x1.v);
      CHECK(same_bits(x0, x1));
    }
    for (double k : {1.0, -1.0, 0.37, -2e7}) {
      reset();
      N_VScale_Serial(k, x0.v, z0.v);
      N_VScale(k, x1.v, z1.v);
      CHECK(same_bits(z0, z1));
      N_VScale_Serial(k, x0.v, x0.v);  // in place
      N_VScale(k, x1.v, x1.v);
      CHECK(same_bits(x0, x1));
      N_VAddConst_Serial(y0.v, k, z0.v);
      N_VAddConst(y1.v, k, z1.v);
      CHECK(same_bits(z0, z1));
      N_VConst_Serial(k, z0.v);
      N_VConst(k, z1.v);
      CHECK(same_bits(z0, z1));
    }
    reset();
    N_VProd_Serial(x0.v, y0.v, z0.v);
    N_VProd(x1.v, y1.v, z1.v);
    CHECK(same_bits(z0, z1));
    N_VDiv_Serial(x0.v, y0.v, z0.v);
    N_VDiv(x1.v, y1.v, z1.v);
    CHECK(same_bits(z0, z1));
    N_VAbs_Serial(x0.v, z0.v);
    N_VAbs(x1.v, z1.v);
    CHECK(same_bits(z0, z1));
    N_VInv_Serial(y0.v, z0.v);
    N_VInv(y1.v, z1.v);
    CHECK(same_bits(z0, z1));
    CHECK(same_bits(N_VMaxNorm_Serial(x0.v), N_VMaxNorm(x1.v)));
    CHECK(same_bits(N_VMin_Serial(x0.v), N_VMin(x1.v)));
    CHECK(same_bits(N_VWrmsNorm_Serial(x0.v, y0.v), N_VWrmsNorm(x1.v, y1.v)));
    CHECK(same_bits(N_VWSqrSumLocal_Serial(x0.v, y0.v), N_VWSqrSumLocal(x1.v, y1.v)));
    N_VConst_Serial(0.0, z0.v);  // a zero norm
    N_VConst(0.0, z1.v);
    CHECK(same_bits(N_VWrmsNorm_Serial(z0.v, y0.v), N_VWrmsNorm(z1.v, y1.v)));
  }
}

TEST_CASE("serial vector operations: clones inherit them", "[integrators][nvector]") {
  Context c;
  Vec x(4, c.ctx, true);
  N_Vector y = N_VClone(x.v);
  CHECK(y->ops->nvlinearsum == x.v->ops->nvlinearsum);
  CHECK(y->ops->nvwrmsnorm == x.v->ops->nvwrmsnorm);
  Vec plain(4, c.ctx, false);
  CHECK(y->ops->nvlinearsum != plain.v->ops->nvlinearsum);
  N_VDestroy(y);
}
