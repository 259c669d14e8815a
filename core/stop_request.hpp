// A request from outside to stop a long computation: Ctrl-C or SIGTERM in the
// program (cli/support_interrupt.hpp), KeyboardInterrupt in Python. Long
// loops (engine::simulate between output points, and through it the runs of
// sweeps and ramps) poll it and throw InterruptedError, so that what was
// computed so far is written and closed (channels.csv whole, summary.json
// marked "interrupted", a sweep's finished points kept for its resume)
// instead of being lost to a kill. A default StopRequest never stops.
// The poll may be called from several threads at once.
#pragma once

#include <functional>
#include <utility>

namespace railsim {

class StopRequest {
 public:
  StopRequest() = default;
  explicit StopRequest(std::function<bool()> poll) : poll_(std::move(poll)) {}
  // True once a stop has been asked for.
  bool requested() const { return poll_ && poll_(); }

 private:
  std::function<bool()> poll_;
};

}  // namespace railsim
