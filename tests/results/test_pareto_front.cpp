// Pareto front of two minimised criteria (results/pareto_front.hpp): dominated
// points are off the front, ties stay on it, NaN points are ignored, and the
// staircase lists the front by increasing cost.
#include <catch2/catch.hpp>

#include <cmath>

#include "core/errors.hpp"
#include "results/pareto_front.hpp"

using railsim::results::pareto_front;
using railsim::results::pareto_staircase;

TEST_CASE("pareto front keeps exactly the non-dominated points", "[results][pareto]") {
  //                    0     1     2     3     4     5
  const std::vector<double> cost = {1.0, 10.0, 2.0, 100.0, 10.0, 50.0};
  const std::vector<double> err = {50.0, 5.0, 60.0, 0.1, 5.0, 5.0};
  const auto f = pareto_front(cost, err);
  // 2 is dominated by 0 (dearer, worse); 5 by 1 (dearer, same error); 1 and 4 tie.
  CHECK(f == std::vector<bool>{true, true, false, true, true, false});
  std::vector<double> x, y;
  pareto_staircase(cost, err, f, x, y);
  REQUIRE(x.size() == 4);
  CHECK(x.front() == 1.0);
  CHECK(x.back() == 100.0);
  CHECK(y.back() == 0.1);
  for (std::size_t i = 1; i < x.size(); ++i) {
    CHECK(x[i] >= x[i - 1]);
    CHECK(y[i] <= y[i - 1]);
  }
}

TEST_CASE("pareto front ignores NaN points and checks the sizes", "[results][pareto]") {
  const auto f = pareto_front({1.0, NAN, 3.0}, {5.0, 0.0, 1.0});
  CHECK(f == std::vector<bool>{true, false, true});
  CHECK_THROWS_AS(pareto_front({1.0}, {1.0, 2.0}), railsim::InputError);
}
