// Potential contact area: a rectangular grid of mx x my equal rectangular
// elements (piecewise-constant tractions), element centres
//   x_i = x0 + (i + 1/2) dx,  y_j = y0 + (j + 1/2) dy,
// x in the rolling direction, y lateral; element (i, j) is stored at
// index i + mx * j (x fastest). Units: m.
//
// For a Hertzian patch with semi-axes a (x) and b (y) the grid follows the
// usual rule of square elements with N elements across the minor axis and
// two unused elements on each side in that direction (as in CONTACT's
// documented set-up): m_minor = N + 4, scale s = (N + 4)/N,
// m_major = round(m_minor * major/minor); the grid covers
// [-s a, s a] x [-s b, s b].
#pragma once

#include <vector>

namespace railsim::contact::mim {

struct ContactGrid {
  int mx = 0;
  int my = 0;
  double dx = 0.0;  // element length in x [m]
  double dy = 0.0;  // element width in y [m]
  double x0 = 0.0;  // lower-left corner [m]
  double y0 = 0.0;

  int size() const { return mx * my; }
  double x(int i) const { return x0 + (i + 0.5) * dx; }
  double y(int j) const { return y0 + (j + 0.5) * dy; }
  double element_area() const { return dx * dy; }
  int index(int i, int j) const { return i + mx * j; }

  // Throws InputError unless mx, my >= 1 and dx, dy > 0 (finite).
  void check(const char* where) const;
};

// Grid for a Hertzian patch of semi-axes a, b [m] with n_minor elements
// across the minor axis (rule above). Throws InputError for n_minor < 4 or
// non-positive semi-axes.
ContactGrid grid_for_patch(double a, double b, int n_minor);

// A grid centred on the origin covering [-half_x, half_x] x [-half_y, half_y].
ContactGrid centred_grid(int mx, int my, double half_x, double half_y);

// Undeformed gap h(x, y) = A x^2 + B y^2 [m] at the element centres.
std::vector<double> quadratic_gap(const ContactGrid& g, double A, double B);

}  // namespace railsim::contact::mim
