// engine::Data; see data.hpp.
#include "engine/data.hpp"

namespace railsim::engine {

Data::Data(const Model& model)
    : motion(model.bodies.size()),
      force(model.bodies.size()),
      track(model.bodies.size()),
      vehicle_motion(model.bodies.size()),
      wheel(2 * model.wheelsets.size()),
      rail(model.wheelsets.size()),
      patch(2 * model.wheelsets.size() * WheelGeometry::kMaxPoints),
      strips(2),
      approach_warm_start(2 * model.wheelsets.size(), 0.0),
      contact_record(model.wheelsets.size()) {
  for (std::size_t i = 0; i < wheel.size(); ++i) workspace.push_back(model.coupling.make_workspace());
  failure.reserve(512);
  first_invalid_reason.reserve(128);
}

void Data::fail(std::string msg) {
  failed = true;
  derailed = left_range = false;
  failure = std::move(msg);
}

void Data::derail(std::string msg) {
  fail(std::move(msg));
  derailed = true;
}

void Data::leave_range(std::string msg) {
  fail(std::move(msg));
  left_range = true;
}

}  // namespace railsim::engine
