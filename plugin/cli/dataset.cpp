#include "cli/dataset.hpp"

#include "lib/errors.hpp"

namespace mcmd::cli {

using gdal::Failure;

namespace {

// GDAL's message about the temporary `path`, naming `shown` instead.
void replace_all(std::string& msg, const std::string& from, const std::string& to) {
  for (std::size_t at = msg.find(from); !from.empty() && at != std::string::npos; at = msg.find(from, at + to.size()))
    msg.replace(at, from.size(), to);
}

std::string named_as(std::string msg, const std::string& path, const std::string& shown) {
  replace_all(msg, path, shown);
  replace_all(msg, CPLGetFilename(path.c_str()), CPLGetFilename(shown.c_str()));
  return msg;
}

}  // namespace

DatasetPtr create_copy(GDALDriver* driver, const std::string& path, GDALDataset& from, CSLConstList co,
                       ErrorLog& log, GDALProgressFunc progress, void* progress_arg, const std::string& shown) {
  log.reset();
  DatasetPtr out(driver->CreateCopy(path.c_str(), &from, FALSE, co, progress, progress_arg));
  if (!out) {
    if (CPLGetLastErrorNo() == CPLE_UserInterrupt) throw Failure(CPLE_UserInterrupt, "cancelled by the user");
    const std::string why = log.first_failure().empty() ? CPLGetLastErrorMsg() : log.first_failure();
    throw Failure(CPLE_FileIO, "cannot write '" + shown + "': " + named_as(why, path, shown));
  }
  return out;
}

DatasetPtr reopen_for_update(DatasetPtr ds, const std::string& path, const std::string& shown) {
  ds.reset();
  CPLErrorReset();
  DatasetPtr again(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER | GDAL_OF_UPDATE));
  if (!again) throw Failure(CPLE_FileIO, "cannot reopen '" + shown + "' for filling: " + CPLGetLastErrorMsg());
  return again;
}

void copy_band_info(GDALDataset& from, GDALDataset& to) {
  for (int b = 1; b <= from.GetRasterCount(); ++b) {
    GDALRasterBand& f = *from.GetRasterBand(b);
    GDALRasterBand& t = *to.GetRasterBand(b);
    t.SetDescription(f.GetDescription());
    if (const char* unit = f.GetUnitType(); unit && *unit) t.SetUnitType(unit);
    int has = FALSE;
    const double offset = f.GetOffset(&has);
    if (has) t.SetOffset(offset);
    const double scale = f.GetScale(&has);
    if (has) t.SetScale(scale);
  }
}

}  // namespace mcmd::cli
