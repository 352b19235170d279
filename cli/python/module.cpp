// The Python module madd._madd (docs/python.md): the library's values and
// runs, bound with pybind11; madd/__init__.py adds the shapely and meshio
// conversions on top.
#include <pybind11/pybind11.h>

#include "domain.hpp"
#include "errors.hpp"
#include "results.hpp"
#include "runs.hpp"

PYBIND11_MODULE(_madd, m) {
  // The docstrings say the signature themselves (as the CLI's help), in Python's terms.
  pybind11::options options;
  options.disable_function_signatures();
  m.doc() = "madd: Medial Axis Domain Decomposition and parallel quality meshing in 2D (the compiled core).";
  madd::python::bind_errors(m);
  madd::python::bind_domain(m);
  madd::python::bind_results(m);
  madd::python::bind_runs(m);
#ifdef MADD_VERSION_STRING
  m.attr("__version__") = MADD_VERSION_STRING;
#endif
}
