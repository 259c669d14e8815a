// Gap on the MIM grid from a wheel-rail gap profile; see profile_gap.hpp.
#include "contact/mim/profile_gap.hpp"

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"

namespace railsim::contact::mim {

GapOnGrid gap_from_profile(const GapProfile& gp, double element, double max_gap) {
  const std::size_t n = gp.q.size();
  if (n < 2 || gp.h.size() != n || gp.A.size() != n)
    throw InputError("mim gap profile: needs >= 2 points with h and A at each");
  if (!(element > 0.0) || !(max_gap > 0.0))
    throw InputError("mim gap profile: element size and maximum gap must be positive");
  const double dq = (gp.q.back() - gp.q.front()) / static_cast<double>(n - 1);
  if (!(dq > 0.0)) throw InputError("mim gap profile: q must increase");
  // Extent of the region h(x, y) < max_gap.
  double ylo = HUGE_VAL, yhi = -HUGE_VAL, xhalf = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    if (!(gp.h[k] < max_gap)) continue;
    if (!(gp.A[k] > 0.0)) throw InputError("mim gap profile: longitudinal curvature A must be positive in the contact region");
    ylo = std::min(ylo, gp.q[k]);
    yhi = std::max(yhi, gp.q[k]);
    xhalf = std::max(xhalf, std::sqrt((max_gap - gp.h[k]) / gp.A[k]));
  }
  if (!(yhi >= ylo)) throw InputError("mim gap profile: no point of the profile lies below the maximum gap");
  ylo -= dq;
  yhi += dq;
  GapOnGrid out;
  ContactGrid& g = out.grid;
  g.dx = g.dy = element;
  g.mx = 2 * static_cast<int>(std::ceil(xhalf / element)) + 4;
  g.my = static_cast<int>(std::ceil((yhi - ylo) / element)) + 4;
  g.x0 = -0.5 * g.mx * element;
  g.y0 = 0.5 * (ylo + yhi) - 0.5 * g.my * element;
  out.h.resize(g.size());
  for (int j = 0; j < g.my; ++j) {
    // Linear interpolation of h and A at y (clamped to the profile's range).
    const double t = std::clamp((g.y(j) - gp.q.front()) / dq, 0.0, static_cast<double>(n - 1));
    const std::size_t k = std::min(static_cast<std::size_t>(t), n - 2);
    const double f = t - static_cast<double>(k);
    const double hy = (1.0 - f) * gp.h[k] + f * gp.h[k + 1];
    const double Ay = (1.0 - f) * gp.A[k] + f * gp.A[k + 1];
    for (int i = 0; i < g.mx; ++i) out.h[g.index(i, j)] = hy + Ay * g.x(i) * g.x(i);
  }
  return out;
}

}  // namespace railsim::contact::mim
