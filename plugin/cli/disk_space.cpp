#include "cli/disk_space.hpp"

#include <sys/statvfs.h>

#include "cli/destination.hpp"
#include "cpl_port.h"
#include "cpl_string.h"
#include "lib/errors.hpp"

namespace mcmd::cli {

namespace {

std::string size_text(std::uint64_t bytes) {
  const double gb = static_cast<double>(bytes) / 1e9;
  if (gb >= 1.0) return CPLString().Printf("%.1f GB", gb);
  return CPLString().Printf("%.1f MB", static_cast<double>(bytes) / 1e6);
}

}  // namespace

std::uint64_t uncompressed_bytes(GDALDataset& ds) {
  std::uint64_t bytes = 0;
  for (int b = 1; b <= ds.GetRasterCount(); ++b)
    bytes += static_cast<std::uint64_t>(ds.GetRasterXSize()) * static_cast<std::uint64_t>(ds.GetRasterYSize()) *
             static_cast<std::uint64_t>(GDALGetDataTypeSizeBytes(ds.GetRasterBand(b)->GetRasterDataType()));
  return bytes;
}

void check_space(const std::string& dst, std::uint64_t bytes, const std::string& what) {
  if (STARTS_WITH(dst.c_str(), "/vsi")) return;
  const std::string dir = folder_of(dst);
  struct statvfs st {};
  if (::statvfs(dir.c_str(), &st) != 0) return;  // unknown: the writes will tell
  const std::uint64_t free = static_cast<std::uint64_t>(st.f_bavail) * static_cast<std::uint64_t>(st.f_frsize);
  if (bytes > free)
    throw gdal::Failure(CPLE_FileIO, "cannot write '" + dst + "': it needs " + size_text(bytes) + " (" + what +
                                         ") and folder '" + dir + "' has " + size_text(free) + " free");
}

}  // namespace mcmd::cli
