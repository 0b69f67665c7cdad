// The roughness of a field (roughness.hpp): where the noise is made (the
// wanted unknown cells and their surroundings, block by block), the octaves
// (octaves.hpp), their calibration from the terrain (statistics.hpp,
// calibration.hpp), cropped to where it is not 0.
#include "roughness/roughness.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "common/distance.hpp"
#include "roughness/blocks.hpp"
#include "roughness/calibration.hpp"
#include "roughness/octaves.hpp"
#include "roughness/statistics.hpp"

namespace mcmd {

namespace {

using namespace rough;

// The cells whose noise a fill uses: its wanted unknown cells (targets) and the
// cells within kNoiseReach cells (Chebyshev) of one. The discrete thin plate at an
// unknown cell involves no constraint farther than 2 cells; the finest
// level's pull towards the cascade (length 8) sees farther, through the coarse
// levels, and a reach of 2 let the noise's coarse octaves through deep inside
// large voids (blob RMSE median 0.941 at 8, 0.955 at 2, 0.938 at 16 and with
// whole 32² blocks around the voids: docs/default-method.md).
constexpr int kNoiseReach = 8;
std::vector<std::uint8_t> noise_cells(const std::vector<std::uint8_t>& target, const Area& a) {
  return within_chebyshev(target.data(), a.w, a.h, kNoiseReach);
}

// Whether the cell is one the noise is made for: unknown and wanted.
bool is_target(const RoughField& g, std::size_t i) { return !is_constraint(g.state[i]) && (!g.wanted || g.wanted[i]); }

// The bounding box of the target cells (empty: x1 <= x0). With a wanted mask
// (a void's own cells: a small part of its field), the mask's rows are
// scanned 8 bytes at a time.
Rect target_bounds(const RoughField& g) {
  Rect b{g.w, 0, g.h, 0};
  for (int y = 0; y < g.h; ++y) {
    const std::size_t row = g.index(0, y);
    int x = 0;
    if (g.wanted)
      for (std::uint64_t word; x + 8 <= g.w; x += 8) {
        std::memcpy(&word, g.wanted + row + x, sizeof word);
        if (word) break;
      }
    while (x < g.w && !is_target(g, row + x)) ++x;
    if (x == g.w) continue;
    int last = g.w - 1;
    if (g.wanted)
      for (std::uint64_t word; last - 7 > x; last -= 8) {
        std::memcpy(&word, g.wanted + row + last - 7, sizeof word);
        if (word) break;
      }
    while (!is_target(g, row + last)) --last;
    b = Rect{std::min(b.x0, x), std::max(b.x1, last + 1), std::min(b.y0, y), y + 1};
  }
  return b;
}

// The target cells of an area, all inside rectangle `t` of it: row by row,
// with and without a wanted mask, so that the loops vectorise.
std::vector<std::uint8_t> target_mask(const RoughField& g, const Area& a, const Rect& t) {
  std::vector<std::uint8_t> mask(a.cells());
  for (int y = t.y0; y < t.y1; ++y) {
    const CellState* state = g.state + g.index(t.x0, y);
    std::uint8_t* m = mask.data() + a.index(t.x0, y);
    const int n = t.x1 - t.x0;
    if (g.wanted) {
      const std::uint8_t* wanted = g.wanted + g.index(t.x0, y);
      for (int x = 0; x < n; ++x) m[x] = (state[x] == CellState::unknown) & (wanted[x] != 0);
    } else {
      for (int x = 0; x < n; ++x) m[x] = state[x] == CellState::unknown;
    }
  }
  return mask;
}


// The bounding box of the `mask` cells (over area `a`) in a rectangle of it
// (empty: x1 <= x0).
Rect mask_bounds(const Area& a, const std::vector<std::uint8_t>& mask, Rect r) {
  Rect b{r.x1, r.x0, r.y1, r.y0};
  for (int y = r.y0; y < r.y1; ++y) {
    const std::uint8_t* m = mask.data() + a.index(a.x0, y);
    const auto at = [&](int x) { return m[x - a.x0]; };
    int first = r.x0;
    while (first < r.x1 && !at(first)) ++first;
    if (first == r.x1) continue;
    int last = r.x1 - 1;
    while (!at(last)) --last;
    b = Rect{std::min(b.x0, first), std::max(b.x1, last + 1), std::min(b.y0, y), y + 1};
  }
  return b;
}

// Each block's box of `mask` cells (over area `a`): the blocks holding one
// become active, and their noise is made and scaled over that box only.
void set_noise_boxes(const RoughField& g, const Area& a, const std::vector<std::uint8_t>& mask, Blocks& b) {
  for (int bj = 0; bj < b.ny; ++bj)
    for (int bi = 0; bi < b.nx; ++bi) {
      const Rect block{std::max(b.x0(bi), a.x0), std::min(b.x1(bi, g.w), a.x0 + a.w), std::max(b.y0(bj), a.y0),
                       std::min(b.y1(bj, g.h), a.y0 + a.h)};
      b.noise_box[b.index(bi, bj)] = block.empty() ? Rect{0, 0, 0, 0} : mask_bounds(a, mask, block);
    }
}
// The area the noise of a field covers: its target cells (bounds `t`) grown
// by kNoiseReach, widened to whole blocks and one cell more (the Laplacian at
// a block's edge), inside the field. Empty without target cells.
Area noise_area(const RoughField& g, const Blocks& b, const Rect& t) {
  if (t.x1 <= t.x0) return Area{};
  const auto block_of = [](int v, int offset) { return (v + offset) / kBlock; };
  const int x0 = b.x0(block_of(std::max(0, t.x0 - kNoiseReach), b.ox));
  const int x1 = b.x1(block_of(std::min(g.w, t.x1 + kNoiseReach) - 1, b.ox), g.w);
  const int y0 = b.y0(block_of(std::max(0, t.y0 - kNoiseReach), b.oy));
  const int y1 = b.y1(block_of(std::min(g.h, t.y1 + kNoiseReach) - 1, b.oy), g.h);
  Area a;
  a.x0 = std::max(0, x0 - 1);
  a.y0 = std::max(0, y0 - 1);
  a.w = std::min(g.w, x1 + 1) - a.x0;
  a.h = std::min(g.h, y1 + 1) - a.y0;
  return a;
}

// d (over area `a`) cut down to the union of the blocks' noise boxes,
// outside which it is 0: a small void's area is whole 32² blocks, its noise
// a few cells.
Displacement crop_to_noise(const Area& a, const Blocks& b, Displacement d) {
  Rect r{a.x0 + a.w, a.x0, a.y0 + a.h, a.y0};
  for (const Rect& box : b.noise_box)
    if (!box.empty())
      r = Rect{std::min(r.x0, box.x0), std::max(r.x1, box.x1), std::min(r.y0, box.y0), std::max(r.y1, box.y1)};
  if (r.empty()) return {};
  if (r.x1 - r.x0 == a.w && r.y1 - r.y0 == a.h) return d;
  Displacement out{r.x0, r.y0, r.x1 - r.x0, r.y1 - r.y0, {}};
  out.values.reserve(static_cast<std::size_t>(out.w) * out.h);
  for (int y = r.y0; y < r.y1; ++y) {
    const auto from = d.values.begin() + static_cast<std::ptrdiff_t>(a.index(r.x0, y));
    out.values.insert(out.values.end(), from, from + out.w);
  }
  return out;
}

}  // namespace

double Displacement::at(int x, int y) const {
  if (x < x0 || y < y0 || x >= x0 + w || y >= y0 + h || values.empty()) return 0.0;
  return values[static_cast<std::size_t>(y - y0) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x - x0)];
}

std::vector<double> Displacement::whole(int field_w, int field_h) const {
  std::vector<double> out(static_cast<std::size_t>(field_w) * static_cast<std::size_t>(field_h), 0.0);
  for (int y = y0; y < y0 + h && !values.empty(); ++y)
    for (int x = x0; x < x0 + w; ++x) out[static_cast<std::size_t>(y) * field_w + x] = at(x, y);
  return out;
}

Displacement roughness_displacement(const RoughField& grid, const FillParams& params, int threads) {
  if (!adds_roughness(params)) return {};
  Blocks blocks = block_lattice(grid);
  std::vector<LagSums> pairs;
  double H = params.H;
  RoughnessModel global;
  if (params.rs_auto) {
    pairs = pair_sums(grid, blocks, threads);
    global = model_of(variogram_of(pairs));
    if (!global.valid) return {};
    H = global.H;
  }
  const Rect targets = target_bounds(grid);
  const Area area = noise_area(grid, blocks, targets);
  if (area.cells() == 0) return {};
  // Unconditioned noise at the noise cells only (0 elsewhere).
  const std::vector<std::uint8_t> target = target_mask(grid, area, targets);
  const std::vector<std::uint8_t> mask = noise_cells(target, area);
  set_noise_boxes(grid, area, mask, blocks);
  const int octaves = params.rs_auto ? auto_octaves(grid.depth) : kOctaves;
  Amplitude amplitude;
  if (params.rs_auto) {  // the terrain's Laplacian variance around each block
    amplitude.blocks = &blocks;
    amplitude.scales = block_scales(blocks, LagTable(pairs, blocks), global, noise_laplacian_variance(H, octaves));
  } else {  // the coarsest octave's amplitude is rs · unit
    const double unit = params.noise_unit > 0 ? params.noise_unit
                                              : known_range({grid.z, grid.cells()}, {grid.state, grid.cells()});
    amplitude.constant = params.rs * unit * std::exp2(-(kOctaves - 1) * H);
  }
  Displacement d{area.x0, area.y0, area.w, area.h, std::vector<double>(area.cells(), 0.0)};
  add_noise(grid, area, blocks, mask, params.seed, H, octaves, amplitude, d.values, threads);
  return crop_to_noise(area, blocks, std::move(d));
}

}  // namespace mcmd
