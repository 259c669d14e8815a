// The small bifurcation sweep several analysis tests share: the single
// wheelset on S1002-like flanged wheels (tests/data/scenarios/
// single_wheelset_flange.yaml, linear critical speed 45.6 m/s), down branch
// only, 44-48 m/s in 2 m/s steps, 6 s per point, two threads.
#pragma once

#include "engine/analysis/critical_speed.hpp"

namespace railsim::test {

inline engine::BifurcationOptions flange_sweep_options() {
  engine::BifurcationOptions o;
  o.v_min = 44.0;
  o.v_max = 48.0;
  o.v_step = 2.0;
  o.duration = 6.0;
  o.up_branch = false;
  o.threads = 2;
  return o;
}

}  // namespace railsim::test
