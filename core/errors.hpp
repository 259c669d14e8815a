// railsim error types and process exit codes.
//
// InputError   : the user gave something the program cannot accept (a bad
//                YAML key, an out-of-range parameter, a malformed profile).
//                The message names the file, line and key and the allowed
//                range:  "file:line: key 'x': expected a positive number (got -3)".
// NumericalError: the physics or the numerics broke down (NaN, loss of
//                contact, integrator step collapse, a solver that did not
//                converge). The message names the time, the place and the model.
//
// InterruptedError: the user stopped the computation (Ctrl-C, SIGTERM,
//                KeyboardInterrupt; core/stop_request.hpp). Neither a result
//                nor a failure: what was finished is kept, nothing is judged.
//
// The command-line program maps them to exit codes 2 and 3, and 130 (SIGINT)
// or 143 (SIGTERM) for an interruption, as a shell reports a killed program.
#pragma once

#include <stdexcept>
#include <string>

namespace railsim {

inline constexpr int kExitSuccess = 0;
inline constexpr int kExitBadInput = 2;
inline constexpr int kExitNumericalFailure = 3;
inline constexpr int kExitInterrupted = 130;  // 128 + SIGINT

class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class NumericalError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A run that ended because the vehicle derailed (the physics, not the
// numerics: a wheelset past its flange). Derived from NumericalError so that
// every handler that stops a run also stops on it; a run report tells the two
// apart and gives derailment a running-safety verdict, numerical failure none.
class DerailmentError : public NumericalError {
 public:
  using NumericalError::NumericalError;
};

// A run that ended because its motion left the model's range (the lateral
// model's quasi-static wheel load reaching zero: a wheel lifting; a lateral
// shift or yaw beyond a geometry without flange contact). Numerical for a run
// (no running-safety verdict: the model cannot say what happens next), but
// it tells an analysis that the motion itself got there: a bifurcation sweep
// counts it as hunting when the lateral motion had grown.
class ModelRangeError : public NumericalError {
 public:
  using NumericalError::NumericalError;
};

// The user asked a running computation to stop (core/stop_request.hpp).
class InterruptedError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace railsim
