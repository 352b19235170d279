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
    // A number, or what float() takes; anything else is the TypeError float() raises.
    const py::object value = state_->function(x, y);
    const py::object number = py::reinterpret_steal<py::object>(PyNumber_Float(value.ptr()));
    if (!number) throw py::error_already_set();
    return PyFloat_AS_DOUBLE(number.ptr());
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
