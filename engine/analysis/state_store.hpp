// Final states of sweep runs kept for path following (the continuation of a
// bifurcation sweep, engine/analysis/critical_speed.cpp): key -> state vector,
// held in memory and appended to a file as runs finish, so an interrupted sweep
// resumes from them. Thread-safe.
//
// File: one line per state, "key,x0,x1,...", numbers with 17 significant digits
// (reading back is exact). Only complete lines count: a last line without its
// newline was torn by an interruption and is ignored (and ended, so the next
// state starts a line of its own). Lines whose length is not n_states are ignored.
#pragma once

#include <Eigen/Dense>

#include <map>
#include <mutex>
#include <string>

#include "core/atomic_file.hpp"

namespace railsim::engine {

class StateStore {
 public:
  StateStore(const std::string& path, int n_states);
  // Keep x under key (ignored unless x has n_states entries).
  void put(const std::string& key, const Eigen::VectorXd& x);
  // The state under key, or nullptr.
  const Eigen::VectorXd* find(const std::string& key) const;

 private:
  int n_;
  mutable std::mutex mutex_;
  std::map<std::string, Eigen::VectorXd> states_;
  AppendFile out_;
};

}  // namespace railsim::engine
