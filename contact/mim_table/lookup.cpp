// The MIM table's lookup: tensor-product cubic Hermite interpolation with
// finite-difference slopes over 4 x 4 x 4 x 4 nodes (C1, exact at the nodes,
// no allocation); axes and their maps in mim_table.hpp.
#include <algorithm>
#include <cmath>
#include <vector>

#include "contact/mim_table/mim_table.hpp"
#include "contact/mim_table/axes.hpp"

namespace railsim::contact {

namespace {

// Cubic Hermite weights (finite-difference slopes) of up to 4 nodes around x.
struct AxisWeights {
  std::size_t idx[4] = {0, 0, 0, 0};
  double w[4] = {0, 0, 0, 0};
};
AxisWeights axis_weights(const std::vector<double>& t, double x) {
  AxisWeights a;
  const std::size_t n = t.size();
  if (n == 1) {
    a.w[1] = 1.0;
    return a;
  }
  x = std::clamp(x, t.front(), t.back());
  std::size_t i = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), x) - t.begin());
  i = std::min(std::max<std::size_t>(i, 1), n - 1) - 1;  // interval [t_i, t_i+1]
  const double h = t[i + 1] - t[i];
  const double s = (x - t[i]) / h;
  const double s2 = s * s, s3 = s2 * s;
  const double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s, h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
  // local slots: 0 -> i-1, 1 -> i, 2 -> i+1, 3 -> i+2
  a.idx[0] = i > 0 ? i - 1 : i;
  a.idx[1] = i;
  a.idx[2] = i + 1;
  a.idx[3] = i + 2 < n ? i + 2 : i + 1;
  a.w[1] += h00;
  a.w[2] += h01;
  const double c1 = h10 * h, c2 = h11 * h;
  if (i > 0) {
    const double d = t[i + 1] - t[i - 1];
    a.w[2] += c1 / d;
    a.w[0] -= c1 / d;
  } else {
    a.w[2] += c1 / h;
    a.w[1] -= c1 / h;
  }
  if (i + 2 < n) {
    const double d = t[i + 2] - t[i];
    a.w[3] += c2 / d;
    a.w[1] -= c2 / d;
  } else {
    a.w[2] += c2 / h;
    a.w[1] -= c2 / h;
  }
  return a;
}

}  // namespace

const double* MimTable::node(std::size_t i, std::size_t j, std::size_t k, std::size_t l) const {
  const std::size_t nj = spec_.uxi.size(), nk = spec_.ueta.size(), nl = spec_.vpsi.size();
  return &values_[3 * (((i * nj + j) * nk + k) * nl + l)];
}

void MimTable::lookup(double aob, double xi_n, double e_n, double psi_n, double out[3]) const {
  const AxisWeights A = axis_weights(lnaob_, std::log(aob));
  const AxisWeights X = axis_weights(spec_.uxi, mim_table_detail::u_of(std::max(0.0, xi_n)));
  const AxisWeights E = axis_weights(spec_.ueta, mim_table_detail::u_of(std::max(0.0, e_n)));
  const AxisWeights P = axis_weights(spec_.vpsi, mim_table_detail::v_of(psi_n));
  double f0 = 0.0, f1 = 0.0, f2 = 0.0;
  for (int a = 0; a < 4; ++a) {
    if (A.w[a] == 0.0) continue;
    for (int x = 0; x < 4; ++x) {
      const double wax = A.w[a] * X.w[x];
      if (wax == 0.0) continue;
      for (int e = 0; e < 4; ++e) {
        const double waxe = wax * E.w[e];
        if (waxe == 0.0) continue;
        for (int p = 0; p < 4; ++p) {
          const double w = waxe * P.w[p];
          if (w == 0.0) continue;
          const double* v = node(A.idx[a], X.idx[x], E.idx[e], P.idx[p]);
          f0 += w * v[0];
          f1 += w * v[1];
          f2 += w * v[2];
        }
      }
    }
  }
  out[0] = f0;
  out[1] = f1;
  out[2] = f2;
}

}  // namespace railsim::contact
