#include "exceptions.hpp"

#include <new>
#include <stdexcept>

#include "lib/errors.hpp"
#include "mcmd/progress.hpp"

namespace py = pybind11;

namespace mcmd::python {

namespace {

PyObject* g_error = nullptr;
PyObject* g_cancelled = nullptr;

PyObject* type_of(const gdal::Failure& f) {
  switch (f.num()) {
    case CPLE_UserInterrupt: return g_cancelled;
    case CPLE_IllegalArg: return PyExc_ValueError;
    default: return g_error;
  }
}

void translate(std::exception_ptr p) {
  try {
    std::rethrow_exception(p);
  } catch (const py::error_already_set&) {
    throw;  // pybind11's own: left to its translators
  } catch (const py::builtin_exception&) {
    throw;
  } catch (const Cancelled& e) {
    PyErr_SetString(g_cancelled, e.what());
  } catch (const gdal::Failure& e) {
    PyErr_SetString(type_of(e), e.what());
  } catch (const std::invalid_argument& e) {
    PyErr_SetString(PyExc_ValueError, e.what());
  } catch (const std::bad_alloc&) {
    PyErr_SetString(PyExc_MemoryError, "out of memory: the raster is too large to fill in memory");
  } catch (const std::exception& e) {
    PyErr_SetString(g_error, e.what());
  }
}

}  // namespace

void register_exceptions(py::module_& m) {
  g_error = PyErr_NewExceptionWithDoc(
      "mcmd.Error",
      "A fill that failed: a file that cannot be read or written, a band with no valid cell, "
      "an I/O error. The message is the one mcmd_fillnodata prints.",
      PyExc_RuntimeError, nullptr);
  g_cancelled = PyErr_NewExceptionWithDoc(
      "mcmd.Cancelled", "A fill stopped by its progress callback (which returned False); nothing is left behind.",
      g_error, nullptr);
  if (!g_error || !g_cancelled) throw py::error_already_set();
  m.attr("Error") = py::handle(g_error);
  m.attr("Cancelled") = py::handle(g_cancelled);
  py::register_exception_translator(&translate);
}

}  // namespace mcmd::python
