#include "single_field.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "mcmd/coarse_guide.hpp"
#include "mcmd/distance.hpp"
#include "mcmd/thin_plate_schedule.hpp"

namespace mcmd::detail {

bool single_field_applies(int width, int height, const FillParams& params, const TilingParams& tiling) {
  const bool smooth_default = params.method == Method::mcmd && !params.rs_auto && params.rs == 0;
  const std::size_t cells = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  return smooth_default && tiling.tile_side == 0 && cells <= kSingleFieldMaxCells;
}

namespace {

// Deep inside large voids the surface is a coarse guide's, as in tiles
// (docs/tiling.md): unknown cells farther than the guide radius from data are
// pinned to it. With the guide stride of tiles (1 up to 1025 cells a side:
// no guide) one field and tiles agree on what a deep void is.
void pin_deep_cells(int w, int h, const std::vector<double>& dist, double farthest, const std::vector<std::uint8_t>& valid,
                    const FillParams& params, std::vector<double>& z, std::vector<CellState>& state) {
  const int stride = guide_stride(w, h);
  const double radius = kGuideRadiusStrides * stride;
  if (stride == 1 || farthest <= radius) return;
  CoarseGuide guide(w, h, stride);
  guide.add_rows(0, h, z.data(), valid.data());
  guide.solve(params);
  for (std::size_t i = 0; i < dist.size(); ++i)
    if (dist[i] > radius) {
      z[i] = guide.at(static_cast<long long>(i % w), static_cast<long long>(i / w));
      state[i] = CellState::known;
    }
}

}  // namespace

bool fill_single_field(const RasterAccess& raster, const FillParams& params, const TilingParams& tiling,
                       const ProgressFn& progress, TiledFillStats* stats) {
  const int w = raster.width, h = raster.height;
  const std::size_t cells = static_cast<std::size_t>(w) * h;
  std::vector<double> z(cells);
  std::vector<std::uint8_t> valid(cells);
  report(progress, 0.0);
  raster.read(0, 0, w, h, z.data(), valid.data());

  TiledFillStats st;
  for (std::uint8_t v : valid) (v ? st.known_cells : st.void_cells) += 1;
  if (stats) *stats = st;
  if (st.void_cells == 0) {
    report(progress, 1.0);
    return true;
  }
  if (st.known_cells == 0) throw std::invalid_argument("the raster has no known cell to fill from");

  // A void reaching far from data needs the guide's tension at a coarse
  // scale and the guide's surface deep inside (one field under tension,
  // solved to the usual tolerance, still carried a coast's slope 2 km up):
  // leave such rasters to the tiles.
  const std::vector<double> dist = distance_to_valid(valid.data(), w, h);
  const double farthest = *std::max_element(dist.begin(), dist.end());
  if (far_void_tension(farthest, 1) > 0) return false;
  report(progress, 0.05);

  std::vector<CellState> state(cells);
  for (std::size_t i = 0; i < cells; ++i) state[i] = valid[i] ? CellState::known : CellState::unknown;
  pin_deep_cells(w, h, dist, farthest, valid, params, z, state);
  thin_plate_smooth(FieldView{w, h, z.data(), state.data()}, ThinPlateSchedule{}, sub_progress(progress, 0.05, 0.95));

  // Write the filled cells (those within max distance): reuse `valid` as the mask.
  const double md = tiling.max_distance;
  for (std::size_t i = 0; i < cells; ++i) {
    valid[i] = !valid[i] && (md <= 0 || dist[i] <= md) ? 1 : 0;
    st.cells_written += valid[i];
  }
  report(progress, 0.95);  // a refusal here leaves the raster untouched
  raster.write(0, 0, w, h, z.data(), valid.data());
  if (stats) *stats = st;
  report(progress, 1.0);
  return true;
}

}  // namespace mcmd::detail
