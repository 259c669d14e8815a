// The parts of the Python module railsim._railsim, one file each:
// bind_contact.cpp (contact models on arrays, the MIM fields), bind_geometry.cpp
// (profiles, wheel-rail geometry, conicity), bind_scenario.cpp (scenarios, run,
// critical speed, modes). module.cpp defines the module and the exceptions;
// keyboard_interrupt.hpp lets Ctrl-C stop a long engine call.
#pragma once

#include <pybind11/pybind11.h>

namespace railsim::python {

void bind_contact(pybind11::module_& m);
void bind_geometry(pybind11::module_& m);
void bind_scenario(pybind11::module_& m);

}  // namespace railsim::python
