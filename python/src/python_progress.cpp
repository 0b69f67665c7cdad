#include "python_progress.hpp"

#include <utility>

namespace py = pybind11;

namespace mcmd::python {

PythonProgress::PythonProgress(py::object callback) : callback_(std::move(callback)) {}

bool PythonProgress::operator()(double fraction) {
  const auto now = std::chrono::steady_clock::now();
  if (last_ && fraction < 1.0 && now - *last_ < kMinInterval) return true;
  last_ = now;
  const py::gil_scoped_acquire gil;
  return call_python(fraction);
}

bool PythonProgress::call_python(double fraction) {
  try {
    if (!callback_.is_none()) {
      const py::object answer = callback_(fraction);
      if (!answer.is_none()) {
        const int go_on = PyObject_IsTrue(answer.ptr());
        if (go_on < 0) throw py::error_already_set();
        if (go_on == 0) return false;
      }
    }
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    return true;
  } catch (py::error_already_set& e) {
    pending_.emplace(std::move(e));
    return false;
  }
}

void PythonProgress::raise_pending() {
  if (!pending_) return;
  py::error_already_set e = std::move(*pending_);
  pending_.reset();
  throw e;
}

}  // namespace mcmd::python
