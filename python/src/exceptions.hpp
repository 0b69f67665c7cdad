// mcmd.Error and mcmd.Cancelled, and the translation of the library's C++
// exceptions into Python ones: bad arguments and options (the CLI's
// UsageError, gdal::OptionError, std::invalid_argument, a Failure with
// CPLE_IllegalArg) become ValueError with the CLI's message; a cancelled fill
// mcmd.Cancelled; other failures (I/O, no valid cell...) mcmd.Error.
#pragma once

#include <pybind11/pybind11.h>

namespace mcmd::python {

// Adds Error and Cancelled to `m` and registers the translator.
void register_exceptions(pybind11::module_& m);

}  // namespace mcmd::python
