// Irregularity channel names; see irregularity.hpp.
#include "track/irregularity.hpp"

namespace railsim::track {

const char* channel_name(Channel c) {
  switch (c) {
    case Channel::lateral: return "lateral";
    case Channel::vertical: return "vertical";
    case Channel::cross_level: return "cross_level";
    case Channel::gauge: return "gauge";
  }
  return "?";
}

std::optional<Channel> channel_from_name(std::string_view name) {
  for (Channel c : kAllChannels)
    if (name == channel_name(c)) return c;
  return std::nullopt;
}

}  // namespace railsim::track
