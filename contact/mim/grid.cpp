// Potential contact grid; see grid.hpp.
#include "contact/mim/grid.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/errors.hpp"

namespace railsim::contact::mim {

void ContactGrid::check(const char* where) const {
  if (mx < 1 || my < 1)
    throw InputError(std::string(where) + ": grid needs at least 1 x 1 elements (got " +
                     std::to_string(mx) + " x " + std::to_string(my) + ")");
  if (!(dx > 0.0) || !(dy > 0.0) || !std::isfinite(dx) || !std::isfinite(dy) ||
      !std::isfinite(x0) || !std::isfinite(y0))
    throw InputError(std::string(where) + ": element size must be positive and finite");
}

ContactGrid grid_for_patch(double a, double b, int n_minor) {
  if (!(a > 0.0) || !(b > 0.0) || !std::isfinite(a) || !std::isfinite(b))
    throw InputError("mim grid: semi-axes a, b must be positive and finite");
  if (n_minor < 4 || n_minor > 4000)
    throw InputError("mim grid: elements across the minor axis must lie in [4, 4000] (got " +
                     std::to_string(n_minor) + ")");
  const int m_minor = n_minor + 4;
  const double s = static_cast<double>(m_minor) / n_minor;
  const double minor = std::min(a, b), major = std::max(a, b);
  const int m_major = std::max(1, static_cast<int>(std::lround(m_minor * major / minor)));
  ContactGrid g;
  g.mx = (a <= b) ? m_minor : m_major;
  g.my = (a <= b) ? m_major : m_minor;
  g.dx = 2.0 * s * a / g.mx;
  g.dy = 2.0 * s * b / g.my;
  g.x0 = -s * a;
  g.y0 = -s * b;
  return g;
}

ContactGrid centred_grid(int mx, int my, double half_x, double half_y) {
  ContactGrid g;
  g.mx = mx;
  g.my = my;
  g.dx = 2.0 * half_x / mx;
  g.dy = 2.0 * half_y / my;
  g.x0 = -half_x;
  g.y0 = -half_y;
  g.check("mim grid");
  return g;
}

std::vector<double> quadratic_gap(const ContactGrid& g, double A, double B) {
  std::vector<double> h(g.size());
  for (int j = 0; j < g.my; ++j)
    for (int i = 0; i < g.mx; ++i) h[g.index(i, j)] = A * g.x(i) * g.x(i) + B * g.y(j) * g.y(j);
  return h;
}

}  // namespace railsim::contact::mim
