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
// those without it. third_body_reduction_cached() does the same for a
// vehicle's contact patch and keeps the result in a cache file (one small
// text file per patch, material, layer and grid under the railsim cache
// folder, contact/mim_table/mim_table.hpp), and adds the friction limit of the layer's
// limiting stress: with tau_c the saturated tangential force of a Hertzian
// patch is F = 2 pi a b int_0^1 min(mu p0 s, tau_c) s ds (p = p0 s,
// s = sqrt(1 - r^2)), i.e. mu_limit = F / Fz <= mu. Units SI; h in m, G3 and
// tau_c in Pa.
#pragma once

#include <string>

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

struct LayerReduction {
  ReductionFactors k;        // initial-slope ratios (third_body_reduction)
  HertzPatch patch;          // the patch they were computed for
  double mu_limit = 0.0;     // tau_limit > 0: saturated force / Fz of the patch (<= mu); 0 without a limit
  int grid = 0;              // elements across the minor axis
  bool from_cache = false;   // read from the cache file rather than computed
  std::string cache_file;    // empty when the cache folder could not be written
};

// third_body_reduction for `patch` (A, B, a, b, Fz > 0), cached in `cache_dir`
// (empty: the default railsim cache folder, core/cache_dir.hpp). A cache
// file that cannot be read or written is recomputed / skipped, never fatal.
LayerReduction third_body_reduction_cached(const HertzPatch& patch, const Material& material,
                                           const ThirdBodyLayer& layer, const std::string& cache_dir = "",
                                           int n_minor = 40);

// Saturated tangential force over mu Fz of a Hertzian patch whose tractions
// are capped by tau_limit (1 without a limit or when tau_limit >= mu p0).
double layer_friction_ratio(const HertzPatch& patch, double mu, double tau_limit);

}  // namespace railsim::contact::mim
