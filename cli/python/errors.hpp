#pragma once
// madd's errors as Python exceptions (docs/python.md, "Errors"): one class per
// madd::ErrorKind under madd.Error, each also a subclass of the built-in
// exception a Python caller already catches (BadInput and OptionError are
// ValueErrors, OutputError an OSError), carrying what the C++ error carries.
#include <pybind11/pybind11.h>

namespace madd::python {

// Creates the exception classes in `m` and registers the translator of
// every madd::Error (and of std::bad_alloc, as MemoryError).
void bind_errors(pybind11::module_& m);

}  // namespace madd::python
