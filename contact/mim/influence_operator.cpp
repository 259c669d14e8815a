// FFT influence operators of a grid; see influence_operator.hpp.
#include "contact/mim/influence_operator.hpp"

#include <cmath>
#include <numbers>

namespace railsim::contact::mim {

namespace {
double xasinh(double x, double y) { return x == 0.0 ? 0.0 : x * std::asinh(y / std::abs(x)); }
}  // namespace

bool InfluenceOperator::matches(const ContactGrid& g, const ElasticPair& m, double layer) const {
  return g.mx == grid_.mx && g.my == grid_.my && g.dx == grid_.dx && g.dy == grid_.dy &&
         m.G == material_.G && m.nu == material_.nu && m.K == material_.K && layer == layer_;
}

InfluenceOperator::InfluenceOperator(const ContactGrid& grid, const ElasticPair& material,
                                     double layer_compliance, unsigned fftw_flags)
    : grid_(grid), material_(material), layer_(layer_compliance),
      conv_(grid.mx, grid.my, 7, fftw_flags) {
  grid_.check("mim influence");
  const int mx = grid.mx, my = grid.my;
  const double dx = grid.dx, dy = grid.dy;
  // Antiderivatives at the element corners x_c = (c - 1/2) dx, c in [-(mx-1), mx+1],
  // y_d = (d - 1/2) dy, d in [-(my-1), my]; shared by neighbouring elements.
  const int c0 = -(mx - 1), nc = 2 * mx + 1;
  const int d0 = -(my - 1), nd = 2 * my;
  std::vector<double> fa(static_cast<std::size_t>(nc) * nd), fb(fa.size()), fr(fa.size());
  for (int d = 0; d < nd; ++d)
    for (int c = 0; c < nc; ++c) {
      const double x = (c0 + c - 0.5) * dx, y = (d0 + d - 0.5) * dy;
      const std::size_t q = static_cast<std::size_t>(d) * nc + c;
      fa[q] = xasinh(x, y);  // corner sum -> I_yy
      fb[q] = xasinh(y, x);  // corner sum -> I_xx
      fr[q] = -std::hypot(x, y);  // corner sum -> I_xy
    }
  auto corner = [&](const std::vector<double>& f, int di, int dj) {
    const int c = di - c0, d = dj - d0;
    auto at = [&](int cc, int dd) { return f[static_cast<std::size_t>(dd) * nc + cc]; };
    return at(c + 1, d + 1) - at(c, d + 1) - at(c + 1, d) + at(c, d);
  };
  const double nu = material.nu, piG = std::numbers::pi * material.G;
  auto axx = [&](int di, int dj) {
    return (corner(fb, di, dj) + (1.0 - nu) * corner(fa, di, dj)) / piG +
           ((di == 0 && dj == 0) ? layer_ : 0.0);
  };
  auto ayy = [&](int di, int dj) {
    return ((1.0 - nu) * corner(fb, di, dj) + corner(fa, di, dj)) / piG +
           ((di == 0 && dj == 0) ? layer_ : 0.0);
  };
  auto axy = [&](int di, int dj) { return nu * corner(fr, di, dj) / piG; };
  auto azz = [&](int di, int dj) {
    return (1.0 - nu) * (corner(fa, di, dj) + corner(fb, di, dj)) / piG;
  };
  conv_.set_kernel(0, azz);
  conv_.set_kernel(1, axx);
  conv_.set_kernel(2, axy);
  conv_.set_kernel(3, ayy);
  conv_.set_kernel(4, [&](int di, int dj) { return (axx(di, dj) - axx(di + 1, dj)) / dx; });
  conv_.set_kernel(5, [&](int di, int dj) { return (axy(di, dj) - axy(di + 1, dj)) / dx; });
  conv_.set_kernel(6, [&](int di, int dj) { return (ayy(di, dj) - ayy(di + 1, dj)) / dx; });
  self_zz_ = azz(0, 0);
  self_xx_ = axx(0, 0);
  self_yy_ = ayy(0, 0);
}

}  // namespace railsim::contact::mim
