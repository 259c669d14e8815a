// Track sampling (engine/analysis/track_sampling.cpp) on a straight track with
// one cosine lateral defect r(s) = A/2 (1 - cos(2 pi (s - s0) / lambda)) over
// one wavelength (tracks/straight_lateral_defect.yaml: A = 10 mm, lambda = 20 m,
// s0 = 80 m): the peak A, and the RMS over [0, L], sqrt(3 A^2 lambda / (8 L))
// (the integral of r^2 over the wavelength is 3 A^2 lambda / 8), the sample
// positions, and no cant deficiency without a speed.
#include <catch2/catch.hpp>

#include <cmath>

#include "engine/analysis/track_sampling.hpp"
#include "test_support.hpp"
#include "track/track_file.hpp"

using namespace railsim;

TEST_CASE("track sampling: peak and RMS of a cosine defect, sample positions", "[track_sampling]") {
  const track::Track track = track::load_track(test::source_path("tracks/straight_lateral_defect.yaml"));
  const double A = 10e-3, lambda = 20.0, L = 200.0;
  std::vector<double> s;
  bool nan_deficiency = true;
  const auto st = engine::sample_track(track, 0.0, L, 0.05, std::nullopt, [&](const engine::TrackSample& p) {
    s.push_back(p.s);
    nan_deficiency = nan_deficiency && std::isnan(p.cant_deficiency);
  });
  const auto lat = static_cast<std::size_t>(track::index(track::Channel::lateral));
  CHECK(st.rows == 4001);
  REQUIRE(s.size() == 4001);
  CHECK(s.front() == 0.0);
  CHECK(s.back() == Approx(L));
  CHECK(nan_deficiency);
  CHECK(st.max_abs[lat] == Approx(A).epsilon(1e-6));  // s = 90 m is a sample
  CHECK(st.rms[lat] == Approx(std::sqrt(3.0 * A * A * lambda / (8.0 * L))).epsilon(1e-3));
  const auto ver = static_cast<std::size_t>(track::index(track::Channel::vertical));
  CHECK(st.max_abs[ver] == 0.0);
  // A step that does not divide the range: every step inside it, then the end itself (it was dropped, while
  // `railsim track` said it sampled up to the end).
  std::vector<double> t;
  engine::sample_track(track, 0.0, 1.0, 0.3, 30.0, [&](const engine::TrackSample& p) { t.push_back(p.s); });
  REQUIRE(t.size() == 5);
  CHECK(t[3] == Approx(0.9));
  CHECK(t.back() == 1.0);
  CHECK(engine::track_sample_count(0.0, 1.0, 0.25) == 5.0);
  CHECK(engine::track_sample_count(0.0, 270.0, 100.0) == 4.0);  // 0, 100, 200, 270
}
