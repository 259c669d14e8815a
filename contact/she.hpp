// The Shen-Hedrick-Elkins (1983) saturation law on given linear coefficients,
// shared by the model "she" (coefficients from Kalker's table at the patch's
// a/b) and the model "coefficients" with saturation "she" (coefficients from
// the geometry). Formula, source and validity flag: she.cpp.
// Units: SI; signs as in types.hpp.
#pragma once

#include "contact/linear_theory.hpp"
#include "contact/types.hpp"

namespace railsim::contact {

// Kalker's linear forces for `f` and in.creep saturated on the resultant with
// the SHE cubic (bound mu Fz from `in`); flagged invalid when
// |f23 phi| > 0.3 mu Fz. No allocation.
ContactForces she_forces(const LinearCoefficients& f, const ContactInput& in);

}  // namespace railsim::contact
