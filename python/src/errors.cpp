// rastrace::InputError (bad input: a malformed file, an unknown option value, an impossible
// cache) reaches Python as rastrace.InputError, a ValueError, with the message the command line
// prints after "rastrace: ".
#include <pybind11/pybind11.h>

#include "core/error.h"

namespace rastrace::python {

namespace py = pybind11;

void bind_errors(py::module_& m) { py::register_exception<InputError>(m, "InputError", PyExc_ValueError); }

}  // namespace rastrace::python
