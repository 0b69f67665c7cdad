#include "dataset.hpp"

namespace mcmd::cli {

void copy_band_info(GDALRasterBand& from, GDALRasterBand& to) {
  to.SetDescription(from.GetDescription());
  if (const char* unit = from.GetUnitType(); unit && *unit) to.SetUnitType(unit);
  int has = FALSE;
  const double offset = from.GetOffset(&has);
  if (has) to.SetOffset(offset);
  const double scale = from.GetScale(&has);
  if (has) to.SetScale(scale);
}

}  // namespace mcmd::cli
