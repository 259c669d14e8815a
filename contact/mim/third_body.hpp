// Interfacial third-body layer between wheel and rail (Hou, Kalker & Elkins
// 1997, "An elastic-plastic interfacial layer model"; CONTACT's M = 4 model;
// Toumi 2016, ch. 3): an elastic layer of thickness h and shear modulus G3
// adds the local tangential compliance h/G3 [m/Pa] to every element
// (u_layer = p h/G3), which lowers the initial creep slope; optionally the
// layer yields at a limiting shear stress tau_c [Pa], which caps the traction
// bound: |p| <= min(mu p_n, tau_c).
//
// third_body_reduction() computes the C_ij reduction factors of such a layer
// with the exact solver: the linear-theory coefficients (tiny creepage,
// friction so large that the whole patch adheres) with the layer, divided by
// those without it. Units SI; h in m, G3 and tau_c in Pa.
#pragma once

#include "contact/types.hpp"

namespace railsim::contact::mim {

struct ThirdBodyLayer {
  double h = 0.0;          // layer thickness [m]; 0 = no layer
  double G3 = 0.0;         // layer shear modulus [Pa]
  double tau_limit = 0.0;  // limiting shear stress [Pa]; 0 = none (purely elastic)

  // Local tangential compliance h/G3 [m/Pa] (0 without a layer).
  double compliance() const { return (h > 0.0) ? h / G3 : 0.0; }
  // Throws InputError naming the parameter and its allowed range.
  void check() const;
  // Traction bound of an element with pressure pn [Pa]: min(mu pn, tau_limit).
  double bound(double mu, double pn) const {
    const double g = mu * pn;
    return (tau_limit > 0.0 && g > tau_limit) ? tau_limit : g;
  }
};

// Reduction factors k11, k22, k23 of the layer for a Hertzian patch (a, b,
// A, B, Fz of `patch`) and material, on a grid of n_minor elements across the
// minor axis: k_ij = C_ij(with layer) / C_ij(without). The limiting stress is
// ignored (initial slope). Throws NumericalError if a solve fails.
ReductionFactors third_body_reduction(const HertzPatch& patch, const Material& material,
                                      const ThirdBodyLayer& layer, int n_minor = 40);

}  // namespace railsim::contact::mim
