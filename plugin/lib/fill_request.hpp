// What a band fill is asked to do, besides the algorithm's options: which
// masks mark the voids, and where the filled cells go.
#pragma once

#include <functional>
#include <vector>

#include "gdal_priv.h"

namespace mcmd::gdal {

struct FillRequest {
  std::vector<GDALRasterBand*> masks;  // validity masks, 0 = void (see read_window)
  bool require_void_marker = false;    // fail when no mask and no NaN marks a void
  bool use_nodata = true;              // honour the band's nodata value (see read_window)
  int band_number = 0;                 // for messages; 0 = unnamed
  bool blank_target = false;           // the target (a copy) holds no cell yet: write them all
};

// The target band as a function called at the first write (it may wait for
// a copy being made), for a target that is not the source.
using TargetBand = std::function<GDALRasterBand&()>;

}  // namespace mcmd::gdal
