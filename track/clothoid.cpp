// Transition curves (clothoid, Bloss, cosine); see clothoid.hpp.
#include "track/clothoid.hpp"

#include <boost/math/quadrature/gauss.hpp>

#include <algorithm>
#include <cmath>

namespace railsim::track {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kMaxTurnPerPiece = 0.25;  // rad of heading change per quadrature piece
}  // namespace

const char* transition_shape_name(TransitionShape s) {
  switch (s) {
    case TransitionShape::linear: return "linear";
    case TransitionShape::bloss: return "bloss";
    case TransitionShape::cosine: return "cosine";
  }
  return "?";
}

Clothoid::Clothoid(double length, double k0, double k1, double E0, double E1, TransitionShape shape)
    : Segment(length), k0_(k0), k1_(k1), E0_(E0), E1_(E1), shape_(shape) {}

Derivs Clothoid::shape_at(double t) const {
  switch (shape_) {
    case TransitionShape::linear: return {t, 1.0, 0.0};
    case TransitionShape::bloss: return {t * t * (3.0 - 2.0 * t), 6.0 * t * (1.0 - t), 6.0 - 12.0 * t};
    case TransitionShape::cosine:
      return {0.5 * (1.0 - std::cos(kPi * t)), 0.5 * kPi * std::sin(kPi * t), 0.5 * kPi * kPi * std::cos(kPi * t)};
  }
  return {};
}

Derivs Clothoid::curvature(double u) const {
  const double L = length();
  const Derivs f = shape_at(u / L);
  const double dk = k1_ - k0_;
  return {k0_ + dk * f.v, dk * f.d1 / L, dk * f.d2 / (L * L)};
}

Derivs Clothoid::cant(double u) const {
  const double L = length();
  const Derivs f = shape_at(u / L);
  const double dE = E1_ - E0_;
  return {E0_ + dE * f.v, dE * f.d1 / L, dE * f.d2 / (L * L)};
}

double Clothoid::heading_change(double u) const {
  const double L = length();
  const double t = u / L;
  double F = 0.0;
  switch (shape_) {
    case TransitionShape::linear: F = 0.5 * t * t; break;
    case TransitionShape::bloss: F = t * t * t * (1.0 - 0.5 * t); break;
    case TransitionShape::cosine: F = 0.5 * t - std::sin(kPi * t) / (2.0 * kPi); break;
  }
  return k0_ * u + (k1_ - k0_) * L * F;
}

std::array<double, 2> Clothoid::offset(double u) const {
  using Gauss = boost::math::quadrature::gauss<double, 20>;
  // |dpsi| on [0, u] is bounded by u max(|k0|, |k1|) since 0 <= f <= 1.
  const double turn = std::abs(u) * std::max(std::abs(k0_), std::abs(k1_));
  const int pieces = 1 + static_cast<int>(turn / kMaxTurnPerPiece);
  const double h = u / pieces;
  double x = 0.0, y = 0.0;
  for (int i = 0; i < pieces; ++i) {
    const double a = i * h, b = (i + 1) * h;
    x += Gauss::integrate([this](double v) { return std::cos(heading_change(v)); }, a, b);
    y += Gauss::integrate([this](double v) { return std::sin(heading_change(v)); }, a, b);
  }
  return {x, y};
}

}  // namespace railsim::track
