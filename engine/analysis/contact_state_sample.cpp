// The contact states of a run and a sample of them; see contact_state_sample.hpp.
#include "engine/analysis/contact_state_sample.hpp"

#include <cmath>
#include <functional>

#include "core/errors.hpp"

namespace railsim::engine {

void ContactStateRecorder::record(const Model& model, double t, const Data& d) {
  const std::size_t first = states_.size();
  for (std::size_t w = 0; w < model.wheelsets.size(); ++w)
    for (int side = 0; side < 2; ++side) {
      const std::size_t wheel = 2 * w + static_cast<std::size_t>(side);
      for (int k = 0; k < d.wheel[wheel].patches; ++k) {
        const PatchState& p = d.patch[wheel * WheelGeometry::kMaxPoints + static_cast<std::size_t>(k)];
        RunContactState s;
        s.t = t;
        s.distance = d.s;
        s.wheelset = static_cast<int>(w);
        s.side = side;
        s.point = p.point;
        s.contact_angle = p.contact_angle;
        s.input = p.input;
        s.forces = p.forces;
        states_.push_back(s);
      }
    }
  if (states_.size() > first) row_start_.push_back(first);
}

ContactStateSample sample_contact_states(const ContactStateRecorder& rec, int n) {
  if (n < kMinAuditSamples || n > kMaxAuditSamples)
    throw InputError("contact audit: " + std::to_string(n) + " samples outside [" +
                     std::to_string(kMinAuditSamples) + ", " + std::to_string(kMaxAuditSamples) + "]");
  const auto& st = rec.states();
  if (st.empty()) throw InputError("contact audit: the run recorded no loaded contact patch");
  ContactStateSample out;
  std::vector<char> taken(st.size(), 0);
  const auto take = [&](std::size_t i, const std::string& why) {
    if (taken[i] || out.index.size() >= static_cast<std::size_t>(n)) return;
    taken[i] = 1;
    out.index.push_back(i);
    out.why.push_back(why);
  };
  if (static_cast<std::size_t>(n) >= st.size()) {
    for (std::size_t i = 0; i < st.size(); ++i) take(i, "all");
    return out;
  }
  // 1. Extremes.
  using Key = std::function<double(const RunContactState&)>;
  const auto ab = [](const RunContactState& s) {
    return s.input.patch.b > 0.0 ? s.input.patch.a / s.input.patch.b : 0.0;
  };
  const std::vector<std::pair<std::string, Key>> extremes = {
      {"max normal load", [](const RunContactState& s) { return s.input.patch.Fz; }},
      {"max |phi|", [](const RunContactState& s) { return std::fabs(s.input.creep.phi); }},
      {"max |(xi, eta)|", [](const RunContactState& s) { return std::hypot(s.input.creep.xi, s.input.creep.eta); }},
      {"max contact angle", [](const RunContactState& s) { return std::fabs(s.contact_angle); }},
      {"max |F|/(mu N)",
       [](const RunContactState& s) {
         return std::hypot(s.forces.Fx, s.forces.Fy) / (s.input.material.mu * s.input.patch.Fz);
       }},
      {"max a/b", ab},
      {"min a/b", [&](const RunContactState& s) { return -ab(s); }},
      {"max |xi|", [](const RunContactState& s) { return std::fabs(s.input.creep.xi); }},
      {"max |eta|", [](const RunContactState& s) { return std::fabs(s.input.creep.eta); }},
  };
  for (const auto& [why, key] : extremes) {
    std::size_t best = 0;
    for (std::size_t i = 1; i < st.size(); ++i)
      if (key(st[i]) > key(st[best])) best = i;
    take(best, why);
  }
  // 2. The rest evenly in time, walking through the wheels.
  const std::size_t m = static_cast<std::size_t>(n) - out.index.size();
  const std::size_t R = rec.rows();
  const auto& start = rec.row_start();
  for (std::size_t j = 0; j < m; ++j) {
    const auto r = static_cast<std::size_t>((static_cast<double>(j) + 0.5) * static_cast<double>(R) /
                                            static_cast<double>(m));
    const std::size_t row = std::min(r, R - 1);
    const std::size_t b = start[row], e = row + 1 < R ? start[row + 1] : st.size();
    const std::size_t count = e - b;
    for (std::size_t k = 0; k < count; ++k) {
      const std::size_t i = b + (j + k) % count;
      if (!taken[i]) {
        take(i, "even in time");
        break;
      }
    }
  }
  // Rows full of chosen states (n close to the number of states): fill up in order.
  for (std::size_t i = 0; i < st.size() && out.index.size() < static_cast<std::size_t>(n); ++i) take(i, "even in time");
  return out;
}

}  // namespace railsim::engine
