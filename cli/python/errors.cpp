#include "errors.hpp"

#include <pybind11/stl.h>

#include <array>
#include <exception>
#include <new>
#include <string>

#include "madd/error.hpp"

namespace py = pybind11;

namespace madd::python {

namespace {

// One class per ErrorKind, in the enum's order; set once by bind_errors.
std::array<PyObject*, 6> classes{};

PyObject* new_class(py::module_& m, const char* name, PyObject* bases, const char* doc) {
  const std::string qualified = std::string("madd.") + name;
  PyObject* cls = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, bases, nullptr);
  if (cls == nullptr) throw py::error_already_set();
  m.add_object(name, py::handle(cls));
  return cls;
}

PyObject* bases_of(PyObject* first, PyObject* second) {
  return py::make_tuple(py::handle(first), py::handle(second)).release().ptr();
}

// The exception object for `e`, with the attributes its subclass carries.
py::object exception_for(const Error& e) {
  PyObject* cls = classes[static_cast<std::size_t>(e.kind())];
  py::object error = py::reinterpret_steal<py::object>(PyObject_CallFunction(cls, "s", e.what()));
  if (!error) throw py::error_already_set();
  error.attr("kind") = to_string(e.kind());
  error.attr("message") = std::string(e.what());
  if (const auto* parse = dynamic_cast<const ParseError*>(&e)) {
    error.attr("path") = parse->path();
    error.attr("line") = parse->line();
    error.attr("column") = parse->column();
    error.attr("message") = parse->message();
  } else if (const auto* input = dynamic_cast<const InvalidInputError*>(&e)) {
    error.attr("problem") = to_string(input->problem());
    error.attr("ids") = py::cast(input->ids());
    py::list points;
    for (const Point p : input->points()) points.append(py::make_tuple(p.x, p.y));
    error.attr("points") = points;
    error.attr("path") = input->path().empty() ? py::object(py::none()) : py::cast(input->path());
    error.attr("line") = input->line();
    error.attr("column") = input->column();
  } else if (const auto* option = dynamic_cast<const OptionError*>(&e)) {
    error.attr("option") = option->option();
    error.attr("requirement") = option->requirement();
  } else if (const auto* split = dynamic_cast<const DecompositionError*>(&e)) {
    error.attr("subdomain") = split->subdomain();
    error.attr("area") = split->area();
    error.attr("separator_angle_deg") = split->separator_angle_deg();
  }
  return error;
}

void translate(std::exception_ptr thrown) {
  try {
    if (thrown) std::rethrow_exception(thrown);
  } catch (const Error& e) {
    const py::object error = exception_for(e);
    PyErr_SetObject(reinterpret_cast<PyObject*>(Py_TYPE(error.ptr())), error.ptr());
  } catch (const std::bad_alloc&) {
    PyErr_SetString(PyExc_MemoryError, "out of memory");
  }
}

}  // namespace

void bind_errors(py::module_& m) {
  PyObject* base = new_class(m, "Error", PyExc_Exception,
                             "Base of every error madd raises on purpose; `kind` names its madd::ErrorKind and "
                             "`message` its text.");
  classes[static_cast<std::size_t>(ErrorKind::bad_option)] =
      new_class(m, "OptionError", bases_of(base, PyExc_ValueError),
                "An option out of its range, or options that contradict each other. `option` names the "
                "keyword (the C++ field), `requirement` the rule it broke.");
  classes[static_cast<std::size_t>(ErrorKind::bad_input)] =
      new_class(m, "BadInput", bases_of(base, PyExc_ValueError),
                "An input could not be read or parsed, or is not a valid domain. `path`, `line` and `column` "
                "locate it in a file; `problem`, `ids` (0-based for arrays, the file's base for files) and "
                "`points` say what is wrong.");
  classes[static_cast<std::size_t>(ErrorKind::decomposition)] =
      new_class(m, "DecompositionError", bases_of(base, PyExc_RuntimeError),
                "No decomposition meets the separator angle bound at these settings. `subdomain`, `area` and "
                "`separator_angle_deg` say where.");
  classes[static_cast<std::size_t>(ErrorKind::output)] =
      new_class(m, "OutputError", bases_of(base, PyExc_OSError), "An output could not be written; nothing was.");
  classes[static_cast<std::size_t>(ErrorKind::limit)] =
      new_class(m, "LimitError", bases_of(base, PyExc_RuntimeError),
                "A resource limit (time_limit_seconds, max_memory_bytes) was reached; nothing is returned.");
  classes[static_cast<std::size_t>(ErrorKind::internal)] =
      new_class(m, "InternalError", bases_of(base, PyExc_RuntimeError),
                "A self-check failed: a bug in madd, never a problem with the input.");
  py::register_exception_translator(translate);
}

}  // namespace madd::python
