// The tiled fill in chunks (mcmd/chunked_fill.hpp): the four steps over
// several chunkings and orders give fill_raster's tiled result bit for bit.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <gtest/gtest.h>
#include <random>
#include <stdexcept>
#include <vector>

#include "mcmd/chunked_fill.hpp"
#include "mcmd/fill_raster.hpp"
#include "mem_raster.hpp"

using namespace mcmd;
using mcmd::test::make_raster;
using mcmd::test::MemRaster;

namespace {

std::vector<double> tiled(MemRaster& r, const FillParams& params, TilingParams tiling) {
  tiling.always_tile = true;
  fill_raster(r.access(), params, tiling);
  return r.out;
}

// Chunk edges along an axis: multiples of `side`, the last chunk merged into
// the one before when shorter than the grid's minimum.
std::vector<int> edges(int length, int side, const ChunkGrid& g) {
  std::vector<int> e;
  for (int v = 0; v < length; v += side) e.push_back(v);
  if (e.size() > 1 && length - e.back() < g.min_side) e.pop_back();
  e.push_back(length);
  return e;
}

// The four steps, chunks visited in a shuffled order at each step.
std::vector<double> chunked(MemRaster& r, const FillParams& params, const TilingParams& tiling, int side,
                            unsigned shuffle) {
  const RasterAccess access = r.access();
  const ChunkGrid g = chunk_grid(r.w, r.h, tiling, params.method);
  EXPECT_EQ(side % g.step, 0);
  const std::vector<int> xs = edges(r.w, side, g), ys = edges(r.h, side, g);
  const int nx = static_cast<int>(xs.size()) - 1, ny = static_cast<int>(ys.size()) - 1;
  std::vector<CellRect> chunks;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) chunks.push_back(CellRect{xs[i], ys[j], xs[i + 1] - xs[i], ys[j + 1] - ys[j]});
  std::vector<std::size_t> order(chunks.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::mt19937 rng(shuffle);

  // Reads near the chunk only.
  auto near = [&](const CellRect& own) {
    RasterAccess a = access;
    a.read = [&access, own, m = g.margin](int x0, int y0, int w, int h, double* z, std::uint8_t* v) {
      EXPECT_TRUE(x0 >= own.x0 - m && y0 >= own.y0 - m && x0 + w <= own.x0 + own.w + m &&
                  y0 + h <= own.y0 + own.h + m);
      access.read(x0, y0, w, h, z, v);
    };
    return a;
  };
  std::shuffle(order.begin(), order.end(), rng);
  std::vector<ChunkSummary> summaries;
  for (std::size_t k : order) summaries.push_back(summarize_chunk(near(chunks[k]), tiling, params.method, chunks[k]));
  const ChunkedPlan plan(r.w, r.h, params, tiling, summaries);
  std::vector<ChunkSolution> solutions(chunks.size());
  std::shuffle(order.begin(), order.end(), rng);
  for (std::size_t k : order) solutions[k] = solve_chunk(near(chunks[k]), plan, chunks[k]);
  std::shuffle(order.begin(), order.end(), rng);
  for (std::size_t k : order) {
    const int i = static_cast<int>(k) % nx, j = static_cast<int>(k) / nx;
    // Its own solution, and what each neighbour sends of its own.
    std::vector<ChunkSolution> parts;
    parts.reserve(8);
    std::vector<const ChunkSolution*> around{&solutions[k]};
    for (int dj = -1; dj <= 1; ++dj)
      for (int di = -1; di <= 1; ++di)
        if ((di || dj) && i + di >= 0 && i + di < nx && j + dj >= 0 && j + dj < ny) {
          parts.push_back(solution_part(solutions[static_cast<std::size_t>(j + dj) * nx + (i + di)], chunks[k]));
          around.push_back(&parts.back());
        }
    blend_chunk(access, plan, around, chunks[k]);
  }
  return r.out;
}

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

// make_raster(w, h, drop) filled in chunks of `side` and by fill_raster's tiled path.
bool chunked_equals_tiled(int w, int h, double drop, const FillParams& params, const TilingParams& tiling, int side,
                          unsigned shuffle) {
  MemRaster r = make_raster(w, h, drop);
  const std::vector<double> want = tiled(r, params, tiling);
  MemRaster c = make_raster(w, h, drop);
  return same_bits(chunked(c, params, tiling, side, shuffle), want);
}

}  // namespace

TEST(ChunkedFill, EqualsTheTiledFillForAnyChunkingAndOrder) {
  MemRaster r = make_raster(301, 233, 0.03);  // a disc spanning chunks and scattered small voids
  TilingParams tiling;
  tiling.tile_side = 33;
  const std::vector<double> want = tiled(r, FillParams{}, tiling);
  ASSERT_TRUE(r.complete());
  for (const auto& [side, shuffle] : {std::pair{64, 1u}, std::pair{96, 2u}, std::pair{160, 3u}, std::pair{320, 4u}}) {
    MemRaster c = make_raster(301, 233, 0.03);
    EXPECT_TRUE(same_bits(chunked(c, FillParams{}, tiling, side, shuffle), want)) << "chunks of " << side;
    EXPECT_EQ(c.known_writes, 0u);
  }
}

TEST(ChunkedFill, EqualsTheTiledFillWithAGuideStrideOfSeveralCells) {
  // 1100 cells wide: the guide's stride is 2, its blocks straddle chunk
  // edges, and a chunk's summary reads its 160 rows in strips of whole blocks.
  TilingParams tiling;
  tiling.tile_side = 33;
  EXPECT_TRUE(chunked_equals_tiled(1100, 330, 0.02, FillParams{}, tiling, 160, 9u));
}

TEST(ChunkedFill, EqualsTheTiledFillWithRoughnessAndMaxDistance) {
  FillParams rough;
  rough.rs = 0.05;
  rough.seed = 7;
  TilingParams tiling;
  tiling.tile_side = 33;
  tiling.max_distance = 12;
  EXPECT_TRUE(chunked_equals_tiled(257, 190, 0.02, rough, tiling, 64, 5u));
}

TEST(ChunkedFill, EqualsTheTiledFillOfAPaperMethod) {
  FillParams paper;
  paper.method = Method::paper_ds;
  TilingParams tiling;
  tiling.tile_side = 65;
  EXPECT_TRUE(chunked_equals_tiled(200, 170, 0.01, paper, tiling, 128, 6u));
}

TEST(ChunkedFill, LeavesTheVoidsTheTiledFillLeaves) {
  // Voids on the border (left by -inner), a disc across chunks and scattered
  // cells; the cap leaves the disc, whatever chunk it crosses.
  auto raster = [] {
    MemRaster r = make_raster(260, 200, 0.02);
    mcmd::test::punch_disc(r, 0, 100, 30);
    return r;
  };
  for (const bool inner : {true, false}) {
    TilingParams tiling;
    tiling.tile_side = 33;
    tiling.inner_only = inner;
    tiling.max_void_cells = inner ? 0 : 500;
    MemRaster r = raster();
    const std::vector<double> want = tiled(r, FillParams{}, tiling);
    MemRaster c = raster();
    EXPECT_TRUE(same_bits(chunked(c, FillParams{}, tiling, 64, 8u), want)) << (inner ? "-inner" : "-maxvoid");
    EXPECT_EQ(std::count_if(c.out.begin(), c.out.end(), [](double v) { return std::isnan(v); }),
              std::count_if(want.begin(), want.end(), [](double v) { return std::isnan(v); }));
    EXPECT_GT(std::count_if(want.begin(), want.end(), [](double v) { return std::isnan(v); }), 0);
  }
}

TEST(ChunkedFill, RefusesWhatItCannotDo) {
  TilingParams tiling;
  tiling.tile_side = 33;
  MemRaster none(70, 70);
  std::fill(none.valid.begin(), none.valid.end(), 0);
  const RasterAccess a = none.access();
  const std::vector<ChunkSummary> s{summarize_chunk(a, tiling, Method::mcmd, CellRect{0, 0, 70, 70})};
  EXPECT_THROW(ChunkedPlan(70, 70, FillParams{}, tiling, s), std::invalid_argument);
}
