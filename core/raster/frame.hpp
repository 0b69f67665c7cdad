// Rasters whose values are so large that the solver's sums and squares
// would overflow (|z| beyond 1e100: Float64 near ±1.8e308 filled NaN) are
// solved in a shifted and scaled frame, z' = (z - shift) / scale, and the
// filled values mapped back. A path of the engine sees the known range
// before it solves or writes anything: there it throws ExtremeRange, and
// fill_raster runs it again through a framed RasterAccess. Every other
// raster is filled exactly as before (one comparison).
#pragma once

#include "mcmd/params.hpp"
#include "mcmd/raster_access.hpp"

namespace mcmd::detail {

// Known values beyond this magnitude are solved in a frame.
constexpr double kFrameFrom = 1e100;

// Thrown by a path that met a known range [lo, hi] needing a frame.
struct ExtremeRange {
  double lo, hi;
};

// Throws ExtremeRange when the known range [lo, hi] needs a frame, and
// std::invalid_argument when it is not finite (a read's known value is not).
void check_range(double lo, double hi);

struct Frame {
  double shift = 0.0;
  double scale = 1.0;  // a power of two: the scaling itself is exact
};

// The frame that maps [lo, hi] into [-1, 1].
Frame frame_for(double lo, double hi);

// `raster` seen through `frame`: reads give (z - shift) / scale at known
// cells, writes take framed values (z' · scale + shift, ±inf beyond the
// range of doubles).
RasterAccess framed(const RasterAccess& raster, const Frame& frame);

// `params` for the framed raster (an explicit noise unit is an elevation).
FillParams framed(const FillParams& params, const Frame& frame);

}  // namespace mcmd::detail
