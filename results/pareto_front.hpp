// Pareto front of points that should be small in two criteria (e.g. cost per
// call and error of a model): a point is on the front when no other point is
// at least as good in both and strictly better in one. Ties (identical points)
// are all on the front. NaN points are never on the front and dominate nothing.
// Quadratic in the number of points (meant for tens of models).
#pragma once

#include <vector>

namespace railsim::results {

// front[i] == true when point (a[i], b[i]) is not dominated. a and b have the same size.
std::vector<bool> pareto_front(const std::vector<double>& a, const std::vector<double>& b);

// The front as a staircase for plotting: the front points sorted by a, as
// (x, y) corners of a "post" step line that starts at the cheapest point.
void pareto_staircase(const std::vector<double>& a, const std::vector<double>& b, const std::vector<bool>& front,
                      std::vector<double>& x, std::vector<double>& y);

}  // namespace railsim::results
