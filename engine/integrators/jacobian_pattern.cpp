// Jacobian sparsity and column colouring; see jacobian_pattern.hpp.
#include "engine/integrators/jacobian_pattern.hpp"

#include <algorithm>
#include <set>

namespace railsim::engine {

JacobianPattern jacobian_pattern(const Model& model) {
  JacobianPattern p;
  const int n = model.n_states;
  p.n = n;
  // States of each body (and the yaw dampers' own states as extra "bodies").
  std::vector<std::vector<int>> group(model.bodies.size());
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    const RigidBody& body = model.bodies[b];
    for (int k = 0; k < kNumDof; ++k) {
      if (body.q_index[k] >= 0) group[b].push_back(body.q_index[k]);
      if (body.v_index[k] >= 0) group[b].push_back(body.v_index[k]);
    }
    if (body.wheelset < 0) continue;
    const Wheelset& ws = model.wheelsets[std::size_t(body.wheelset)];
    if (ws.beta_state >= 0) group[b].push_back(ws.beta_state);
    // The flexible track under the wheelset couples only to it (positions, rates).
    for (int s : ws.track_states())
      if (s >= 0) {
        group[b].push_back(s);
        group[b].push_back(s + 1);
      }
  }
  std::vector<std::set<int>> linked(model.bodies.size() + model.yaw_dampers.size());
  for (std::size_t b = 0; b < model.bodies.size(); ++b) linked[b].insert(int(b));
  auto link = [&](int a, int b) {
    if (a < 0 || b < 0) return;
    linked[std::size_t(a)].insert(b);
    linked[std::size_t(b)].insert(a);
  };
  for (const auto& e : model.springs) link(e.body_a, e.body_b);
  for (const auto& e : model.bump_stops) link(e.body_a, e.body_b);
  for (const auto& e : model.anti_roll_bars) link(e.body_a, e.body_b);
  for (std::size_t k = 0; k < model.yaw_dampers.size(); ++k) {
    const auto& e = model.yaw_dampers[k];
    const int g = int(model.bodies.size() + k);
    group.push_back({e.state});
    linked[std::size_t(g)].insert(g);
    link(e.body_a, e.body_b);
    link(g, e.body_a);
    link(g, e.body_b);
  }
  std::vector<int> owner(std::size_t(n), -1);
  for (std::size_t g = 0; g < group.size(); ++g)
    for (int s : group[g]) owner[std::size_t(s)] = int(g);
  p.kinematic_row.assign(std::size_t(n), 0);
  p.kinematic_col.assign(std::size_t(n), -1);
  for (const auto& b : model.bodies)
    for (int k = 0; k < kNumDof; ++k)
      if (b.q_index[k] >= 0) {
        p.kinematic_row[std::size_t(b.q_index[k])] = 1;
        p.kinematic_col[std::size_t(b.q_index[k])] = b.v_index[k];
      }
  for (const auto& w : model.wheelsets)
    for (int s : w.track_states())
      if (s >= 0) {
        p.kinematic_row[std::size_t(s)] = 1;
        p.kinematic_col[std::size_t(s)] = s + 1;
      }
  // Columns: column j (state j of group g) reaches the rows of every group linked to g.
  p.colptr.assign(std::size_t(n) + 1, 0);
  for (int j = 0; j < n; ++j) {
    std::vector<int> rows;
    const int g = owner[std::size_t(j)];
    if (g >= 0)
      for (int h : linked[std::size_t(g)])
        for (int i : group[std::size_t(h)]) {
          if (p.kinematic_row[std::size_t(i)] && p.kinematic_col[std::size_t(i)] != j && i != j) continue;
          rows.push_back(i);
        }
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    p.rowind.insert(p.rowind.end(), rows.begin(), rows.end());
    p.colptr[std::size_t(j) + 1] = int(p.rowind.size());
  }
  // Greedy colouring: a column takes the first colour none of whose columns shares a row with it.
  p.color.assign(std::size_t(n), -1);
  std::vector<std::vector<char>> used;  // used[c][row]
  for (int j = 0; j < n; ++j) {
    int c = 0;
    for (;; ++c) {
      if (c == int(used.size())) used.emplace_back(std::size_t(n), 0);
      bool clash = false;
      for (int k = p.colptr[std::size_t(j)]; k < p.colptr[std::size_t(j) + 1] && !clash; ++k)
        clash = used[std::size_t(c)][std::size_t(p.rowind[std::size_t(k)])] != 0;
      if (!clash) break;
    }
    p.color[std::size_t(j)] = c;
    for (int k = p.colptr[std::size_t(j)]; k < p.colptr[std::size_t(j) + 1]; ++k)
      used[std::size_t(c)][std::size_t(p.rowind[std::size_t(k)])] = 1;
  }
  p.colors = int(used.size());
  return p;
}

}  // namespace railsim::engine
