// engine::Model helpers; see model.hpp.
#include "engine/model.hpp"

namespace railsim::engine {

const char* wheelset_model_name(WheelsetModel m) { return m == WheelsetModel::full ? "full" : "lateral"; }

int Model::body_index(const std::string& name) const {
  for (std::size_t i = 0; i < bodies.size(); ++i)
    if (bodies[i].name == name) return static_cast<int>(i);
  return -1;
}

}  // namespace railsim::engine
