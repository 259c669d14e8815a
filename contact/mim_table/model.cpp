// Model "mim_table": Kalker's normalised creepages of the contact
// (xi' = G c^2 k11 C11 xi / (3 mu N), eta' likewise with C22, psi' =
// G c^3 k23 C23 phi / (mu N)), the table's symmetries, the lookup and the
// forces scaled back (Fx, Fy by mu N, Mz by mu N c); flagged outside the
// table's a/b range or Poisson's ratio. The registry factory loads or builds
// the standard table (progress reported through spdlog). See mim_table.hpp.
#include <spdlog/spdlog.h>

#include <cmath>
#include <string>

#include "contact/fastsim.hpp"  // check_tangential_input
#include "contact/kalker_coefficients.hpp"
#include "contact/mim_table/mim_table.hpp"

namespace railsim::contact {

ContactForces MimTableModel::compute(const ContactInput& in, TangentialWorkspace* /*ws*/) const {
  ContactForces f;
  if (!check_tangential_input(in, "mim_table") || in.material.mu == 0.0) return f;
  const MimTableSpec& s = table_->spec();
  const double a = in.patch.a, b = in.patch.b, aob = a / b;
  const double c = std::sqrt(a * b), G = in.material.shear_modulus(), muN = in.material.mu * in.patch.Fz;
  const KalkerCoefficients C = kalker_coefficients(aob, s.nu);
  const ReductionFactors& k = in.reduction;
  double xi = G * c * c * k.k11 * C.C11 * in.creep.xi / (3.0 * muN);
  const double eta = G * c * c * k.k22 * C.C22 * in.creep.eta / (3.0 * muN);
  double psi = G * c * c * c * k.k23 * C.C23 * in.creep.phi / muN;
  double e = eta + psi / 3.0;                // the table's lateral axis (mim_table.hpp)
  const double sx = xi < 0.0 ? -1.0 : 1.0;  // (-xi, eta, phi) -> (-Fx, Fy, Mz)
  const double sy = e < 0.0 ? -1.0 : 1.0;   // (xi, -eta, -phi) -> (Fx, -Fy, -Mz)
  xi *= sx;
  e *= sy;
  psi *= sy;
  double v[3];
  table_->lookup(aob, xi, e, psi, v);
  f.Fx = sx * v[0] * muN;
  f.Fy = sy * v[1] * muN;
  f.Mz = sy * v[2] * muN * c;
  if (aob < s.aob.front() * (1 - 1e-9) || aob > s.aob.back() * (1 + 1e-9)) {
    f.valid = false;
    f.reason = "mim_table: a/b outside the table (value held at the edge)";
  } else if (std::abs(in.material.nu - s.nu) > 0.02) {
    f.valid = false;
    f.reason = "mim_table: Poisson's ratio differs from the table's";
  }
  return f;
}

std::unique_ptr<TangentialModel> make_mim_table(const TangentialModelOptions& options) {
  MimTableSpec spec = MimTableSpec::standard();
  if (options.grid != 0) spec.grid = options.grid;
  if (options.tolerance != 0.0) spec.tolerance = options.tolerance;
  auto table = load_or_build_mim_table(spec, options.cache_dir,
                                       [](const std::string& m) { spdlog::info("{}", m); });
  return std::make_unique<MimTableModel>(std::move(table));
}

}  // namespace railsim::contact
