// The influence operators of one potential-contact grid, applied with FFTs:
//   normal:    u_z = A_zz p_z                                   [m]
//   shift:     (u_x, u_y) = A_t (p_x, p_y)                        [m]
//   rolling:   (v_x, v_y) = (u(x_i) - u(x_i + dx)) / dx           [-]
// A_zz and A_t are the Love and Boussinesq-Cerruti element coefficients of
// influence.hpp (two quasi-identical bodies). The rolling operator is the
// steady-rolling discretisation with the element length as rolling step
// (Kalker 1990, sec. 5.2): the slip of element i is
//   s_i = w_i + (u_i - u_{i+1})/dx,   rigid slip w = (xi - phi y, eta + phi x)
// (x evaluated at x_i + dx/6 for spin, see mim_model.hpp),
// where u_{i+1} is the displacement one element further along +x (the
// leading side: material flows from +x to -x). Its kernel is the difference
// of A_t at offsets k and k + 1, so it is one more convolution.
//
// An interfacial layer of thickness h and shear modulus G3 adds the local
// compliance h/G3 [m/Pa] to the tangential self-coefficients (Hou et al.
// 1997; CONTACT's interfacial-layer model, u_layer = p h/G3).
//
// Built once per grid and material (kernel evaluation O(mx my), FFT plans);
// the apply functions allocate nothing.
#pragma once

#include <vector>

#include "contact/mim/convolution.hpp"
#include "contact/mim/grid.hpp"
#include "contact/mim/influence.hpp"

namespace railsim::contact::mim {

class InfluenceOperator {
 public:
  // layer_compliance = h/G3 [m/Pa] (0: no layer). fftw_flags: see Convolution.
  InfluenceOperator(const ContactGrid& grid, const ElasticPair& material, double layer_compliance,
                    unsigned fftw_flags);

  const ContactGrid& grid() const { return grid_; }
  const ElasticPair& material() const { return material_; }
  double layer_compliance() const { return layer_; }
  // True when this operator can serve (grid, material, layer) unchanged.
  bool matches(const ContactGrid& g, const ElasticPair& m, double layer) const;

  void normal(const double* p, double* u) { conv_.apply(0, p, u); }
  void shift(const double* px, const double* py, double* ux, double* uy) {
    conv_.apply_block(1, 2, 2, 3, px, py, ux, uy);
  }
  void rolling(const double* px, const double* py, double* vx, double* vy) {
    conv_.apply_block(4, 5, 5, 6, px, py, vx, vy);
  }

  // Self-influence coefficients (offset 0) [m/Pa].
  double self_zz() const { return self_zz_; }
  double self_xx() const { return self_xx_; }
  double self_yy() const { return self_yy_; }

 private:
  ContactGrid grid_;
  ElasticPair material_;
  double layer_;
  Convolution conv_;
  double self_zz_ = 0.0, self_xx_ = 0.0, self_yy_ = 0.0;
};

}  // namespace railsim::contact::mim
