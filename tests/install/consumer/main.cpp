// A consumer of the installed railsim: a contact model from the registry, the
// Hertz patch, a shipped profile through the installed data folder, and the
// library's error type. Prints "railsim <version> ok" when the numbers hold.
#include <railsim/contact/geometry/profile.hpp>
#include <railsim/contact/hertz.hpp>
#include <railsim/contact/registry.hpp>
#include <railsim/core/errors.hpp>
#include <railsim/core/version.hpp>
#include <railsim/engine/io/scenario.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>

int main() {
  using namespace railsim;
  const contact::Material m{2.1e11, 0.28, 0.3};
  contact::ContactInput in;
  in.patch = contact::hertz_from_semi_axes(6e-3, 4e-3, 75e3, m);
  in.material = m;
  in.creep = {1e-3, 0.0, 0.0};
  const auto model = contact::make_tangential_model("fastsim");
  const auto ws = model->make_workspace();
  const contact::ContactForces f = model->solve(in, ws.get());
  // A positive creepage gives a negative force below mu Fz.
  if (!(f.Fx < 0 && std::fabs(f.Fx) < m.mu * 75e3)) return std::printf("bad Fx %g\n", f.Fx), 1;
  try {
    contact::make_tangential_model("no_such_model");
    return 1;
  } catch (const InputError&) {
  }
  setenv("RAILSIM_DATA_DIR", RAILSIM_CONSUMER_DATA_DIR, 1);
  const contact::Profile w = contact::read_profile("S1002", contact::ProfileKind::wheel);
  if (w.y().size() < 100) return 1;
  const engine::Scenario sc =
      engine::load_scenario(std::string(RAILSIM_CONSUMER_DATA_DIR) + "/scenarios/single_wheelset.yaml");
  if (sc.model.n_states <= 0) return 1;
  std::printf("railsim %s ok (fastsim Fx %.1f N, %zu wheel points, scenario %s)\n", kVersion, f.Fx, w.y().size(),
              sc.name.c_str());
  return 0;
}
