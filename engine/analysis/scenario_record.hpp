// What a result was computed with, as JSON for summaries: scenario, vehicle,
// wheelset model, wheel-rail geometry with its equivalent conicity
// (equivalent_conicity.hpp), contact model and its saturation law, material
// (mu, E, nu, G of the creep forces) and the reduction factors as the user
// gave them (a preset name only when a preset was chosen, numbers otherwise;
// for a third-body layer its parameters, the nominal patch it was computed
// for and the computed factors). Units SI unless a key says otherwise.
#pragma once

#include "engine/io/scenario.hpp"
#include "results/json_writer.hpp"

namespace railsim::engine {

// The reduction entry of a summary: {"given", "form", "label", "k11", "k22", "k23"[, "layer"]}.
results::Json reduction_record(const Scenario& sc);

// {"scenario", "vehicle", "wheelset_model", "geometry", "equivalent_conicity",
//  "contact_model", "saturation_law", "material", "reduction"}.
results::Json scenario_record(const Scenario& sc);

// Saturation law of the scenario's creep forces, in words (the tangential
// model's own for registry models; none / she for the coefficients mode).
std::string saturation_law(const Scenario& sc);

}  // namespace railsim::engine
