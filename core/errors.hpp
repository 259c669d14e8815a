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
// The command-line program maps them to exit codes 2 and 3.
#pragma once

#include <stdexcept>
#include <string>

namespace railsim {

inline constexpr int kExitSuccess = 0;
inline constexpr int kExitBadInput = 2;
inline constexpr int kExitNumericalFailure = 3;

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

}  // namespace railsim
