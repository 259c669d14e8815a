// Serial N_Vector operations built with our flags; see serial_vector_ops.hpp.
#include "engine/integrators/serial_vector_ops.hpp"

#include <cmath>

namespace railsim::engine {

namespace {

inline double* data(N_Vector v) { return NV_DATA_S(v); }
inline sunindextype length(N_Vector v) { return NV_LENGTH_S(v); }

// z = a x + b y. Where a == b or a == -b (other than +-1) the library
// factors, z = a (x +- y), which rounds differently; so do we. Every other
// case (a or b = +-1 included) rounds as a x + b y. The most called operation
// (14 times a step): an AVX2 copy on x86-64 (no FMA, so both copies round
// alike).
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
__attribute__((target_clones("avx2", "default")))
#endif
void linear_sum(double a, N_Vector x, double b, N_Vector y, N_Vector z) {
  const sunindextype n = length(z);
  const double* xd = data(x);
  const double* yd = data(y);
  double* zd = data(z);
  const bool unit = a == 1.0 || a == -1.0 || b == 1.0 || b == -1.0;
  if (!unit && a == b) {
    for (sunindextype i = 0; i < n; ++i) zd[i] = a * (xd[i] + yd[i]);
  } else if (!unit && a == -b) {
    for (sunindextype i = 0; i < n; ++i) zd[i] = a * (xd[i] - yd[i]);
  } else {
    for (sunindextype i = 0; i < n; ++i) zd[i] = a * xd[i] + b * yd[i];
  }
}

void constant(double c, N_Vector z) {
  const sunindextype n = length(z);
  double* zd = data(z);
  for (sunindextype i = 0; i < n; ++i) zd[i] = c;
}

void product(N_Vector x, N_Vector y, N_Vector z) {
  const sunindextype n = length(z);
  const double *xd = data(x), *yd = data(y);
  double* zd = data(z);
  for (sunindextype i = 0; i < n; ++i) zd[i] = xd[i] * yd[i];
}

void quotient(N_Vector x, N_Vector y, N_Vector z) {
  const sunindextype n = length(z);
  const double *xd = data(x), *yd = data(y);
  double* zd = data(z);
  for (sunindextype i = 0; i < n; ++i) zd[i] = xd[i] / yd[i];
}

void scale(double c, N_Vector x, N_Vector z) {
  const sunindextype n = length(z);
  const double* xd = data(x);
  double* zd = data(z);
  for (sunindextype i = 0; i < n; ++i) zd[i] = c * xd[i];
}

void absolute(N_Vector x, N_Vector z) {
  const sunindextype n = length(z);
  const double* xd = data(x);
  double* zd = data(z);
  for (sunindextype i = 0; i < n; ++i) zd[i] = std::abs(xd[i]);
}

void inverse(N_Vector x, N_Vector z) {
  const sunindextype n = length(z);
  const double* xd = data(x);
  double* zd = data(z);
  for (sunindextype i = 0; i < n; ++i) zd[i] = 1.0 / xd[i];
}

void add_constant(N_Vector x, double b, N_Vector z) {
  const sunindextype n = length(z);
  const double* xd = data(x);
  double* zd = data(z);
  for (sunindextype i = 0; i < n; ++i) zd[i] = xd[i] + b;
}

// max |x_i| (0 for an empty vector).
double max_norm(N_Vector x) {
  const sunindextype n = length(x);
  const double* xd = data(x);
  double m = 0.0;
  for (sunindextype i = 0; i < n; ++i) m = std::abs(xd[i]) > m ? std::abs(xd[i]) : m;
  return m;
}

// sum (x_i w_i)^2 in index order.
double weighted_square_sum(N_Vector x, N_Vector w) {
  const sunindextype n = length(x);
  const double *xd = data(x), *wd = data(w);
  double s = 0.0;
  for (sunindextype i = 0; i < n; ++i) {
    const double p = xd[i] * wd[i];
    s += p * p;
  }
  return s;
}

// sqrt(sum (x_i w_i)^2 / n), 0 where the mean is not positive (SUNRsqrt).
double weighted_rms_norm(N_Vector x, N_Vector w) {
  const double m = weighted_square_sum(x, w) / static_cast<double>(length(x));
  return m <= 0.0 ? 0.0 : std::sqrt(m);
}

// min x_i (the first element for n = 1).
double minimum(N_Vector x) {
  const sunindextype n = length(x);
  const double* xd = data(x);
  double m = xd[0];
  for (sunindextype i = 1; i < n; ++i) m = xd[i] < m ? xd[i] : m;
  return m;
}

}  // namespace

void install_serial_vector_ops(N_Vector v) {
  N_Vector_Ops o = v->ops;
  o->nvlinearsum = linear_sum;
  o->nvconst = constant;
  o->nvprod = product;
  o->nvdiv = quotient;
  o->nvscale = scale;
  o->nvabs = absolute;
  o->nvinv = inverse;
  o->nvaddconst = add_constant;
  o->nvmaxnorm = max_norm;
  o->nvwrmsnorm = weighted_rms_norm;
  o->nvmin = minimum;
  o->nvmaxnormlocal = max_norm;
  o->nvminlocal = minimum;
  o->nvwsqrsumlocal = weighted_square_sum;
}

}  // namespace railsim::engine
