#pragma once
// madd.decompose, madd.mesh, madd.triangulate, madd.partition: the runs, with
// the GIL released while they work, a progress callback that may stop them,
// and Ctrl-C (KeyboardInterrupt) checked at every progress step.
#include <pybind11/pybind11.h>

namespace madd::python {

void bind_runs(pybind11::module_& m);

}  // namespace madd::python
