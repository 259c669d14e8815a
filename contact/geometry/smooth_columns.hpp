// Smooth, C1 representation of tabulated columns on a uniform grid, made for
// stiff time integrators: the contact geometry a vehicle model reads every
// right-hand side must have continuous first derivatives and no cell-scale
// wiggle, or the integrator's step is set by the table's cells instead of by
// the motion.
//
// Representation: nodes x_i = x0 + i h; at every node each column has a value
// f_i and a slope m_i; between nodes the column is the cubic Hermite
// interpolant of (f, m) at the two ends (C1 everywhere, exact for cubics).
// All columns are stored interleaved per node, so one evaluation locates the
// cell once and costs 4 multiply-adds per column (no allocation, no search).
// Boost.Math's cubic_hermite does the same per column with a binary search
// each; the interleaved layout is what makes one evaluation per wheel cheap.
//
// Two ways to get (f, m):
//  - fit_noisy: raw rows (e.g. a table file sampled finely with cell-scale
//    noise) are smoothed by a local least-squares quadratic around each node
//    over +-halfwidth (Savitzky & Golay 1964, Anal. Chem. 36(8), 1627-1639;
//    the fit's value and first derivative at the node), the slopes then
//    limited as Fritsch & Carlson (1980, SIAM J. Numer. Anal. 17(2)) so that
//    a cell never overshoots its nodes (at a jump or a sharp peak of the raw
//    data the fit rounds, it does not ring); the nodes are coarser than the
//    raw rows. max_deviation() reports, per column, the largest
//    difference between the smooth curve and the raw rows and where.
//  - interpolate: exact values at the nodes (a contact search), slopes by
//    centred differences, one-sided at the ends (cardinal cubic Hermite,
//    second-order accurate; the Fritsch-Carlson limiter optional).
// Outside [x0, x_last] evaluation clamps to the end nodes' values with zero
// slope (callers check their ranges). Units are the caller's.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace railsim::contact {

class SmoothColumns {
 public:
  SmoothColumns() = default;

  // raw: rows x cols, row-major, rows on the uniform grid x = raw_x0 + r raw_h.
  // Nodes every node_step from raw_x0 to the last raw row (node_step a
  // multiple of raw_h is not required). halfwidth: half-width of the local fit.
  static SmoothColumns fit_noisy(const std::vector<double>& raw, std::size_t rows, int cols, double raw_x0,
                                 double raw_h, double node_step, double halfwidth);
  // values: nodes x cols, row-major, nodes on x = x0 + i h.
  static SmoothColumns interpolate(const std::vector<double>& values, std::size_t nodes, int cols, double x0,
                                   double h, bool monotone_limiter = false);

  // All columns at x (out has cols() entries); optional derivatives d/dx.
  void eval(double x, double* out, double* dout = nullptr) const;
  // One column.
  double eval(double x, int col) const;
  double derivative(double x, int col) const;

  int cols() const { return cols_; }
  std::size_t nodes() const { return nodes_; }
  double x_min() const { return x0_; }
  double x_max() const { return x0_ + h_ * double(nodes_ - 1); }
  double step() const { return h_; }
  bool empty() const { return nodes_ == 0; }

  struct Deviation {
    double max_abs = 0.0;  // largest |smooth - raw| over the raw rows
    double at = 0.0;       // abscissa of that row
  };
  // fit_noisy only (else zeros): per column.
  const std::vector<Deviation>& deviation() const { return deviation_; }

  // Raw access for serialisation: values then slopes, node-major.
  const std::vector<double>& data() const { return data_; }
  static SmoothColumns from_data(std::vector<double> data, std::size_t nodes, int cols, double x0, double h);

 private:
  void limit_slopes();
  double x0_ = 0.0, h_ = 1.0;
  std::size_t nodes_ = 0;
  int cols_ = 0;
  // Per node: cols values, then cols slopes (per unit x).
  std::vector<double> data_;
  std::vector<Deviation> deviation_;
};

}  // namespace railsim::contact
