// Integrator registry and shared helpers; see integrator.hpp.
#include <cmath>
#include <cstdio>
#include <vector>

#include "core/errors.hpp"
#include "engine/integrators/integrator.hpp"

namespace railsim::engine {

bool OdeSystem::jacobian(double t, const double* x, const double* fx, double* J) {
  const int n = size();
  std::vector<double> xp(x, x + n), fp(n);
  for (int j = 0; j < n; ++j) {
    const double h = 1e-7 * std::max(1.0, std::abs(x[j])) + 1e-9;
    xp[j] = x[j] + h;
    if (!rhs(t, xp.data(), fp.data())) return false;
    for (int i = 0; i < n; ++i) J[i + j * n] = (fp[i] - fx[i]) / h;
    xp[j] = x[j];
  }
  return true;
}

void OdeSystem::tolerances(const IntegratorOptions& options, double* atol) const {
  for (int i = 0; i < size(); ++i) atol[i] = options.atol;
}

const std::vector<IntegratorEntry>& integrators() {
  static const std::vector<IntegratorEntry> table = {
      {"cvode_bdf", "SUNDIALS CVODE variable-order BDF (implicit, stiff)", &make_cvode_integrator},
      {"arkode_erk", "SUNDIALS ARKODE explicit Runge-Kutta, Dormand-Prince 5(4)", &make_arkode_erk_integrator},
      {"arkode_dirk", "SUNDIALS ARKODE implicit (SDIRK) Runge-Kutta", &make_arkode_dirk_integrator},
      {"odeint_dopri5", "Boost.Odeint Dormand-Prince 5(4) with error control (explicit)", &make_odeint_integrator},
  };
  return table;
}

std::string integrator_names() {
  std::string s;
  for (const auto& e : integrators()) s += (s.empty() ? "" : ", ") + std::string(e.name);
  return s;
}

std::unique_ptr<Integrator> make_integrator(OdeSystem& sys, const IntegratorOptions& o) {
  if (!(o.rtol > 0 && o.atol > 0)) throw InputError("integrator: tolerances must be positive");
  if (o.jacobian != "fd" && o.jacobian != "assembled")
    throw InputError("integrator: jacobian must be 'fd' or 'assembled' (got '" + o.jacobian + "')");
  if (o.linear_solver != "auto" && o.linear_solver != "dense" && o.linear_solver != "band" && o.linear_solver != "klu")
    throw InputError("integrator: linear_solver must be 'auto', 'klu', 'dense' or 'band' (got '" + o.linear_solver + "')");
  for (const auto& e : integrators())
    if (o.method == e.name) return e.make(sys, o);
  throw InputError("unknown integrator '" + o.method + "' (known: " + integrator_names() + ")");
}

std::string integrator_failure(double t, const std::string& integrator, const std::string& what) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "t = %.6g s: ", t);
  return std::string(buf) + integrator + ": " + what;
}

}  // namespace railsim::engine
