#pragma once
// madd.Mesh, madd.Decomposition, madd.Triangulation and madd.Partition: the
// results, their arrays (views, no copy), checks, figures and writers
// (docs/python.md, "Results").
#include <pybind11/pybind11.h>

namespace madd::python {

void bind_results(pybind11::module_& m);

}  // namespace madd::python
