#include "values.hpp"

#include <exception>
#include <limits>
#include <mutex>

namespace madd::python {

void DomainValue::check_domain(const ValidateOptions& options) const {
  if (is_domain.load() && !options.check_weights) return;
  validate(coast.domain, source, options);
  is_domain.store(true);
}

struct PythonFunction::State {
  py::object function;
  std::mutex mutex;
  std::exception_ptr failure;
  ~State() {
    py::gil_scoped_acquire gil;  // a Python exception and the callable are freed with the GIL held
    failure = nullptr;
    function = py::object();
  }
};

PythonFunction::PythonFunction(py::object f) : state_(new State{std::move(f), {}, {}}, [](State* s) { delete s; }) {}

double PythonFunction::operator()(double x, double y) const {
  {
    std::lock_guard lock(state_->mutex);
    if (state_->failure) return std::numeric_limits<double>::quiet_NaN();
  }
  py::gil_scoped_acquire gil;
  try {
    // A number (anything with __float__ or __index__); else the TypeError Python raises.
    const py::object value = state_->function(x, y);
    const double number = PyFloat_AsDouble(value.ptr());
    if (number == -1.0 && PyErr_Occurred() != nullptr) throw py::error_already_set();
    return number;
  } catch (...) {
    std::lock_guard lock(state_->mutex);
    if (!state_->failure) state_->failure = std::current_exception();
    return std::numeric_limits<double>::quiet_NaN();
  }
}

void PythonFunction::rethrow_if_failed() const {
  std::exception_ptr failure;
  {
    std::lock_guard lock(state_->mutex);
    failure = state_->failure;
  }
  if (failure) std::rethrow_exception(failure);
}

}  // namespace madd::python
