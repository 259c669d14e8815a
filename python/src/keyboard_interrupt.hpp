// Ctrl-C in Python during a long engine call (run, critical_speed): a stop
// request (core/stop_request.hpp) that, on the calling (main) thread and at
// most every 50 ms, takes the GIL and lets Python handle pending signals
// (PyErr_CheckSignals). On KeyboardInterrupt it stays set: the engine stops
// between output points, keeps what it finished (channels.csv, summary.json
// "interrupted", a sweep's points for the resume) and throws
// InterruptedError, which module.cpp turns back into that KeyboardInterrupt.
// Worker threads of a sweep see the request once the main thread has seen it.
#pragma once

#include <pybind11/pybind11.h>

#include <atomic>
#include <chrono>
#include <memory>
#include <thread>

#include "core/stop_request.hpp"

namespace railsim::python {

// Call with the GIL held, on the thread that will run the engine.
inline StopRequest keyboard_interrupt_request() {
  struct State {
    std::thread::id caller = std::this_thread::get_id();
    std::atomic<bool> tripped{false};
    std::chrono::steady_clock::time_point last = std::chrono::steady_clock::now();  // caller's thread only
  };
  auto st = std::make_shared<State>();
  return StopRequest([st] {
    if (st->tripped.load(std::memory_order_relaxed)) return true;
    if (std::this_thread::get_id() != st->caller) return false;
    const auto now = std::chrono::steady_clock::now();
    if (now - st->last < std::chrono::milliseconds(50)) return false;
    st->last = now;
    const pybind11::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) st->tripped.store(true, std::memory_order_relaxed);
    return st->tripped.load(std::memory_order_relaxed);
  });
}

}  // namespace railsim::python
