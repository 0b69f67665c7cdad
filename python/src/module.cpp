// mcmd._mcmd: the extension module under the Python package mcmd
// (python/mcmd/__init__.py checks and converts the arguments; this binds the
// GDAL glue's band fill and the CLI's run with the GIL released).
#include <climits>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "arguments.hpp"
#include "array_fill.hpp"
#include "chunk_fill.hpp"
#include "exceptions.hpp"
#include "file_fill.hpp"
#include "gdal.h"
#include "mcmd_gdal.h"
#include "python_progress.hpp"

namespace py = pybind11;
using namespace mcmd::python;

namespace {

int dimension(py::ssize_t n) {
  if (n < 1 || n > INT_MAX) throw std::invalid_argument("array dimension " + std::to_string(n) + " is out of range");
  return static_cast<int>(n);
}

MemoryRaster raster_of(py::array& out, const std::string& gdal_type) {
  const bool native = out.dtype().attr("isnative").cast<bool>();
  if (out.ndim() != 2 || !(out.flags() & py::array::c_style) || !out.writeable() || !native)
    throw std::invalid_argument("fill_array expects a writeable C-contiguous 2-D array in native byte order");
  MemoryRaster r = memory_raster(gdal_type.c_str(), out.mutable_data(), dimension(out.shape(1)),
                                 dimension(out.shape(0)));
  if (out.itemsize() != GDALGetDataTypeSizeBytes(r.type))
    throw std::invalid_argument("array item size does not match GDAL type " + gdal_type);
  return r;
}

const std::uint8_t* valid_cells(const std::optional<py::array>& valid, const py::array& out) {
  if (!valid) return nullptr;
  if (valid->ndim() != 2 || valid->shape(0) != out.shape(0) || valid->shape(1) != out.shape(1) ||
      valid->itemsize() != 1 || !(valid->flags() & py::array::c_style))
    throw std::invalid_argument("fill_array expects a C-contiguous uint8 mask of the array's shape");
  return static_cast<const std::uint8_t*>(valid->data());
}

// Runs `fill` with the GIL released; a Python exception that stopped it (the
// callback's, or KeyboardInterrupt) is raised instead of the cancellation.
template <class Fill>
void without_gil(PythonProgress& progress, Fill&& fill) {
  try {
    const py::gil_scoped_release nogil;
    fill();
  } catch (...) {
    progress.raise_pending();
    throw;
  }
}

void fill_array(py::array out, std::optional<py::array> valid, const std::string& gdal_type, py::object nodata,
                const std::vector<std::string>& options, py::object callback, std::optional<py::array> filled) {
  const MemoryRaster raster = raster_of(out, gdal_type);
  const std::uint8_t* mask = valid_cells(valid, out);
  std::uint8_t* written = filled ? const_cast<std::uint8_t*>(valid_cells(filled, out)) : nullptr;
  if (filled && !filled->writeable()) throw std::invalid_argument("fill_array's `filled` must be writeable");
  const Nodata nd = nodata_of(nodata, raster.type);
  const mcmd::gdal::Options parsed = parse_options(options);
  PythonProgress progress(std::move(callback));
  without_gil(progress, [&] { fill_memory_raster(raster, mask, nd, parsed, progress.as_fn(), written); });
}

void fill_file_(const std::vector<std::string>& flags, const std::string& src, const std::string& dst,
                py::object callback) {
  PythonProgress progress(std::move(callback));
  without_gil(progress, [&] { fill_file(flags, src, dst, progress.as_fn()); });
}

}  // namespace

PYBIND11_MODULE(_mcmd, m) {
  m.doc() = "mcmd's extension module; use the package mcmd (mcmd.fill, mcmd.fill_file).";
  GDALAllRegister();
  register_exceptions(m);
  m.attr("__version__") = MCMDVersion();
  m.def("fill_array", &fill_array, py::arg("out"), py::arg("valid"), py::arg("gdal_type"), py::arg("nodata"),
        py::arg("options"), py::arg("progress"), py::arg("filled") = py::none(),
        "Fill the voids of `out` (C-contiguous, 2-D, native byte order, of GDAL type `gdal_type`) in place; "
        "`filled` (uint8 of out's shape, optional) gets 1 at every cell written.");
  m.def("fill_file", &fill_file_, py::arg("flags"), py::arg("src"), py::arg("dst"), py::arg("progress"),
        "Run mcmd_fillnodata's code: `flags` as the CLI takes them, dst '' = in place.");
  register_chunk_fill(m);
}
