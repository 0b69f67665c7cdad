// The steps of the chunked fill (mcmd/chunked_fill.hpp) on numpy blocks, for
// mcmd.dask: a block is a part of the raster held in memory at a known
// place, read and written through the CLI's own band access (a MEM band,
// lib/band_access.hpp), so voids, nodata, masks and the encoding of filled
// cells are the CLI's.
#pragma once

#include <memory>

#include <pybind11/pybind11.h>

namespace mcmd::python {

void register_chunk_fill(pybind11::module_& m);

}  // namespace mcmd::python
