// Final states of sweep runs, kept in memory and in a file; see state_store.hpp.
#include "engine/analysis/state_store.hpp"

#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <vector>

namespace railsim::engine {

StateStore::StateStore(const std::string& path, int n_states) : n_(n_states) {
  const std::string text = read_own_file(path);
  std::size_t start = 0;
  for (std::size_t end = text.find('\n'); end != std::string::npos; start = end + 1, end = text.find('\n', start)) {
    std::stringstream ls(text.substr(start, end - start));
    std::string key, cell;
    if (!std::getline(ls, key, ',')) continue;
    std::vector<double> x;
    while (std::getline(ls, cell, ',')) x.push_back(std::strtod(cell.c_str(), nullptr));
    if (static_cast<int>(x.size()) == n_)
      states_[key] = Eigen::Map<const Eigen::VectorXd>(x.data(), static_cast<Eigen::Index>(x.size()));
  }
  out_.open(path);  // checked writes: a full disk is an error naming the file
  if (start < text.size()) out_.write("\n");  // end the torn line
}

void StateStore::put(const std::string& key, const Eigen::VectorXd& x) {
  if (x.size() != n_) return;
  std::string line = key;
  char buf[40];
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    std::snprintf(buf, sizeof buf, ",%.17g", x[i]);
    line += buf;
  }
  std::lock_guard<std::mutex> lock(mutex_);
  states_[key] = x;
  out_.write(line + '\n');
}

const Eigen::VectorXd* StateStore::find(const std::string& key) const {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto it = states_.find(key);
  return it == states_.end() ? nullptr : &it->second;
}

}  // namespace railsim::engine
