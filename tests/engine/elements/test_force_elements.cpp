// Force elements: spring-damper lever arms, bump-stop table, Maxwell yaw
// damper (against its analytic complex stiffness), anti-roll bar.
#include <catch2/catch.hpp>

#include <cmath>
#include <complex>

#include "engine/elements/anti_roll_bar.hpp"
#include "engine/elements/bump_stop.hpp"
#include "engine/elements/spring_damper.hpp"
#include "engine/elements/yaw_damper.hpp"

using namespace railsim::engine;

TEST_CASE("spring-damper: force along each axis and its moment about the CoM", "[engine][elements]") {
  SpringDamper s;
  s.body_a = 0;
  s.body_b = -1;
  s.r_a = Eigen::Vector3d(0.5, 1.0, -0.2);
  s.k = Eigen::Vector3d(1e6, 2e6, 3e6);
  s.c = Eigen::Vector3d(10, 20, 30);
  std::vector<BodyMotion> m(1);
  std::vector<GenForce> f(1);
  f[0].fill(0);
  m[0].q[kRoll] = 1e-3;  // roll lifts the marker at y = 1 by 1 mm and moves it by +0.2 mm in y (z = -0.2)
  m[0].v[kVert] = 0.01;
  const Eigen::Vector3d F = apply_spring_damper(s, m, f);
  CHECK(F.z() == Approx(-3e6 * 1e-3 - 30 * 0.01));
  CHECK(F.y() == Approx(-2e6 * 0.2e-3));
  CHECK(f[0][kVert] == Approx(F.z()));
  CHECK(f[0][kRoll] == Approx(1.0 * F.z() - (-0.2) * F.y()));  // M_x = y Fz - z Fy
  CHECK(f[0][kPitch] == Approx(-0.2 * F.x() - 0.5 * F.z()));   // M_y = z Fx - x Fz
}

TEST_CASE("bump stop: free play then the piecewise-linear table, symmetric", "[engine][elements]") {
  BumpStop b;
  b.deflection = {0.025, 0.030, 0.035};
  b.force = {0, 600, 1760};
  CHECK(bump_stop_force(b, 0.02) == 0.0);
  CHECK(bump_stop_force(b, 0.0275) == Approx(300));
  CHECK(bump_stop_force(b, 0.0325) == Approx(1180));
  CHECK(bump_stop_force(b, 0.040) == Approx(1760 + 1160));  // last slope continues
  b.body_a = 0;
  b.axis = 1;
  std::vector<BodyMotion> m(1);
  std::vector<GenForce> f(1);
  f[0].fill(0);
  m[0].q[kLat] = -0.0275;
  apply_bump_stop(b, m, f);
  CHECK(f[0][kLat] == Approx(300));
}

TEST_CASE("yaw damper: Maxwell element matches its complex stiffness", "[engine][elements]") {
  // Harmonic deflection Delta = A sin(w t): steady force amplitude |k*| A with
  // k* = k_s i w c / (k_s + i w c) (Maxwell element).
  YawDamper y;
  y.body_a = 0;
  y.series_stiffness = 5e6;
  y.damping = 2e5;
  const double A = 1e-3;
  for (double w : {5.0, 25.0, 100.0}) {
    const std::complex<double> iwc(0.0, w * y.damping);
    const double kstar = std::abs(y.series_stiffness * iwc / (y.series_stiffness + iwc));
    std::vector<BodyMotion> m(1);
    std::vector<GenForce> f(1);
    // Integrate de/dt with classical RK4, small steps, over many periods.
    double e = 0, t = 0, Fmax = 0;
    const double h = 2 * M_PI / w / 2000, T = 20 * 2 * M_PI / w;
    auto rate = [&](double tt, double ee) {
      m[0].q[kYaw] = 0;
      m[0].q[kLat] = 0;
      // marker at y = -1 so that yaw psi moves it by +psi in x: Delta_x = -psi * r_y
      y.r_a = Eigen::Vector3d(0, -1, 0);
      m[0].q[kYaw] = A * std::sin(w * tt);
      f[0].fill(0);
      return apply_yaw_damper(y, ee, m, f);
    };
    while (t < T) {
      const double k1 = rate(t, e), k2 = rate(t + h / 2, e + h / 2 * k1), k3 = rate(t + h / 2, e + h / 2 * k2),
                   k4 = rate(t + h, e + h * k3);
      e += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
      t += h;
      if (t > T / 2) {
        rate(t, e);
        Fmax = std::max(Fmax, std::abs(f[0][kYaw]));  // moment = force x 1 m lever
      }
    }
    CHECK(Fmax == Approx(kstar * A).epsilon(1e-3));
  }
}

TEST_CASE("anti-roll bar: opposite moments proportional to the relative roll", "[engine][elements]") {
  AntiRollBar a{"arb", 0, 1, 940e3};
  std::vector<BodyMotion> m(2);
  std::vector<GenForce> f(2);
  f[0].fill(0);
  f[1].fill(0);
  m[0].q[kRoll] = 0.01;
  m[1].q[kRoll] = 0.004;
  apply_anti_roll_bar(a, m, f);
  CHECK(f[0][kRoll] == Approx(-940e3 * 0.006));
  CHECK(f[1][kRoll] == Approx(940e3 * 0.006));
}
