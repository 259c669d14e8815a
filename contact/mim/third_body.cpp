// Third-body layer parameters and reduction factors; see third_body.hpp.
#include "contact/mim/third_body.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "contact/mim/mim_model.hpp"
#include "core/atomic_file.hpp"
#include "core/cache_dir.hpp"
#include "core/content_hash.hpp"
#include "core/errors.hpp"

namespace railsim::contact::mim {

void ThirdBodyLayer::check() const {
  if (!(h >= 0.0) || !std::isfinite(h) || h > 0.1)
    throw InputError("third-body layer: thickness h must lie in [0, 0.1] m (got " + std::to_string(h) + ")");
  if (h > 0.0 && (!(G3 > 0.0) || !std::isfinite(G3)))
    throw InputError("third-body layer: shear modulus G3 must be positive when h > 0 (got " + std::to_string(G3) + ")");
  if (!(tau_limit >= 0.0) || !std::isfinite(tau_limit))
    throw InputError("third-body layer: limiting shear stress must be >= 0 (got " + std::to_string(tau_limit) + ")");
}

ReductionFactors third_body_reduction(const HertzPatch& patch, const Material& material,
                                      const ThirdBodyLayer& layer, int n_minor) {
  layer.check();
  // Linear theory: creepages small enough and friction large enough for full adhesion.
  Material m = material;
  m.mu = 1e4;
  const double c = std::sqrt(patch.a * patch.b);
  const double xi = 1e-6, phi = 1e-6 / c;
  auto coefficients = [&](const ThirdBodyLayer& l) {
    MimOptions o;
    o.grid = n_minor;
    o.layer = l;
    o.layer.tau_limit = 0.0;
    MimSolver s(o);
    const double Fx = s.solve_hertz(patch, {xi, 0.0, 0.0}, m).Fx;
    const double Fy = s.solve_hertz(patch, {0.0, xi, 0.0}, m).Fy;
    const double Fy_phi = s.solve_hertz(patch, {0.0, 0.0, phi}, m).Fy;
    return ReductionFactors{Fx, Fy, Fy_phi};
  };
  const ReductionFactors with = coefficients(layer);
  const ReductionFactors without = coefficients(ThirdBodyLayer{});
  return {with.k11 / without.k11, with.k22 / without.k22, with.k23 / without.k23};
}

double layer_friction_ratio(const HertzPatch& patch, double mu, double tau_limit) {
  if (!(tau_limit > 0.0) || !(patch.a > 0.0 && patch.b > 0.0 && patch.Fz > 0.0)) return 1.0;
  const double pi = std::acos(-1.0);
  const double p0 = 1.5 * patch.Fz / (pi * patch.a * patch.b);
  const double s = tau_limit / (mu * p0);  // p = p0 s: the cap acts where s > s*
  if (s >= 1.0) return 1.0;
  // F = 2 pi a b [ mu p0 s*^3 / 3 + tau (1 - s*^2) / 2 ],  mu Fz = 2 pi a b mu p0 / 3
  const double F = 2.0 * pi * patch.a * patch.b * (mu * p0 * s * s * s / 3.0 + tau_limit * (1.0 - s * s) / 2.0);
  return F / (mu * patch.Fz);
}

namespace {

// Every input of the computation, with 17 digits: the cache file's first line.
std::string cache_key(const HertzPatch& p, const Material& m, const ThirdBodyLayer& l, int n) {
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "third_body v1 A=%.17g B=%.17g a=%.17g b=%.17g Fz=%.17g E=%.17g nu=%.17g h=%.17g G3=%.17g grid=%d", p.A,
                p.B, p.a, p.b, p.Fz, m.E, m.nu, l.h, l.G3, n);
  return buf;
}

bool read_cache(const std::string& path, const std::string& key, ReductionFactors& k) {
  std::ifstream in(path);
  std::string first, second;
  if (!in || !std::getline(in, first) || first != key || !std::getline(in, second)) return false;
  std::stringstream ss(second);
  std::string a, b, c;
  if (!std::getline(ss, a, ',') || !std::getline(ss, b, ',') || !std::getline(ss, c)) return false;
  char* end = nullptr;
  k.k11 = std::strtod(a.c_str(), &end);
  k.k22 = std::strtod(b.c_str(), &end);
  k.k23 = std::strtod(c.c_str(), &end);
  return std::isfinite(k.k11) && std::isfinite(k.k22) && std::isfinite(k.k23) && k.k11 > 0 && k.k22 > 0 &&
         k.k23 > 0;
}

}  // namespace

LayerReduction third_body_reduction_cached(const HertzPatch& patch, const Material& material,
                                           const ThirdBodyLayer& layer, const std::string& cache_dir,
                                           int n_minor) {
  layer.check();
  if (!(patch.A > 0.0 && patch.B > 0.0 && patch.a > 0.0 && patch.b > 0.0 && patch.Fz > 0.0))
    throw InputError("third-body layer: the contact patch needs A, B, a, b and Fz > 0 (got a = " +
                     std::to_string(patch.a) + " m, b = " + std::to_string(patch.b) + " m, Fz = " +
                     std::to_string(patch.Fz) + " N)");
  LayerReduction r;
  r.patch = patch;
  r.grid = n_minor;
  r.mu_limit = layer.tau_limit > 0.0 ? material.mu * layer_friction_ratio(patch, material.mu, layer.tau_limit) : 0.0;
  const std::string key = cache_key(patch, material, layer, n_minor);
  std::string dir;
  try {
    dir = railsim::cache_dir(cache_dir, "third-body layer");
  } catch (const std::exception&) {
    dir.clear();
  }
  char name[64];
  std::snprintf(name, sizeof name, "third_body_%016llx.txt",
                static_cast<unsigned long long>(ContentHash().text(key).value()));
  const std::string path = dir.empty() ? std::string() : dir + "/" + name;
  if (!path.empty() && read_cache(path, key, r.k)) {
    r.from_cache = true;
    r.cache_file = path;
    return r;
  }
  r.k = third_body_reduction(patch, material, layer, n_minor);
  if (!path.empty()) {
    // Readers see all or nothing; a cache that cannot be written is skipped.
    char line[128];
    std::snprintf(line, sizeof line, "%.17g,%.17g,%.17g", r.k.k11, r.k.k22, r.k.k23);
    try {
      write_file_atomically(path, key + "\n" + line + "\n");
      r.cache_file = path;
    } catch (const InputError&) {
    }
  }
  return r;
}

}  // namespace railsim::contact::mim
