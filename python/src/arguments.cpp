#include "arguments.hpp"

#include "cpl_string.h"

namespace mcmd::python {

gdal::Options parse_options(const std::vector<std::string>& options) {
  CPLStringList list;
  for (const std::string& o : options) list.AddString(o.c_str());
  return gdal::parse_options(list.List());
}

Nodata nodata_of(const pybind11::object& nodata, GDALDataType type) {
  if (nodata.is_none()) return {};
  if (type == GDT_Int64) return nodata.cast<std::int64_t>();
  if (type == GDT_UInt64) return nodata.cast<std::uint64_t>();
  return nodata.cast<double>();
}

}  // namespace mcmd::python
