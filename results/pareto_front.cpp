// Pareto front of two minimised criteria; see pareto_front.hpp.
#include "results/pareto_front.hpp"

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"

namespace railsim::results {

std::vector<bool> pareto_front(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) throw InputError("pareto_front: criteria of different lengths");
  const std::size_t n = a.size();
  std::vector<bool> front(n, false);
  for (std::size_t i = 0; i < n; ++i) {
    if (std::isnan(a[i]) || std::isnan(b[i])) continue;
    bool dominated = false;
    for (std::size_t j = 0; j < n && !dominated; ++j) {
      if (j == i || std::isnan(a[j]) || std::isnan(b[j])) continue;
      dominated = a[j] <= a[i] && b[j] <= b[i] && (a[j] < a[i] || b[j] < b[i]);
    }
    front[i] = !dominated;
  }
  return front;
}

void pareto_staircase(const std::vector<double>& a, const std::vector<double>& b, const std::vector<bool>& front,
                      std::vector<double>& x, std::vector<double>& y) {
  std::vector<std::size_t> idx;
  for (std::size_t i = 0; i < front.size(); ++i)
    if (front[i]) idx.push_back(i);
  std::sort(idx.begin(), idx.end(), [&](std::size_t i, std::size_t j) { return a[i] < a[j]; });
  x.clear();
  y.clear();
  for (const std::size_t i : idx) {
    x.push_back(a[i]);
    y.push_back(b[i]);
  }
}

}  // namespace railsim::results
