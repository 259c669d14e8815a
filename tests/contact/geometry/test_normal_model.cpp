// Normal-model registry (contact/geometry/normal_model.cpp): hertz and semi_hertz by name.
#include <catch2/catch.hpp>

#include <cmath>

#include "contact/geometry/normal_model.hpp"
#include "contact/hertz.hpp"
#include "core/errors.hpp"

using namespace railsim;
using namespace railsim::contact;

TEST_CASE("hertz and semi_hertz are selectable by name and agree on a quadratic gap", "[geometry][normal_model]") {
  const double A = 1.0 / 0.92, B = 1.0 / 0.6, Fn = 75e3;
  GapProfile gp;
  for (int j = 0; j < 601; ++j) {
    const double q = -0.008 + 0.016 * j / 600.0;
    gp.q.push_back(q);
    gp.h.push_back(B * q * q);
    gp.A.push_back(A);
  }
  NormalProblem p;
  p.A = A;
  p.B = B;
  p.gap = &gp;
  p.Fn = Fn;
  NormalSolution h, s;
  make_normal_model("hertz")->solve(p, h);
  make_normal_model("semi_hertz")->solve(p, s);
  CHECK(s.area == Approx(h.area).epsilon(0.01));
  CHECK(s.p_max == Approx(h.p_max).epsilon(0.01));
  CHECK(s.equivalent.a == Approx(h.equivalent.a).epsilon(0.01));
  CHECK(s.equivalent.b == Approx(h.equivalent.b).epsilon(0.01));
  CHECK(s.equivalent.A == Approx(A).epsilon(0.03));
  CHECK(s.equivalent.B == Approx(B).epsilon(0.03));
  // Strip loads integrate to the normal load: sum (pi/2) p x_half dq.
  double F = 0.0;
  const double dq = 2.0 * h.equivalent.b / static_cast<double>(h.strips.size());
  for (const auto& st : h.strips) F += 0.5 * M_PI * st.p_max * st.x_half * dq;
  CHECK(F == Approx(Fn).epsilon(0.01));
  CHECK_THROWS_WITH(make_normal_model("kik"), Catch::Contains("hertz, semi_hertz"));
  p.gap = nullptr;
  CHECK_THROWS_AS(make_normal_model("semi_hertz")->solve(p, s), InputError);
}
