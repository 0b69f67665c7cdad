// Small voids solved alone (internal to the tiled fill; docs/tiling.md,
// "Small voids"). A small component's discrete thin-plate problem depends only
// on the known cells within 2 cells of it, so it is solved in its own 2^k+1
// grid whose size and place depend only on the component's bounding box: any
// run builds the identical grid and gets identical values, whatever the tile
// layout around it, so the component needs neither windows nor blending.
#pragma once

#include <cstdint>
#include <vector>

#include "common/grid.hpp"
#include "mcmd/params.hpp"
#include "mcmd/progress.hpp"
#include "morphology/lines.hpp"
#include "raster/coarse_guide.hpp"
#include "raster/tiles/tile_layout.hpp"
#include "raster/tiles/tile_window.hpp"
#include "raster/void_components.hpp"
#include "raster/void_field.hpp"

namespace mcmd::detail {

// Cells kept around a component's bounding box, at least, on every side:
// kSmallVoidMargin + extent / kSmallVoidMarginDivisor (extent: the box's longer side).
constexpr int kSmallVoidMargin = 8;
constexpr int kSmallVoidMarginDivisor = 8;
int small_void_margin(int extent);

// The largest bounding-box side solved alone: half a tile, at most
// kMaxSmallExtent, and its grid never larger than a tile's 2^n+1 window.
// Below 1: no component is solved alone.
constexpr int kMaxSmallExtent = 128;
int max_small_extent(const TileLayout& layout);

struct ComponentGrid {
  int levels = 0;
  int ox = 0, oy = 0;  // global raster coordinates of grid cell (0, 0)
  ReadRect rect;       // raster cells the grid needs (reflected into the raster)
};
ComponentGrid component_grid(const Box& box, int width, int height);

// How far from its centre the grid of any component solved alone reaches
// (0: none is solved alone).
int small_grid_reach(const TileLayout& layout);

// Fill the component (its grid read as `z`/`valid` over g.rect). Other void
// cells of the grid, and component cells farther than `radius` from every
// known cell, are pinned to the guide. Returns the values of the component's
// cells, run after run.
std::vector<double> solve_component(const SmallComponent& c, const ComponentGrid& g, int width, int height,
                                    const double* z, const std::uint8_t* valid, const CoarseGuide& guide,
                                    double radius, const FillParams& params, const ProgressFn& progress,
                                    const std::vector<morph::LineCell>& lines = {});

// With -morph auto: the component solved in its void field (`field`, read as
// `z`/`valid`), channels routed from the field's own drainage, as a raster
// filled whole solves each void (void_field.hpp): the values depend on the
// field's cells and the guide only. Cells deeper than field_pin_radius are
// pinned to the guide, as there: at the tiles' guide radius (8 cells on a
// 1025² raster) the pins kept the channels from the valley floor (valley F1
// 0.483 against the whole raster's 0.563). Returns the values of the
// component's cells, run after run.
std::vector<double> solve_component_in_field(const SmallComponent& c, const Box& field, std::vector<double> z,
                                             const std::uint8_t* valid, const CoarseGuide& guide,
                                             const FillParams& params, const ProgressFn& progress,
                                             const std::vector<morph::LineCell>& lines);

}  // namespace mcmd::detail
