// Error of a tangential solution against a reference (contact/force_error.hpp):
// the documented scales (reference resultant, its floor 1e-3 mu Fz at zero
// creepage, |Mz_ref| with floor 1e-2 mu Fz sqrt(ab)) on hand-computed numbers.
#include <catch2/catch.hpp>

#include <cmath>

#include "contact/force_error.hpp"

using namespace railsim::contact;

TEST_CASE("force errors are relative to the reference resultant", "[contact][force_error]") {
  ContactInput in;
  in.patch.a = 0.006;
  in.patch.b = 0.0054;  // c = 5.69 mm
  in.patch.Fz = 1.0e5;
  in.material.mu = 0.3;  // mu Fz = 30 kN
  ContactForces ref;
  ref.Fx = -3000.0;
  ref.Fy = -4000.0;  // |F_ref| = 5 kN
  ref.Mz = 20.0;
  ContactForces f = ref;
  f.Fx = -3300.0;
  f.Fy = -4400.0;
  f.Mz = 15.0;
  const ForceError e = force_error(f, ref, in);
  CHECK(e.Fx == Approx(300.0 / 5000.0));
  CHECK(e.Fy == Approx(400.0 / 5000.0));
  CHECK(e.F == Approx(500.0 / 5000.0));
  CHECK(e.Mz == Approx(5.0 / 20.0));
  // A force of the right size in the wrong direction is an error of 2 |F_ref| / |F_ref|.
  ContactForces opposite = ref;
  opposite.Fx = -ref.Fx;
  opposite.Fy = -ref.Fy;
  CHECK(force_error(opposite, ref, in).F == Approx(2.0));
}

TEST_CASE("force errors use floors when the reference vanishes", "[contact][force_error]") {
  ContactInput in;
  in.patch.a = in.patch.b = 0.005;
  in.patch.Fz = 1.0e5;
  in.material.mu = 0.3;
  const ContactForces zero;
  ContactForces f;
  f.Fx = 3.0;                      // 1e-3 mu Fz = 30 N
  f.Mz = 0.1 * 1e-2 * 3.0e4 * 0.005;  // 10 % of the Mz floor
  const ForceError e = force_error(f, zero, in);
  CHECK(e.F == Approx(0.1));
  CHECK(e.Mz == Approx(0.1));
  CHECK(std::isfinite(force_error(zero, zero, in).F));
}
