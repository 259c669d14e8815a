// railsim._railsim: the compiled part of the Python package railsim (pybind11,
// Jakob et al. 2017-). railsim's InputError and NumericalError become the
// Python exceptions railsim.InputError (a ValueError) and
// railsim.NumericalError (an ArithmeticError) carrying railsim's message; a
// computation stopped by Ctrl-C (InterruptedError) raises KeyboardInterrupt.
#include <pybind11/pybind11.h>

#include "core/data_dir.hpp"
#include "core/errors.hpp"
#include "core/version.hpp"
#include "python/src/bindings.hpp"

namespace py = pybind11;

PYBIND11_MODULE(_railsim, m) {
  m.doc() = "railsim: railway vehicle dynamics with pluggable wheel-rail contact (compiled part)";
  m.attr("__version__") = railsim::kVersion;
  static py::exception<railsim::InputError> input_error(m, "InputError", PyExc_ValueError);
  static py::exception<railsim::NumericalError> numerical_error(m, "NumericalError", PyExc_ArithmeticError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const railsim::InputError& e) {
      input_error(e.what());
    } catch (const railsim::NumericalError& e) {
      numerical_error(e.what());
    } catch (const railsim::InterruptedError& e) {
      // Stopped by Ctrl-C (keyboard_interrupt.hpp): the KeyboardInterrupt the check raised.
      if (PyErr_Occurred() == nullptr) PyErr_SetString(PyExc_KeyboardInterrupt, e.what());
    }
  });
  m.def("data_dir", &railsim::data_dir, "The data folder railsim reads (profiles, plots, vehicles, tracks, scenarios)");
  railsim::python::bind_contact(m);
  railsim::python::bind_geometry(m);
  railsim::python::bind_scenario(m);
}
