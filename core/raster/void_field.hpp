// One void component solved in its own field (internal to the small-raster
// path, whole_raster.hpp; docs/tiling.md, "Small rasters"): the component's
// bounding box grown by void_field_margin cells on every side, clipped to the
// raster, filled by the smooth default method. Other voids inside the field are
// solved with it but are not its output. The values depend on the field's
// cells only, so any run, thread count or tile layout gives the same ones.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "common/grid.hpp"
#include "mcmd/params.hpp"
#include "mcmd/progress.hpp"
#include "morphology/lines.hpp"
#include "raster/coarse_guide.hpp"
#include "raster/void_components.hpp"

namespace mcmd::detail {

// min(32, 8 + 2·extent) + extent, extent the box's longer side: measured on
// the blob benchmark (docs/tiling.md); small voids need less context (a
// 1-cell void gets 11 cells, not 33: same RMSE to 4 digits, blobs 8 % faster).
constexpr int kVoidFieldMargin = 32;
int void_field_margin(int extent);
Box void_field_rect(const Box& box, int width, int height);

// The longest run of void cells along a row of a w×h field. A void cell d
// cells from data lies in a run of at least 2d - 1: half of it bounds every
// distance to data.
int longest_void_run(const std::uint8_t* valid, int w, int h);

// Other voids' cells in a field are pinned to the guide when they are at
// least this many and at least as many as the component's own cells.
constexpr std::size_t kPinOthersMin = 64;

// A field's unknown cells farther than field_pin_radius(S) from data are
// pinned to a coarse guide of stride S: kGuideRadiusStrides · S, S at least
// kMinGuideStride (a raster filled whole builds its guide at that stride at
// least; the tiles' when larger).
constexpr int kMinGuideStride = 4;
double field_pin_radius(int guide_stride);

// Unknown cells farther than `radius` from data, and other voids' cells (see
// kPinOthersMin), are pinned to the guide that `guide()` returns, called only
// by a field that has such cells (it may build the guide then; empty function
// or null result: no pins).
struct DeepPins {
  std::function<const CoarseGuide*()> guide;
  double radius = 0.0;
};

// The raster's morphology: the known terrain's accumulation draining into a
// void per raster cell (morphology/channels.hpp's inflow_into_voids; null:
// each field computes its own with -morph auto), and the line cells in
// voids, sorted by (y, x) (morphology/lines.hpp; null: none).
struct RasterMorphology {
  const double* inflow = nullptr;
  int width = 0;  // of the raster
  const std::vector<morph::LineCell>* lines = nullptr;
};

struct VoidFieldResult {
  double farthest = 0.0;            // of the component's cells from data
  std::vector<double> values;       // the component's cells, run after run
  std::vector<std::uint8_t> write;  // and whether each lies within max distance
};

// Pre: z and valid hold the field `rect` (row-major, raster coordinates of
// rect), which contains the component's runs and a known ring around them;
// z is taken over as the solver's work array.
// Post: when the component reaches far (reaches_far: the coarse guide's
// tension is needed) values is empty: the caller must fill it another way.
// `threads` run the solver of a large field (same result for any count).
// With -morph auto or line cells in the field, it is filled with its
// morphology (morphology/channel_fill.hpp).
VoidFieldResult solve_void_field(const Box& rect, const std::vector<VoidRun>& runs, std::vector<double> z,
                                 const std::uint8_t* valid, const DeepPins& pins, const FillParams& params,
                                 double max_distance, const ProgressFn& progress = {}, int threads = 1,
                                 const RasterMorphology& morphology = {});

}  // namespace mcmd::detail
