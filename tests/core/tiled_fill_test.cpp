// The tiled fill (docs/tiling.md): layout maths, completeness on odd raster
// sizes, seams, large voids, determinism across threads and processing order,
// cancellation and max distance — all through an in-memory RasterAccess.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <gtest/gtest.h>
#include <limits>
#include <numeric>
#include <random>
#include <vector>

#include "common/distance.hpp"
#include "common/padding.hpp"
#include "mcmd/fill_raster.hpp"
#include "method/fill_grid.hpp"
#include "raster/coarse_guide.hpp"
#include "raster/tiles/tile_layout.hpp"
#include "raster/tiles/tile_window.hpp"
#include "raster/void_selection.hpp"
#include "mem_raster.hpp"
#include "test_terrain.hpp"
#include "thin_plate/thin_plate.hpp"

using namespace mcmd;
using mcmd::test::MemRaster;
using mcmd::test::make_raster;
using mcmd::test::punch_disc;
using mcmd::test::terrain;
using mcmd::test::terrain_raster;

namespace {

// Hooks that record a run's statistics (not copyable: hooks point at stats).
struct Recorded {
  RasterFillStats stats;
  RasterFillHooks hooks;
  Recorded() { hooks.stats = &stats; }
  Recorded(const Recorded&) = delete;
};


std::vector<double> run(MemRaster& r, int tile, int threads, const RasterFillHooks& hooks = {}) {
  TilingParams tp;
  tp.tile_side = tile;
  tp.always_tile = tile != 0;  // these tests are about tiles
  tp.threads = threads;
  fill_raster(r.access(), FillParams{}, tp, {}, hooks);
  return r.out;
}

bool bit_identical(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

// Tile (tx, ty)'s window of `r`, solved with the guide of the whole raster.
WindowResult solve_tile(const MemRaster& r, const TileLayout& layout, const CoarseGuide& guide, int tx, int ty,
                        const FillParams& params) {
  WindowInput in;
  in.tx = tx;
  in.ty = ty;
  in.rect = window_read_rect(layout, tx, ty, params.method);
  for (int y = 0; y < in.rect.h; ++y)
    for (int x = 0; x < in.rect.w; ++x) {
      in.z.push_back(r.z[r.at(in.rect.x0 + x, in.rect.y0 + y)]);
      in.valid.push_back(r.valid[r.at(in.rect.x0 + x, in.rect.y0 + y)]);
    }
  return solve_window(layout, in, &guide, params, 0.0);
}

CoarseGuide whole_guide(const MemRaster& r) {
  CoarseGuide guide(r.w, r.h, guide_stride(r.w, r.h));
  guide.add_rows(0, r.h, r.z.data(), r.valid.data());
  EXPECT_TRUE(guide.solve(FillParams{}));
  return guide;
}

}  // namespace

TEST(TileLayout, AxisCoversTheRasterWithSharedBorders) {
  const TileAxis a(1000, 64);  // tiles of 65 cells
  EXPECT_EQ(a.count(), 16);    // ceil(999 / 64)
  EXPECT_EQ(a.band(), 8);
  EXPECT_EQ(a.window_side(), 129);
  EXPECT_EQ(a.window_origin(3), 3 * 64 - 32);
  EXPECT_EQ(TileAxis(1, 2).count(), 1);
  EXPECT_EQ(TileAxis(65, 64).count(), 1);
  EXPECT_EQ(TileAxis(66, 64).count(), 2);
  // Solo zones and seam bands partition the axis; weights sum to one.
  std::vector<int> covered(1000, 0);
  for (int t = 0; t < a.count(); ++t)
    for (int x = a.solo(t).begin; x < a.solo(t).end; ++x) ++covered[x];
  for (int s = 1; s < a.count(); ++s)
    for (int x = a.seam_band(s).begin; x < a.seam_band(s).end; ++x) ++covered[x];
  EXPECT_TRUE(std::all_of(covered.begin(), covered.end(), [](int c) { return c == 1; }));
  for (int x = 0; x < 1000; ++x) {
    double sum = 0.0;
    for (int t = 0; t < a.count(); ++t) {
      const double w = a.weight(t, x);
      const Range r = a.region(t);
      EXPECT_EQ(w > 0.0, x >= r.begin && x < r.end) << "t=" << t << " x=" << x;
      sum += w;
    }
    EXPECT_NEAR(sum, 1.0, 1e-15);
    EXPECT_EQ(a.weight(a.owner(x), x) >= 0.5, true);
  }
  for (int t = 0; t < a.count(); ++t)  // the output region lies inside the window
    EXPECT_GE(a.region(t).begin, a.window_origin(t));
  EXPECT_EQ(a.weight(2, 2 * 64), 0.5);  // the shared border cell: half each
}

TEST(TileLayout, RampIsSmoothAndSymmetric) {
  EXPECT_EQ(blend_ramp(-1.0), 0.0);
  EXPECT_EQ(blend_ramp(2.0), 1.0);
  for (double u = 0.0; u <= 1.0; u += 0.01) EXPECT_NEAR(blend_ramp(u) + blend_ramp(1.0 - u), 1.0, 1e-14);
  const double e = 1e-6;  // zero slope at both ends: no kink where the band starts
  EXPECT_NEAR((blend_ramp(e) - blend_ramp(0.0)) / e, 0.0, 1e-6);
  EXPECT_NEAR((blend_ramp(1.0) - blend_ramp(1.0 - e)) / e, 0.0, 1e-6);
}

TEST(TileLayout, EffectiveTileSide) {
  EXPECT_EQ(effective_tile_side(5000, 300, 0, Method::mcmd), 513);
  EXPECT_EQ(effective_tile_side(5000, 300, 0, Method::paper_ds), 129);
  EXPECT_EQ(effective_tile_side(100, 60, 0, Method::mcmd), 129);
  EXPECT_EQ(effective_tile_side(1, 1, 0, Method::mcmd), 3);
  EXPECT_EQ(effective_tile_side(5000, 300, 257, Method::paper_ds), 257);
  EXPECT_THROW(effective_tile_side(100, 100, 100, Method::mcmd), std::invalid_argument);
  EXPECT_THROW(effective_tile_side(100, 100, 2, Method::mcmd), std::invalid_argument);
}

TEST(CoarseGuide, InterpolatesLatticeAndFillsGaps) {
  const int W = 64, H = 40;
  std::vector<double> z(W * H);
  std::vector<std::uint8_t> v(W * H, 1);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) z[y * W + x] = 2.0 * x - 3.0 * y + 10.0;
  for (int y = 10; y < 30; ++y)
    for (int x = 20; x < 50; ++x) v[y * W + x] = 0;
  CoarseGuide g(W, H, guide_stride(W, H, 9));
  EXPECT_EQ(g.stride(), 8);
  g.add_rows(0, 17, z.data(), v.data());
  g.add_rows(17, H - 17, z.data() + 17 * W, v.data() + 17 * W);
  ASSERT_TRUE(g.solve(FillParams{}));
  // A plane is kept by the block plane fits (also of partly known blocks),
  // the thin-plate fill and Catmull-Rom, up to the fits' regularisation and
  // the mirror padding of the lattice (5 rows padded to 9).
  EXPECT_NEAR(g.at(8, 8), 2.0 * 8 - 3.0 * 8 + 10.0, 0.05);
  EXPECT_NEAR(g.at(35, 20), 2.0 * 35 - 3.0 * 20 + 10.0, 1.0);
  EXPECT_NEAR(g.at(63, 39), 2.0 * 63 - 3.0 * 39 + 10.0, 1.0);
  EXPECT_EQ(g.at(-3, 5), g.at(3, 5));  // reflected outside the raster
}

TEST(TiledFill, OddRasterSizesFillCompletelyAndNeverWriteKnownCells) {
  const int sizes[][2] = {{1, 1}, {2, 2}, {3, 1000}, {1000, 3}, {256, 256}, {257, 257}, {258, 258}, {37, 91}};
  for (int tile : {5, 17, 65, 0}) {
    for (const auto& s : sizes) {
      MemRaster r = make_raster(s[0], s[1]);
      if (s[0] == 2) r.valid = {1, 0, 0, 1};
      const std::size_t voids = r.voids();
      RasterFillStats stats;
      RasterFillHooks hooks;
      hooks.stats = &stats;
      run(r, tile, 2, hooks);
      SCOPED_TRACE(testing::Message() << s[0] << "x" << s[1] << " tile " << tile);
      EXPECT_TRUE(r.complete());
      EXPECT_EQ(r.known_writes, 0u);
      EXPECT_EQ(r.writes, voids);  // each void cell written exactly once
      EXPECT_TRUE(std::all_of(r.write_count.begin(), r.write_count.end(), [](int c) { return c <= 1; }));
      for (std::size_t i = 0; i < r.z.size(); ++i)
        if (r.valid[i]) {
          ASSERT_EQ(r.out[i], r.z[i]);
        }
      EXPECT_EQ(stats.void_cells, voids);
    }
  }
}

TEST(TiledFill, FillsCloseToTheTerrain) {
  MemRaster r = make_raster(300, 200, 0.3);
  run(r, 65, 2);
  double se = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < r.z.size(); ++i)
    if (!r.valid[i]) {
      se += (r.out[i] - r.z[i]) * (r.out[i] - r.z[i]);
      ++n;
    }
  EXPECT_LT(std::sqrt(se / n), 10.0);  // elevation range ~900
}

// A void centred on a vertical seam and on a horizontal one: neighbouring
// windows agree where they overlap, and the blended surface has no jump or
// kink at the seam (second differences there like those inside the void).
TEST(TiledFill, VoidAcrossASeamIsOneSurface) {
  MemRaster r(257, 257);
  for (int y = 0; y < r.h; ++y)
    for (int x = 0; x < r.w; ++x) r.z[r.at(x, y)] = terrain(3 * x, 3 * y);
  punch_disc(r, 128, 100, 40);  // crosses seam x = 128 (tile 65: seams every 64)
  const std::vector<double> out = run(r, 65, 2);

  const TileLayout layout(r.w, r.h, 65);
  const CoarseGuide guide = whole_guide(r);
  FillParams p;
  p.noise_unit = 1.0;
  const auto window = [&](int tx, int ty) { return solve_tile(r, layout, guide, tx, ty, p); };
  const WindowResult a = window(1, 1), b = window(2, 1);  // seam x = 128 between them
  double max_diff = 0.0;
  for (int y = std::max(a.ys.begin, b.ys.begin); y < std::min(a.ys.end, b.ys.end); ++y)
    for (int x = b.xs.begin; x < a.xs.end; ++x) {
      if (r.valid[r.at(x, y)]) continue;
      const double fa = a.z[(y - a.ys.begin) * a.xs.size() + (x - a.xs.begin)];
      const double fb = b.z[(y - b.ys.begin) * b.xs.size() + (x - b.xs.begin)];
      max_diff = std::max(max_diff, std::abs(fa - fb));
    }
  EXPECT_LT(max_diff, 0.5) << "windows disagree on the overlap";

  // Second differences across the seam column vs elsewhere in the void.
  auto d2x = [&](int x, int y) { return std::abs(out[r.at(x - 1, y)] - 2 * out[r.at(x, y)] + out[r.at(x + 1, y)]); };
  auto d1x = [&](int x, int y) { return std::abs(out[r.at(x + 1, y)] - out[r.at(x, y)]); };
  double seam_d2 = 0.0, inner_d2 = 0.0, seam_d1 = 0.0, inner_d1 = 0.0;
  for (int y = 0; y < r.h; ++y)
    for (int x = 1; x < r.w - 1; ++x) {
      if (r.valid[r.at(x - 1, y)] || r.valid[r.at(x, y)] || r.valid[r.at(x + 1, y)]) continue;
      const bool at_seam = std::abs(x - 128) <= layout.x.band();
      (at_seam ? seam_d2 : inner_d2) = std::max(at_seam ? seam_d2 : inner_d2, d2x(x, y));
      (at_seam ? seam_d1 : inner_d1) = std::max(at_seam ? seam_d1 : inner_d1, d1x(x, y));
    }
  EXPECT_GT(inner_d2, 0.0);
  EXPECT_LE(seam_d2, 1.5 * inner_d2);
  EXPECT_LE(seam_d1, 1.5 * inner_d1);
}

// The default method solves a window's output region and some context
// around it, not the whole 2^n+1 window (each cell solved about 2.25 times at
// T = 129, not 4): known cells beyond that change nothing. The context is one
// blend band, or 4 cells where every cell lies near data, as with these
// scattered samples. A paper method still solves the whole window.
TEST(TiledFill, DefaultMethodSolvesTheRegionAndSomeContext) {
  MemRaster r(257, 257);
  std::mt19937 rng(7);
  for (int y = 0; y < r.h; ++y)
    for (int x = 0; x < r.w; ++x) {
      r.z[r.at(x, y)] = terrain(3 * x, 3 * y);
      r.valid[r.at(x, y)] = rng() % 10 == 0;  // scattered samples, every cell within 5 of one
    }
  const TileLayout layout(r.w, r.h, 65);  // window (1, 1): cells [32, 161); region [57, 136); band 8
  const int outside = layout.x.region(1).begin - 4;  // 53: the first cell solved
  MemRaster changed = r;
  for (int y = 0; y < r.h; ++y)
    for (int x = layout.x.window_origin(1); x < outside; ++x) changed.z[changed.at(x, y)] += 100.0;
  MemRaster inside = r;  // one column of samples within the context
  for (int y = 0; y < r.h; ++y) inside.z[inside.at(outside + 2, y)] += 100.0;
  const CoarseGuide guide = whole_guide(r);  // the same guide for all: only the window differs
  for (const Method method : {Method::mcmd, Method::paper_ds}) {
    FillParams p;
    p.method = method;
    p.noise_unit = 1.0;
    const WindowResult a = solve_tile(r, layout, guide, 1, 1, p), b = solve_tile(changed, layout, guide, 1, 1, p);
    EXPECT_EQ(bit_identical(a.z, b.z), method == Method::mcmd) << "method " << static_cast<int>(method);
    EXPECT_FALSE(bit_identical(a.z, solve_tile(inside, layout, guide, 1, 1, p).z));
  }
}

// A region window solves only around the void cells it writes (grown by one
// band, snapped to 32 cells): a void in one corner of its region leaves the
// rest of the region unsolved, so known cells beyond that part change none of
// the written values, although they lie within the region and its band.
TEST(TiledFill, WindowSolvesOnlyAroundTheVoidsItWrites) {
  MemRaster r(257, 257);
  for (int y = 0; y < r.h; ++y)
    for (int x = 0; x < r.w; ++x) {
      r.z[r.at(x, y)] = terrain(3 * x, 3 * y);
      const int dx = x - 64, dy = y - 64;
      r.valid[r.at(x, y)] = dx * dx + dy * dy > 36;  // a disc in the corner of window (1, 1)'s region [57, 136)
    }
  const TileLayout layout(r.w, r.h, 65);
  MemRaster changed = r;
  for (int y = 100; y < 140; ++y)
    for (int x = 100; x < 140; ++x) changed.z[changed.at(x, y)] += 100.0;
  const CoarseGuide guide = whole_guide(r);
  FillParams p;
  p.noise_unit = 1.0;
  const WindowResult a = solve_tile(r, layout, guide, 1, 1, p), b = solve_tile(changed, layout, guide, 1, 1, p);
  std::size_t written = 0;
  for (std::size_t k = 0; k < a.z.size(); ++k) {
    ASSERT_EQ(a.write[k], b.write[k]);
    if (!a.write[k]) continue;
    ++written;
    EXPECT_EQ(a.z[k], b.z[k]) << "cell " << k;
  }
  EXPECT_EQ(written, static_cast<std::size_t>(std::count(r.valid.begin(), r.valid.end(), 0)));  // the disc
}

TEST(TiledFill, VoidLargerThanATileFills) {
  MemRaster r = terrain_raster(300, 260);
  for (int y = 20; y < 240; ++y)
    for (int x = 30; x < 270; ++x) r.valid[r.at(x, y)] = 0;  // 240×220 void, tiles of 33
  Recorded rec;
  RasterFillStats& stats = rec.stats;
  const RasterFillHooks& hooks = rec.hooks;
  run(r, 33, 2, hooks);
  EXPECT_TRUE(r.complete());
  EXPECT_EQ(r.known_writes, 0u);
  EXPECT_GT(stats.guide_stride, 0);
  const auto [lo, hi] = std::minmax_element(r.z.begin(), r.z.end());
  for (std::size_t i = 0; i < r.out.size(); ++i) {
    EXPECT_GT(r.out[i], *lo - 0.5 * (*hi - *lo));
    EXPECT_LT(r.out[i], *hi + 0.5 * (*hi - *lo));
  }
}

TEST(TiledFill, BitIdenticalForAnyThreadCountAndOrder) {
  MemRaster r = make_raster(301, 203, 0.2);
  punch_disc(r, 150, 100, 60);
  const std::vector<double> one = run(r, 33, 1);
  EXPECT_TRUE(bit_identical(one, run(r, 33, 2)));
  EXPECT_TRUE(bit_identical(one, run(r, 33, 4)));
  RasterFillHooks shuffled;
  shuffled.reorder = [](std::vector<std::size_t>& order) {
    std::mt19937 rng(7);
    std::shuffle(order.begin(), order.end(), rng);
  };
  EXPECT_TRUE(bit_identical(one, run(r, 33, 3, shuffled)));
  RasterFillHooks reversed;
  reversed.reorder = [](std::vector<std::size_t>& order) { std::reverse(order.begin(), order.end()); };
  EXPECT_TRUE(bit_identical(one, run(r, 33, 1, reversed)));
}

// Scattered samples (3.3 % kept): every window is one shallow field, solved
// with the structure term (thin_plate/structure_term.hpp), whose directions
// come from the window's own fill. Still the same bits for any thread count
// and order, and close to the terrain (relief ~1000 m).
TEST(TiledFill, ScatteredSamplesAreDeterministic) {
  MemRaster r(301, 233);
  for (int y = 0; y < r.h; ++y)
    for (int x = 0; x < r.w; ++x) {
      r.z[r.at(x, y)] = terrain(x, y);
      r.valid[r.at(x, y)] = (hash_uniform(5, x, y) + 1.0) / 2.0 < 0.033;
    }
  const std::vector<double> one = run(r, 129, 1);
  EXPECT_TRUE(bit_identical(one, run(r, 129, 2)));
  RasterFillHooks reversed;
  reversed.reorder = [](std::vector<std::size_t>& order) { std::reverse(order.begin(), order.end()); };
  EXPECT_TRUE(bit_identical(one, run(r, 129, 2, reversed)));
  double se = 0;
  for (std::size_t i = 0; i < one.size(); ++i) se += (one[i] - r.z[i]) * (one[i] - r.z[i]);
  EXPECT_LT(std::sqrt(se / static_cast<double>(r.voids())), 2.0);
}

TEST(TiledFill, TileSizesAgreeClosely) {
  MemRaster r = make_raster(300, 300, 0.1);
  const std::vector<double> a = run(r, 65, 2);
  const std::vector<double> b = run(r, 129, 2);
  double se_a = 0, se_b = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!r.valid[i]) {
      se_a += (a[i] - r.z[i]) * (a[i] - r.z[i]);
      se_b += (b[i] - r.z[i]) * (b[i] - r.z[i]);
    }
  EXPECT_NEAR(std::sqrt(se_a), std::sqrt(se_b), 0.03 * std::sqrt(se_b));
}

TEST(TiledFill, VoidFreeTilesAreNotSolved) {
  MemRaster r = terrain_raster(400, 400);
  punch_disc(r, 30, 30, 5);
  Recorded rec;
  RasterFillStats& stats = rec.stats;
  const RasterFillHooks& hooks = rec.hooks;
  run(r, 65, 2, hooks);
  EXPECT_EQ(stats.tiles_x * stats.tiles_y, 49);
  EXPECT_EQ(stats.windows_solved, 0u);  // a small void is solved alone
  EXPECT_EQ(stats.small_components, 1u);
  EXPECT_TRUE(r.complete());

  punch_disc(r, 300, 300, 60);  // larger than a small grid at tile 65 (extent > 129 - 16)
  run(r, 65, 2, hooks);
  EXPECT_EQ(stats.small_components, 1u);
  EXPECT_EQ(stats.windows_solved, 9u);  // the tiles whose output region meets its box
  EXPECT_TRUE(r.complete());

  MemRaster clean(100, 100);
  run(clean, 33, 2, hooks);
  EXPECT_EQ(clean.writes, 0u);
  EXPECT_EQ(stats.windows_solved, 0u);
}

TEST(TiledFill, MaxDistanceLeavesFarCellsUnwritten) {
  MemRaster r = terrain_raster(200, 150);
  punch_disc(r, 100, 75, 30);
  punch_disc(r, 20, 20, 6);
  TilingParams tp;
  tp.tile_side = 129;  // halo 64, band 16: exact up to 46 cells
  tp.always_tile = true;
  tp.max_distance = 10.0;
  fill_raster(r.access(), FillParams{}, tp);
  const std::vector<double> dist = distance_to_valid(r.valid.data(), r.w, r.h);
  for (std::size_t i = 0; i < dist.size(); ++i) {
    if (r.valid[i]) continue;
    EXPECT_EQ(r.write_count[i], dist[i] <= 10.0 ? 1 : 0) << i;
  }
}

// Max distances beyond what a window sees are decided on the guide lattice
// (exact here: a raster this small has a guide stride of 1).
TEST(TiledFill, MaxDistanceBeyondTheHaloUsesTheGuide) {
  MemRaster r = terrain_raster(200, 150);
  punch_disc(r, 100, 75, 60);
  TilingParams tp;
  tp.tile_side = 33;  // halo 16, band 4: exact up to 12 cells in a window
  tp.always_tile = true;
  tp.max_distance = 40.0;
  fill_raster(r.access(), FillParams{}, tp);
  const std::vector<double> dist = distance_to_valid(r.valid.data(), r.w, r.h);
  std::size_t written = 0, expected = 0;
  for (std::size_t i = 0; i < dist.size(); ++i) {
    if (r.valid[i]) continue;
    EXPECT_EQ(r.write_count[i], dist[i] <= 40.0 ? 1 : 0) << i;
    written += r.write_count[i];
    expected += dist[i] <= 40.0;
  }
  EXPECT_EQ(written, expected);
  EXPECT_LT(expected, r.voids());
}

TEST(TiledFill, CancelStopsWithCancelled) {
  MemRaster r = make_raster(300, 300, 0.2);
  TilingParams tp;
  tp.tile_side = 33;
  tp.threads = 2;
  tp.always_tile = true;
  int calls = 0;
  const ProgressFn stop = [&](double f) {
    ++calls;
    return f < 0.5;
  };
  EXPECT_THROW(fill_raster(r.access(), FillParams{}, tp, stop), Cancelled);
  EXPECT_GT(calls, 1);
  int last_calls = 0;
  double last = -1.0;
  bool monotone = true;
  const ProgressFn watch = [&](double f) {
    monotone = monotone && f >= last;
    last = f;
    ++last_calls;
    return true;
  };
  fill_raster(r.access(), FillParams{}, tp, watch);
  EXPECT_TRUE(monotone);
  EXPECT_EQ(last, 1.0);
}

// A small raster (one field per void, on 2 threads) stops too, writing nothing.
TEST(TiledFill, CancelInTheSmallRasterPathWritesNothing) {
  MemRaster r = make_raster(300, 300, 0.2);
  TilingParams tp;
  tp.threads = 2;
  const ProgressFn stop = [](double f) { return f < 0.5; };
  EXPECT_THROW(fill_raster(r.access(), FillParams{}, tp, stop), Cancelled);
  EXPECT_EQ(r.writes, 0u);
}

TEST(TiledFill, RejectsBadInput) {
  MemRaster r = make_raster(50, 50);
  TilingParams tp;
  tp.tile_side = 100;
  EXPECT_THROW(fill_raster(r.access(), FillParams{}, tp), std::invalid_argument);
  tp.tile_side = 17;
  tp.max_distance = -1;
  EXPECT_THROW(fill_raster(r.access(), FillParams{}, tp), std::invalid_argument);
  MemRaster empty(40, 30);
  std::fill(empty.valid.begin(), empty.valid.end(), 0);
  EXPECT_THROW(fill_raster(empty.access(), FillParams{}, TilingParams{}), std::invalid_argument);
}

TEST(TiledFill, HugeVoidDoesNotExtrapolateCoastSlopesIntoMountains) {
  // Half an SRTM tile void above a coast: sea (0 m) on the left, a slope
  // climbing 6 m per cell towards the void on the right. A plain thin plate
  // carries that slope a thousand cells into the void; the guide's tension
  // must level it off near the data's range.
  MemRaster r(1100, 1100);
  for (int y = 0; y < r.h; ++y)
    for (int x = 0; x < r.w; ++x) {
      const int from_void = y - 900;  // rows 900.. are known
      r.z[r.at(x, y)] = x < 550 ? 0.0 : std::max(0.0, 1000.0 - 6.0 * from_void);
      r.valid[r.at(x, y)] = y >= 900;
    }
  const std::vector<double> out = run(r, 0, 2);
  ASSERT_TRUE(r.complete());
  const auto [lo, hi] = std::minmax_element(out.begin(), out.end());
  EXPECT_LT(*hi, 1400.0);  // known range 0..1000
  EXPECT_GT(*lo, -400.0);
}

// Small voids (docs/tiling.md, "Small voids"): a component whose box fits a
// small grid is solved alone in a grid placed by its box, so its values do
// not depend on the tile layout, equal a direct fill of that grid, and every
// cell of it is written exactly once.
TEST(TiledFill, SmallVoidIsSolvedAloneWhateverTheTiles) {
  MemRaster r = terrain_raster(400, 300);
  punch_disc(r, 128, 128, 6);  // on a seam crossing of tiles 33, 65 and 129
  punch_disc(r, 3, 200, 6);    // against the raster's left border (mirrored)
  const std::vector<double> a = run(r, 33, 2);
  for (std::size_t i = 0; i < r.write_count.size(); ++i) EXPECT_EQ(r.write_count[i], r.valid[i] ? 0 : 1);
  const std::vector<double> b = run(r, 65, 1);
  const std::vector<double> c = run(r, 129, 3);
  EXPECT_TRUE(bit_identical(a, b));
  EXPECT_TRUE(bit_identical(a, c));

  // The same values as the default method on the component's grid, to a
  // window's tolerance: side 2^k+1 >= box side + 2·8, centred on the box
  // (13×13 box -> 33² grid at 128 - 16). No cell is farther than the guide
  // radius (8 here) from data: no guide pin.
  Grid g(5, 128 - 16, 128 - 16);
  for (int v = 0; v < g.side(); ++v)
    for (int u = 0; u < g.side(); ++u) {
      const std::size_t i = r.at(g.origin_x() + u, g.origin_y() + v);
      g.z(u, v) = r.z[i];
      g.state(u, v) = r.valid[i] ? CellState::known : CellState::unknown;
    }
  FillParams p;  // the tiled fill's noise unit: the known range of the raster
  double lo = 1e300, hi = -1e300;
  for (std::size_t i = 0; i < r.z.size(); ++i)
    if (r.valid[i]) lo = std::min(lo, r.z[i]), hi = std::max(hi, r.z[i]);
  p.noise_unit = hi - lo;
  ThinPlateSchedule pinned;
  pinned.pcg_tol = kPinnedPcgTolerance;
  thin_plate_fill_scheduled(g, p, pinned);
  for (int v = 0; v < g.side(); ++v)
    for (int u = 0; u < g.side(); ++u) {
      const std::size_t i = r.at(g.origin_x() + u, g.origin_y() + v);
      if (!r.valid[i]) {
        EXPECT_EQ(a[i], g.z(u, v)) << u << "," << v;
      }
    }
}

TEST(TiledFill, SmallAndLargeVoidsTogetherAreDeterministic) {
  MemRaster r = make_raster(401, 303, 0.01);  // scattered single cells: small components
  punch_disc(r, 200, 150, 70);                // a large one across several tiles
  punch_disc(r, 64, 64, 12);                  // a small one on a seam crossing
  Recorded rec;
  RasterFillStats& stats = rec.stats;
  const RasterFillHooks& hooks = rec.hooks;
  const std::vector<double> one = run(r, 65, 1, hooks);
  EXPECT_GT(stats.small_components, 100u);
  EXPECT_GT(stats.windows_solved, 0u);
  EXPECT_TRUE(r.complete());
  EXPECT_EQ(r.known_writes, 0u);
  for (std::size_t i = 0; i < r.write_count.size(); ++i) EXPECT_EQ(r.write_count[i], r.valid[i] ? 0 : 1);
  EXPECT_TRUE(bit_identical(one, run(r, 65, 2)));
  EXPECT_TRUE(bit_identical(one, run(r, 65, 4)));
  RasterFillHooks shuffled;
  shuffled.reorder = [](std::vector<std::size_t>& order) {
    std::mt19937 rng(3);
    std::shuffle(order.begin(), order.end(), rng);
  };
  EXPECT_TRUE(bit_identical(one, run(r, 65, 3, shuffled)));
  // Scattered single cells, solved alone, are close to the terrain.
  double se = 0;
  std::size_t n = 0;
  for (int y = 0; y < r.h; ++y)
    for (int x = 0; x < r.w; ++x) {
      const std::size_t i = r.at(x, y);
      if (r.valid[i] || std::hypot(x - 200, y - 150) < 85 || std::hypot(x - 64, y - 64) < 15 ||
          std::hypot(x - 0.4 * r.w, y - 0.6 * r.h) < 0.12 * r.w + 15)  // make_raster's disc
        continue;
      se += (one[i] - r.z[i]) * (one[i] - r.z[i]);
      ++n;
    }
  ASSERT_GT(n, 100u);
  EXPECT_LT(std::sqrt(se / n), 1.0);
}

// Small rasters (docs/tiling.md, "Small rasters"): a raster of at most 2^21
// cells, default tile size, is filled without tiles, each void component in
// its own field — its box grown by min(32, 8 + 2·e) + e, e its longer side (21
// here: 53) — so its values are
// that field's thin plate, whatever other voids the raster holds.
TEST(TiledFill, SmallRasterSolvesEachVoidInItsOwnField) {
  MemRaster r = terrain_raster(400, 300);
  punch_disc(r, 80, 90, 10);  // box [70, 90] × [80, 100], extent 21: field [17, 143] × [27, 153]
  Recorded rec;
  RasterFillStats& stats = rec.stats;
  const RasterFillHooks& hooks = rec.hooks;
  const std::vector<double> alone = run(r, 0, 1, hooks);
  EXPECT_EQ(stats.tile_side, 0);
  EXPECT_EQ(stats.windows_solved, 0u);
  EXPECT_EQ(stats.cells_written, r.voids());

  const int x0 = 17, y0 = 27, side = 127;
  std::vector<double> z(static_cast<std::size_t>(side) * side);
  std::vector<CellState> state(z.size());
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x) {
      z[static_cast<std::size_t>(y) * side + x] = r.z[r.at(x0 + x, y0 + y)];
      state[static_cast<std::size_t>(y) * side + x] =
          r.valid[r.at(x0 + x, y0 + y)] ? CellState::known : CellState::unknown;
    }
  thin_plate_smooth(FieldView{side, side, z.data(), state.data()}, ThinPlateSchedule{});
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x)
      ASSERT_EQ(alone[r.at(x0 + x, y0 + y)], z[static_cast<std::size_t>(y) * side + x]) << x << "," << y;

  // Other voids (one at a corner, one touching the first's field) change nothing of it.
  punch_disc(r, 2, 290, 12);
  punch_disc(r, 160, 100, 15);
  std::fill(r.write_count.begin(), r.write_count.end(), 0);
  const std::vector<double> both = run(r, 0, 2, hooks);
  for (std::size_t i = 0; i < r.write_count.size(); ++i) ASSERT_EQ(r.write_count[i], r.valid[i] ? 0 : 1);
  for (int y = 80; y <= 100; ++y)
    for (int x = 70; x <= 90; ++x) ASSERT_EQ(both[r.at(x, y)], alone[r.at(x, y)]);
  EXPECT_TRUE(r.complete());
  EXPECT_TRUE(bit_identical(run(r, 0, 1), both));
}

// Fills `r` without tiles on 2 threads and on 1, expecting a complete fill and
// the same bits; returns the coarse guide's stride (0: not built).
int small_raster_guide_stride(MemRaster& r) {
  Recorded rec;
  const std::vector<double> two = run(r, 0, 2, rec.hooks);
  EXPECT_EQ(rec.stats.tile_side, 0);
  EXPECT_TRUE(r.complete());
  EXPECT_TRUE(bit_identical(run(r, 0, 1), two));
  return rec.stats.guide_stride;
}

// The coarse guide is built only when some void cell lies farther than its
// radius (8·4 cells here) from data: not for a long thin void, whose row runs
// are long but whose cells are all next to data; and the deep void's fill is
// the same on any number of threads (whichever field builds the guide).
TEST(TiledFill, SmallRasterBuildsTheGuideOnlyForDeepVoids) {
  MemRaster r = terrain_raster(400, 300);
  for (int x = 20; x < 380; ++x) r.valid[r.at(x, 40)] = 0;  // one row, 360 cells long
  EXPECT_EQ(small_raster_guide_stride(r), 0);
  punch_disc(r, 200, 180, 50);  // its centre is 50 cells from data
  punch_disc(r, 60, 200, 8);
  EXPECT_EQ(small_raster_guide_stride(r), 4);
}

// Fields that need the guide while another thread builds it are set aside
// and solved once it is ready (single_field.cpp, DomainQueue): many deep and
// neighbouring voids give the same bits on 1, 2 and 4 threads.
TEST(TiledFill, FieldsWaitingForTheGuideGiveTheSameBits) {
  MemRaster r = terrain_raster(600, 500);
  for (int k = 0; k < 6; ++k) {
    punch_disc(r, 80 + 90 * k, 120 + 40 * (k % 3), 38);  // deep: centres 38 cells from data
    punch_disc(r, 80 + 90 * k + 44, 120 + 40 * (k % 3), 3);  // beside it: its cells pinned
    punch_disc(r, 60 + 90 * k, 380, 6 + k);
  }
  Recorded rec;
  const std::vector<double> one = run(r, 0, 1, rec.hooks);
  EXPECT_EQ(rec.stats.tile_side, 0);
  EXPECT_EQ(rec.stats.guide_stride, 4);
  EXPECT_TRUE(r.complete());
  EXPECT_TRUE(bit_identical(run(r, 0, 2), one));
  EXPECT_TRUE(bit_identical(run(r, 0, 4), one));
}

// A small void beside a larger one: the small void's field holds more of its
// neighbour's cells than its own, so those are pinned to the coarse guide
// (built although no cell is deep) instead of being solved a second time.
TEST(TiledFill, NeighbourVoidCellsArePinnedNotSolvedTwice) {
  MemRaster r = terrain_raster(300, 300);
  punch_disc(r, 100, 150, 25);  // no cell farther than 25 from data
  EXPECT_EQ(small_raster_guide_stride(r), 0);
  punch_disc(r, 135, 150, 3);   // its field reaches 29 cells into the first disc
  EXPECT_EQ(small_raster_guide_stride(r), 4);
}

TEST(TiledFill, OneFieldHonoursMaxDistanceExactly) {
  MemRaster r = terrain_raster(200, 120);
  punch_disc(r, 100, 60, 20);
  TilingParams tp;
  tp.max_distance = 5.0;
  fill_raster(r.access(), FillParams{}, tp);
  const std::vector<double> dist = distance_to_valid(r.valid.data(), r.w, r.h);
  for (std::size_t i = 0; i < dist.size(); ++i) {
    if (r.valid[i]) continue;
    EXPECT_EQ(std::isfinite(r.out[i]), dist[i] <= 5.0) << i;
  }
}

// Tiles are still used when asked for (-tile with TILING=ALWAYS), for the
// paper methods, for rasters beyond the size limit, and for voids reaching far
// from data (the guide's tension and deep-void surface; see
// HugeVoidDoesNotExtrapolate...). Rough fills (rs auto) of small rasters are
// fields too: the same bits on any number of threads, other bits per seed.
TEST(TiledFill, TilesWhenAskedForPaperOrFarReachingVoids) {
  MemRaster r = terrain_raster(300, 300);
  punch_disc(r, 150, 150, 20);
  Recorded rec;
  RasterFillStats& stats = rec.stats;
  const RasterFillHooks& hooks = rec.hooks;
  run(r, 65, 2, hooks);
  EXPECT_EQ(stats.tile_side, 65);
  TilingParams tp;
  FillParams paper;
  paper.method = Method::paper_ds;
  fill_raster(r.access(), paper, tp, {}, hooks);
  EXPECT_GT(stats.tile_side, 0);

  FillParams rough;
  rough.rs_auto = true;
  tp.threads = 2;
  fill_raster(r.access(), rough, tp, {}, hooks);
  EXPECT_EQ(stats.tile_side, 0);
  EXPECT_TRUE(r.complete());
  const std::vector<double> two = r.out;
  tp.threads = 1;
  fill_raster(r.access(), rough, tp);
  EXPECT_TRUE(bit_identical(r.out, two));
  rough.seed = 7;
  fill_raster(r.access(), rough, tp);
  EXPECT_FALSE(bit_identical(r.out, two));

  punch_disc(r, 150, 150, 140);  // a void cell 140 cells from data
  run(r, 0, 2, hooks);
  EXPECT_GT(stats.tile_side, 0);
  EXPECT_TRUE(r.complete());
}

// -inner and -maxvoid (raster/void_selection.hpp).
namespace {

// Voids of exactly n cells: an L of cells in one row then down one column,
// placed at (x, y).
void punch_cells(MemRaster& r, int x, int y, int n) {
  for (int k = 0; k < n; ++k) {
    const int along = std::min(k, 7);
    r.valid[r.at(x + along, y + std::max(0, k - 7))] = 0;
  }
}

std::size_t unwritten_voids(const MemRaster& r) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < r.valid.size(); ++i) n += !r.valid[i] && r.write_count[i] == 0;
  return n;
}

TilingParams selecting(bool inner_only, std::size_t max_void_cells, int tile, int threads) {
  TilingParams tp;
  tp.inner_only = inner_only;
  tp.max_void_cells = max_void_cells;
  tp.tile_side = tile;
  tp.always_tile = tile != 0;
  tp.threads = threads;
  return tp;
}

}  // namespace

TEST(VoidSelection, EightNeighboursMakeOneVoidAndTheBorderIsSeen) {
  // Row-major 6×4: a border void (left column), a diagonal pair (one void of
  // 2 cells) and a single inner cell.
  const std::vector<std::uint8_t> valid = {
      0, 1, 1, 1, 1, 1,  //
      0, 1, 0, 1, 1, 1,  //
      1, 1, 1, 0, 1, 0,  //
      1, 1, 1, 1, 1, 1,
  };
  const auto left_of = [&](bool inner, std::size_t cap) {
    detail::VoidSelector s(6, 4, selecting(inner, cap, 0, 1));
    for (int y = 0; y < 4; ++y) s.add_row(y, valid.data() + 6 * y);
    return s.finish();
  };
  EXPECT_EQ(left_of(true, 0).cells(), 3u);  // the left column's 2 cells and (5, 2) on the right border
  EXPECT_EQ(left_of(false, 1).cells(), 4u);  // the two 2-cell voids (the diagonal pair is one)
  EXPECT_EQ(left_of(false, 2).cells(), 0u);
  EXPECT_EQ(left_of(true, 1).cells(), 5u);
}

TEST(VoidSelection, InnerOnlyLeavesTheSeaAndFillsTheLake) {
  MemRaster r = terrain_raster(230, 170);
  for (int y = 0; y < r.h; ++y)  // a sea along the left border, wider than a tile
    for (int x = 0; x < 40 + y / 4; ++x) r.valid[r.at(x, y)] = 0;
  punch_disc(r, 160, 90, 12);  // an inner lake
  for (int tile : {0, 33}) {
    std::vector<double> first;
    for (int threads : {1, 2}) {
      fill_raster(r.access(), FillParams{}, selecting(true, 0, tile, threads));
      EXPECT_EQ(r.known_writes, 0u);
      for (int y = 0; y < r.h; ++y)
        for (int x = 0; x < r.w; ++x) {
          const std::size_t i = r.at(x, y);
          if (r.valid[i]) continue;
          const bool lake = std::hypot(x - 160, y - 90) <= 12;
          ASSERT_EQ(r.write_count[i], lake ? 1 : 0) << "tile " << tile << " at " << x << "," << y;
          ASSERT_EQ(std::isfinite(r.out[i]), lake);
        }
      if (first.empty()) first = r.out;
      EXPECT_TRUE(bit_identical(first, r.out)) << "tile " << tile;
      std::fill(r.write_count.begin(), r.write_count.end(), 0);
    }
  }
}

TEST(VoidSelection, TilesHoldingOnlyLeftVoidsAreNotSolved) {
  MemRaster r = terrain_raster(300, 200);
  for (int y = 0; y < r.h; ++y)  // a sea over the left third, several tiles wide
    for (int x = 0; x < 100; ++x) r.valid[r.at(x, y)] = 0;
  punch_disc(r, 220, 100, 40);  // a lake larger than a small component
  Recorded plain, inner;
  const std::vector<double> all = run(r, 33, 2, plain.hooks);
  fill_raster(r.access(), FillParams{}, selecting(true, 0, 33, 2), {}, inner.hooks);
  EXPECT_GT(inner.stats.windows_solved, 0u);
  EXPECT_LT(inner.stats.windows_solved, plain.stats.windows_solved / 2);
  // The lake's cells: the same windows, the same bits.
  for (int y = 0; y < r.h; ++y)
    for (int x = 100; x < r.w; ++x) {
      if (r.valid[r.at(x, y)]) continue;
      ASSERT_EQ(all[r.at(x, y)], r.out[r.at(x, y)]) << x << "," << y;
    }
}

TEST(VoidSelection, InnerOnlyLakeIsFilledAsWithoutTheOption) {
  // Raster held whole: the sea is not solved, the lake's field is its own.
  MemRaster r = terrain_raster(200, 150);
  for (int y = 0; y < r.h; ++y) r.valid[r.at(0, y)] = r.valid[r.at(1, y)] = 0;
  punch_disc(r, 120, 70, 10);
  const std::vector<double> plain = run(r, 0, 2);
  fill_raster(r.access(), FillParams{}, selecting(true, 0, 0, 2));
  for (int y = 0; y < r.h; ++y)
    for (int x = 0; x < r.w; ++x) {
      if (std::hypot(x - 120, y - 70) > 10) continue;
      ASSERT_EQ(plain[r.at(x, y)], r.out[r.at(x, y)]) << x << "," << y;
    }
}

TEST(VoidSelection, CapAtTheThresholdAcrossATileSeam) {
  // Voids of 39, 40 and 41 cells, each crossing the seam at x = 32 of 33-cell
  // tiles (the L runs from x = 28 to 35 then down).
  for (int tile : {0, 33}) {
    std::vector<double> first;
    for (int threads : {1, 2}) {
      MemRaster r = terrain_raster(120, 150);
      punch_cells(r, 28, 10, 39);
      punch_cells(r, 28, 55, 40);
      punch_cells(r, 28, 100, 41);
      fill_raster(r.access(), FillParams{}, selecting(false, 40, tile, threads));
      EXPECT_EQ(unwritten_voids(r), 41u) << "tile " << tile;
      for (int y = 100; y < r.h; ++y) {
        for (int x = 0; x < r.w; ++x) ASSERT_EQ(r.write_count[r.at(x, y)], 0) << x << "," << y;
      }
      if (first.empty()) first = r.out;
      EXPECT_TRUE(bit_identical(first, r.out));
    }
  }
}
