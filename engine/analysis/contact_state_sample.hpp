// The contact states of a run and a sample of them for the contact audit
// (run_contact_audit.hpp).
//
// ContactStateRecorder keeps, at every output of a run (the observer of
// simulate(), the same evaluation the channels come from), the tangential
// model's input of every loaded patch of every wheel (Data::patch: Hertzian
// patch a, b, A, B, p0 and normal load, creepages xi, eta, phi, material,
// mu, reduction factors, rolling speed) with what the run's model returned,
// the time, the vehicle reference distance, wheelset, side and contact angle.
// Memory: about 250 bytes per patch and output (a 6 s run of a four-axle
// vehicle at 5 ms output: about 10,000 patches, 2.5 MB).
//
// sample_contact_states() picks n of them:
//  1. the extremes, in this order (each once, a state already chosen is not
//     taken twice): largest normal load, largest |phi|, largest |(xi, eta)|,
//     largest contact angle (flange contact), largest |F|/(mu N) of the run's
//     own model (the most saturated), largest and smallest a/b, largest |xi|,
//     largest |eta|; when n is smaller than their number, the first n;
//  2. the rest evenly in time: sample j of m goes to the output row
//     floor((j + 1/2) R / m) of the R rows with loaded patches, and there to
//     its patch j mod (patches in the row) (the next one when that is already
//     chosen), so successive samples also walk through the wheels;
//  3. n at least the number of recorded states: all of them.
// Deterministic (no random numbers). Units SI.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "contact/types.hpp"
#include "engine/data.hpp"
#include "engine/model.hpp"

namespace railsim::engine {

struct RunContactState {
  double t = 0.0;          // [s]
  double distance = 0.0;   // vehicle reference distance [m]
  int wheelset = 0;        // index into Model::wheelsets
  int side = 0;            // 0 left, 1 right
  int point = 0;           // patch / potential contact point of the wheel
  double contact_angle = 0.0;  // [rad]
  contact::ContactInput input;     // what the run's tangential model was given
  contact::ContactForces forces;   // what it returned
};

class ContactStateRecorder {
 public:
  // Every loaded patch of the evaluation `d` (simulate()'s reporting Data,
  // which records them). One output row per call.
  void record(const Model& model, double t, const Data& d);
  const std::vector<RunContactState>& states() const { return states_; }
  // First state of each output row (rows without loaded patches are not kept).
  const std::vector<std::size_t>& row_start() const { return row_start_; }
  std::size_t rows() const { return row_start_.size(); }

 private:
  std::vector<RunContactState> states_;
  std::vector<std::size_t> row_start_;
};

struct ContactStateSample {
  std::vector<std::size_t> index;  // into ContactStateRecorder::states(), in the order chosen
  std::vector<std::string> why;    // per sample: "max normal load", ..., "even in time", "all"
};

// Bounds of n (inclusive).
constexpr int kMinAuditSamples = 1;
constexpr int kMaxAuditSamples = 10000;

// Throws InputError for n outside [1, 10000] or a recorder without states.
ContactStateSample sample_contact_states(const ContactStateRecorder& recorder, int n);

}  // namespace railsim::engine
