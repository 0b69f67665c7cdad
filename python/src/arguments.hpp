// Python arguments as the GDAL glue takes them: the NAME=VALUE options
// (parsed by the CLI's parser) and a nodata value of the band's type.
#pragma once

#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include "array_fill.hpp"
#include "gdal.h"
#include "lib/options.hpp"

namespace mcmd::python {

// Throws gdal::OptionError with the CLI's message.
gdal::Options parse_options(const std::vector<std::string>& options);

// None: no nodata value; an exact integer for (U)Int64 bands, else a double.
Nodata nodata_of(const pybind11::object& nodata, GDALDataType type);

}  // namespace mcmd::python
