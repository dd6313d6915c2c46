// The extension module rastrace._rastrace: one bind_* function per area (one file each). The
// package rastrace (python/rastrace/__init__.py) re-exports it.
#include <pybind11/pybind11.h>

namespace rastrace::python {

namespace py = pybind11;

void bind_errors(py::module_& m);
void bind_meshes(py::module_& m);
void bind_orderings(py::module_& m);
void bind_render(py::module_& m);
void bind_traces(py::module_& m);
void bind_caches(py::module_& m);

}  // namespace rastrace::python

PYBIND11_MODULE(_rastrace, m) {
  namespace python = rastrace::python;
  m.doc() = "rastrace's engine: meshes, orderings, vertex caches, rendering, traces, replays and sweeps";
  m.attr("__version__") = RASTRACE_VERSION;
  python::bind_errors(m);
  python::bind_meshes(m);
  python::bind_orderings(m);
  python::bind_render(m);
  python::bind_traces(m);
  python::bind_caches(m);
}
