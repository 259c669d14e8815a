// Rigid bodies in the track-following frame; see rigid_body.hpp.
#include "engine/elements/rigid_body.hpp"

namespace railsim::engine {

const char* dof_name(int dof) {
  static const char* names[kNumDof] = {"lateral", "vertical", "roll", "pitch", "yaw"};
  return (dof >= 0 && dof < kNumDof) ? names[dof] : "?";
}

double RigidBody::generalised_mass(int dof) const {
  switch (dof) {
    case kLat:
    case kVert: return mass;
    case kRoll: return inertia.x();
    case kPitch: return inertia.y();
    default: return inertia.z();
  }
}

}  // namespace railsim::engine
