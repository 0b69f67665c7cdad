#include "cli/output_driver.hpp"

#include <cstdlib>

#include "lib/errors.hpp"

namespace mcmd::cli {

using gdal::Failure;

namespace {

constexpr const char* kInstead = "write GTiff or COG instead (lossless compression: -co COMPRESS=DEFLATE)";

GDALDriver* driver_by_extension(const std::string& dst) {
  const std::string ext = CPLGetExtension(dst.c_str());
  if (ext.empty() || EQUAL(ext.c_str(), "tif") || EQUAL(ext.c_str(), "tiff"))
    return GetGDALDriverManager()->GetDriverByName("GTiff");
  auto* manager = GetGDALDriverManager();
  for (int i = 0; i < manager->GetDriverCount(); ++i) {
    GDALDriver* d = manager->GetDriver(i);
    const char* exts = d->GetMetadataItem(GDAL_DMD_EXTENSIONS);
    const bool writes = d->GetMetadataItem(GDAL_DCAP_CREATE) || d->GetMetadataItem(GDAL_DCAP_CREATECOPY);
    if (!exts || !writes || !d->GetMetadataItem(GDAL_DCAP_RASTER)) continue;
    const CPLStringList list(CSLTokenizeString(exts));
    if (list.FindString(ext.c_str()) >= 0) return d;
  }
  return GetGDALDriverManager()->GetDriverByName("GTiff");
}

bool is(GDALDriver* d, const char* name) { return EQUAL(d->GetDescription(), name); }

// The creation option `name` (case-insensitive), or `otherwise`.
std::string option(const CPLStringList& co, const char* name, const char* otherwise = "") {
  const char* v = co.FetchNameValue(name);
  return v ? v : otherwise;
}

bool option_is(const CPLStringList& co, const char* name, const char* value) {
  return EQUAL(option(co, name).c_str(), value);
}

bool option_true(const CPLStringList& co, const char* name) {
  const char* v = co.FetchNameValue(name);
  return v && CPLTestBool(v);
}

// Drivers whose output holds no data of its own.
const char* without_data(GDALDriver* d) {
  if (is(d, "VRT")) return "a VRT only points at other files (here a temporary one, deleted at the end)";
  if (is(d, "MEM")) return "MEM writes no file: the raster would exist only in memory";
  if (is(d, "WMS") || is(d, "WMTS")) return "it only describes a web service";
  return nullptr;
}

// Drivers and options that move or resample the cells.
const char* resamples(GDALDriver* d, const CPLStringList& co) {
  if (is(d, "MBTiles")) return "it reprojects the raster to Web Mercator tiles";
  if (is(d, "KMLSUPEROVERLAY")) return "it writes reprojected image tiles";
  if (is(d, "COG") && (!option(co, "TILING_SCHEME").empty() && !option_is(co, "TILING_SCHEME", "CUSTOM")))
    return "-co TILING_SCHEME reprojects and resamples the raster";
  if (is(d, "COG") && (co.FetchNameValue("TARGET_SRS") || co.FetchNameValue("RES") || co.FetchNameValue("EXTENT")))
    return "-co TARGET_SRS, RES or EXTENT warp the raster";
  return nullptr;
}

// What makes a GeoTIFF or COG lossy, as "" when nothing does.
std::string lossy_tiff(GDALDriver* d, const CPLStringList& co) {
  const std::string compress = option(co, "COMPRESS");
  if (EQUAL(compress.c_str(), "JPEG")) return "-co COMPRESS=JPEG is lossy";
  if (EQUAL(compress.c_str(), "WEBP")) {
    const bool lossless = is(d, "COG") ? option_is(co, "QUALITY", "100") : option_true(co, "WEBP_LOSSLESS");
    if (!lossless)
      return is(d, "COG") ? "-co COMPRESS=WEBP is lossy unless -co QUALITY=100"
                          : "-co COMPRESS=WEBP is lossy unless -co WEBP_LOSSLESS=TRUE";
  }
  if (STARTS_WITH_CI(compress.c_str(), "LERC") && std::atof(option(co, "MAX_Z_ERROR", "0").c_str()) != 0.0)
    return "-co MAX_Z_ERROR=" + option(co, "MAX_Z_ERROR") + " makes LERC lossy";
  if (EQUAL(compress.c_str(), "JXL") && co.FetchNameValue("JXL_LOSSLESS") && !option_true(co, "JXL_LOSSLESS"))
    return "-co JXL_LOSSLESS=NO is lossy";
  if (co.FetchNameValue("DISCARD_LSB")) return "-co DISCARD_LSB drops bits of every cell";
  return "";
}

// What makes `d` with `co` lossy for cells of `bits` bits, as "" when
// nothing the rules know of does.
std::string lossy(GDALDriver* d, const CPLStringList& co, int bits) {
  if (is(d, "JPEG")) return "JPEG is lossy";
  if (is(d, "WEBP") && !option_true(co, "LOSSLESS")) return "WEBP is lossy unless -co LOSSLESS=YES";
  if (is(d, "JP2OpenJPEG")) {
    const bool best = option_is(co, "QUALITY", "100");
    if (!best || (co.FetchNameValue("REVERSIBLE") && !option_true(co, "REVERSIBLE")))
      return "JPEG 2000 is lossy unless -co QUALITY=100 -co REVERSIBLE=YES";
  }
  if (is(d, "GTiff") || is(d, "COG")) {
    const std::string why = lossy_tiff(d, co);
    if (!why.empty()) return why;
  }
  if ((is(d, "PDF") && (option_is(co, "COMPRESS", "JPEG") || option_is(co, "COMPRESS", "JPEG2000"))) ||
      (is(d, "NITF") && (option_is(co, "IC", "C3") || option_is(co, "IC", "M3"))) ||
      (is(d, "PCIDSK") && STARTS_WITH_CI(option(co, "COMPRESSION").c_str(), "JPEG")) ||
      (is(d, "MRF") && (option_is(co, "COMPRESS", "JPEG") || option_is(co, "COMPRESS", "JPNG"))) ||
      (is(d, "GPKG") && (option_is(co, "TILE_FORMAT", "JPEG") || option_is(co, "TILE_FORMAT", "WEBP"))))
    return std::string(d->GetDescription()) + " with these creation options is lossy (JPEG)";
  if (const char* nbits = co.FetchNameValue("NBITS"); nbits && std::atoi(nbits) < bits)
    return std::string("-co NBITS=") + nbits + " keeps fewer than the " + std::to_string(bits) + " bits of a cell";
  return "";
}

// GDAL 3.5 and 3.6 GeoTIFF writes 64-bit integers without listing them.
bool holds_type(GDALDriver* d, GDALDataType type) {
  const char* types = d->GetMetadataItem(GDAL_DMD_CREATIONDATATYPES);
  if (!types) return true;  // not said: the check after writing decides
  const CPLStringList list(CSLTokenizeString(types));
  if (list.FindString(GDALGetDataTypeName(type)) >= 0) return true;
  return is(d, "GTiff") && (type == GDT_Int64 || type == GDT_UInt64);
}

std::string band_cells(int b, GDALDataType type) {
  return "band " + std::to_string(b) + "'s " + GDALGetDataTypeName(type) + " cells";
}

[[noreturn]] void refuse(GDALDriver* d, const std::string& why) {
  throw Failure(CPLE_NotSupported, std::string("cannot write ") + d->GetDescription() + ": " + why);
}

}  // namespace

GDALDriver* output_driver(const std::string& format, const std::string& dst) {
  GDALDriver* d = format.empty() ? driver_by_extension(dst) : GetGDALDriverManager()->GetDriverByName(format.c_str());
  if (!d) throw Failure(CPLE_IllegalArg, "unknown output format '" + format + "' (see gdalinfo --formats)");
  if (!d->GetMetadataItem(GDAL_DCAP_RASTER) ||
      (!d->GetMetadataItem(GDAL_DCAP_CREATE) && !d->GetMetadataItem(GDAL_DCAP_CREATECOPY)))
    throw Failure(CPLE_IllegalArg, std::string("output format '") + d->GetDescription() + "' cannot write rasters");
  return d;
}

void check_output_driver(GDALDriver* driver, const CPLStringList& co, GDALDataset& src) {
  if (const char* why = without_data(driver)) refuse(driver, std::string(why) + "; write GTiff or COG instead");
  if (const char* why = resamples(driver, co))
    refuse(driver, std::string(why) + ": valid cells would change; " + kInstead);
  for (int b = 1; b <= src.GetRasterCount(); ++b) {
    const GDALDataType type = src.GetRasterBand(b)->GetRasterDataType();
    if (!holds_type(driver, type))
      refuse(driver, "it cannot hold " + band_cells(b, type) + " (it writes " +
                         driver->GetMetadataItem(GDAL_DMD_CREATIONDATATYPES) + "); " + kInstead);
    const std::string why = lossy(driver, co, GDALGetDataTypeSizeBits(type));
    if (!why.empty()) refuse(driver, why + ": " + band_cells(b, type) + " would change; " + kInstead);
  }
}

}  // namespace mcmd::cli
