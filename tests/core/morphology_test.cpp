// Morphology: the flow routines, channels through voids (-morph auto) and
// ridge/river lines, on small synthetic terrains whose drainage is known.
#include <algorithm>
#include <array>
#include <cmath>
#include <gtest/gtest.h>
#include <random>
#include <vector>

#include "mcmd/fill_raster.hpp"
#include "morphology/channel_fill.hpp"
#include "morphology/channels.hpp"
#include "morphology/flow.hpp"
#include "morphology/lines.hpp"
#include "morphology/radix_heap.hpp"
#include "raster/void_field.hpp"

namespace {

using namespace mcmd;

// A raster in memory for fill_raster: z and valid, filled in place.
struct MemoryRaster {
  int w, h;
  std::vector<double> z;
  std::vector<std::uint8_t> valid;
  std::vector<Line> lines;
  RasterAccess access() {
    RasterAccess a;
    a.width = w;
    a.height = h;
    const std::vector<double> source = z;
    const std::vector<std::uint8_t> source_valid = valid;
    a.read = [this, source, source_valid](int x0, int y0, int rw, int rh, double* out, std::uint8_t* v) {
      for (int y = 0; y < rh; ++y)
        for (int x = 0; x < rw; ++x) {
          const std::size_t i = static_cast<std::size_t>(y0 + y) * w + x0 + x;
          out[y * rw + x] = source[i];
          v[y * rw + x] = source_valid[i];
        }
    };
    a.write = [this](int x0, int y0, int rw, int rh, const double* in, const std::uint8_t* m) {
      for (int y = 0; y < rh; ++y)
        for (int x = 0; x < rw; ++x)
          if (m[y * rw + x]) z[static_cast<std::size_t>(y0 + y) * w + x0 + x] = in[y * rw + x];
    };
    a.lines = lines;
    return a;
  }
  double at(int x, int y) const { return z[static_cast<std::size_t>(y) * w + x]; }
  bool is_void(int x, int y) const { return !valid[static_cast<std::size_t>(y) * w + x]; }
};

// A meandering gorge falling gently to the south (+y), axis x = c(y), its
// walls rising steeply to a plateau: a void wider than the gorge sees high
// ground all round its rim but for the floor where the gorge enters and
// leaves, and a smooth fill across it dams the gorge.
double valley_axis(double y) { return 60.0 + 8.0 * std::sin(y / 15.0); }
double valley(int x, int y) { return 1000.0 - 0.5 * y + 80.0 * std::tanh(std::abs(x - valley_axis(y)) / 5.0); }

MemoryRaster with_disc_void(int w, int h, double (*f)(int, int), double cx, double cy, double r) {
  MemoryRaster m{w, h, std::vector<double>(static_cast<std::size_t>(w) * h), std::vector<std::uint8_t>(static_cast<std::size_t>(w) * h, 1), {}};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      m.z[i] = f(x, y);
      if (std::hypot(x - cx, y - cy) <= r) m.valid[i] = 0, m.z[i] = -9999.0;
    }
  return m;
}

// Cells plain Priority-Flood would raise (closed depressions), with the
// raster border as the outlet. (The sampled gorge has a few pits of its own.)
std::vector<std::uint8_t> ponded(const MemoryRaster& m) {
  const std::vector<morph::FlowCell> land(m.z.size(), morph::FlowCell::land);
  const std::vector<double> level = morph::flood_levels(m.z.data(), m.w, m.h, land.data());
  std::vector<std::uint8_t> out(m.z.size());
  // ε levels sit a few ulps above a cell on its way out: a pond is a rise of
  // more than a millimetre.
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = level[i] > m.z[i] + 1e-3;
  return out;
}

// Cells of a filled terrain (the gorge, valley(), unless told) ponded that
// the void-free terrain does not pond: the dam a fill builds across the valley.
int new_pond_cells(const MemoryRaster& m, double (*terrain)(int, int) = valley) {
  const std::vector<std::uint8_t> pond = ponded(m), truth = ponded(with_disc_void(m.w, m.h, terrain, -100, -100, 1));
  int n = 0;
  for (std::size_t i = 0; i < pond.size(); ++i) n += pond[i] && !truth[i];
  return n;
}

// The floor of row y across columns [x0, x1): its lowest cell.
double row_floor(const MemoryRaster& m, int y, int x0, int x1) {
  double floor = 1e300;
  for (int x = x0; x < x1; ++x) floor = std::min(floor, m.at(x, y));
  return floor;
}

// The steepest-descent path on the raw values from (x, y) until the border
// or a cell with no lower neighbour (an independent D8, no flooding).
std::vector<std::pair<int, int>> d8_path(const MemoryRaster& m, int x, int y) {
  std::vector<std::pair<int, int>> path{{x, y}};
  for (int steps = 0; steps < m.w * m.h; ++steps) {
    int bx = -1, by = -1;
    double best = 0.0;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int nx = x + dx, ny = y + dy;
        if ((!dx && !dy) || nx < 0 || ny < 0 || nx >= m.w || ny >= m.h) continue;
        const double slope = (m.at(x, y) - m.at(nx, ny)) / std::hypot(dx, dy);
        if (slope > best) best = slope, bx = nx, by = ny;
      }
    if (bx < 0) break;
    x = bx, y = by;
    path.emplace_back(x, y);
  }
  return path;
}

TEST(RadixHeap, PopsInOrderAndEqualLevelsInTheOrderPushed) {
  morph::RadixHeap heap;
  heap.push(5.0, 1);
  heap.push(-3.0, 2);
  heap.push(5.0, 3);
  heap.push(1e10, 4);
  EXPECT_EQ(heap.pop().second, 2);
  heap.push(0.5, 5);
  EXPECT_EQ(heap.pop().second, 5);
  EXPECT_EQ(heap.pop().second, 1);
  EXPECT_EQ(heap.pop().second, 3);
  const auto last = heap.pop();
  EXPECT_EQ(last.first, 1e10);
  EXPECT_TRUE(heap.empty());
}

// A flood's use: pushes at or above the last pop, many levels apart and
// many equal, interleaved with pops; against a stable sort of what went in.
TEST(RadixHeap, AgreesWithAStableOrderOverManyBuckets) {
  morph::RadixHeap heap;
  std::mt19937_64 rng(7);
  std::vector<std::pair<double, std::int32_t>> pending;  // pushed, not yet popped
  double last = -1e6;
  std::int32_t next_cell = 0;
  for (int round = 0; round < 20000; ++round) {
    for (int k = static_cast<int>(rng() % 3); k > 0; --k) {
      const int exponent = static_cast<int>(rng() % 40) - 20;
      const double step = rng() % 3 == 0 ? 0.0 : std::ldexp(static_cast<double>(rng() % 1000), exponent);
      heap.push(last + step, next_cell);
      pending.emplace_back(last + step, next_cell++);
    }
    if (pending.empty()) continue;
    std::stable_sort(pending.begin(), pending.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    const auto got = heap.pop();
    ASSERT_EQ(got, pending.front()) << "round " << round;
    pending.erase(pending.begin());
    last = got.first;
  }
}

double v_valley(int x, int y) { return 1000.0 - 2.0 * y + 3.0 * std::abs(x - valley_axis(y)); }

TEST(Flow, AccumulationGathersAlongTheValleyFloor) {
  MemoryRaster m = with_disc_void(121, 161, v_valley, -100, -100, 1);  // no void
  const std::vector<morph::FlowCell> land(m.z.size(), morph::FlowCell::land);
  const morph::Flow f = morph::route(m.z.data(), m.w, m.h, land.data());
  const std::vector<double> a = morph::accumulation(f, land.data());
  // Near the outlet at the southern border, the floor carries most of the raster.
  const int y = m.h - 3, x = static_cast<int>(std::lround(valley_axis(y)));
  double best = 0;
  for (int dx = -1; dx <= 1; ++dx) best = std::max(best, a[static_cast<std::size_t>(y) * m.w + x + dx]);
  EXPECT_GT(best, 0.5 * m.w * m.h);
}

// On a bumpy field with pits, flats, a void (sink) and an off cell, each
// cell's accumulation is the number of land cells whose drainage passes
// through it, counted by walking every cell's path to its end.
TEST(Flow, AccumulationCountsEveryCellUpstream) {
  const int w = 47, h = 31;
  std::vector<double> z(static_cast<std::size_t>(w) * h);
  std::vector<morph::FlowCell> kind(z.size(), morph::FlowCell::land);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      z[i] = std::round(20.0 * std::sin(0.4 * x) * std::cos(0.3 * y) + 0.5 * x);  // whole metres: flats
      if (std::hypot(x - 30, y - 12) < 4) kind[i] = morph::FlowCell::sink;
    }
  kind[5 * w + 7] = morph::FlowCell::off;
  const morph::Flow f = morph::route(z.data(), w, h, kind.data());
  const std::vector<double> a = morph::accumulation(f, kind.data());
  std::vector<double> walked(z.size(), 0.0);
  for (std::size_t s = 0; s < z.size(); ++s) {
    if (kind[s] != morph::FlowCell::land) continue;
    for (std::int32_t i = static_cast<std::int32_t>(s); i >= 0 && kind[i] != morph::FlowCell::off;) {
      walked[i] += 1.0;
      i = kind[i] == morph::FlowCell::land ? f.receiver[i] : -1;
    }
  }
  EXPECT_EQ(a, walked);
  EXPECT_GT(*std::max_element(a.begin(), a.end()), 100.0);
}

// Each land cell's receiver, against its definition walked neighbour by
// neighbour on the flooded levels: the first sink beside it (east, then
// clockwise), else its steepest lower land neighbour (diagonals √2 away,
// the first of equal slopes), else -1. A field with pits, flats, sinks on
// and off the border and off cells, so that every case meets the
// interior cells' branch-free path and the border cells' own.
TEST(Flow, ReceiversFollowTheirDefinition) {
  const int w = 53, h = 37;
  std::vector<double> z(static_cast<std::size_t>(w) * h);
  std::vector<morph::FlowCell> kind(z.size(), morph::FlowCell::land);
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> bump(0, 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      z[i] = std::round(15.0 * std::sin(0.35 * x) * std::cos(0.27 * y) + 0.3 * y) + bump(rng);  // flats and pits
      if (std::hypot(x - 20, y - 15) < 5 || std::hypot(x - 52, y - 3) < 3) kind[i] = morph::FlowCell::sink;
      if ((x * 7 + y * 3) % 41 == 0) kind[i] = morph::FlowCell::off;
    }
  const morph::Flow f = morph::route(z.data(), w, h, kind.data());
  const std::vector<double> level = morph::flood_levels(z.data(), w, h, kind.data());
  constexpr int dx[8] = {1, 1, 0, -1, -1, -1, 0, 1}, dy[8] = {0, 1, 1, 1, 0, -1, -1, -1};
  int to_sink = 0, to_land = 0, out = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      if (kind[i] != morph::FlowCell::land) {
        EXPECT_EQ(f.receiver[i], -1);
        continue;
      }
      std::int32_t sink = -1, best = -1;
      double steepest = 0.0;
      for (int k = 0; k < 8; ++k) {
        const int nx = x + dx[k], ny = y + dy[k];
        if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
        const std::int32_t j = ny * w + nx;
        if (kind[j] == morph::FlowCell::sink && sink < 0) sink = j;
        if (kind[j] != morph::FlowCell::land) continue;
        const double slope = (level[i] - level[j]) * (k % 2 ? M_SQRT1_2 : 1.0);
        if (slope > steepest) steepest = slope, best = j;
      }
      const std::int32_t expected = sink >= 0 ? sink : best;
      EXPECT_EQ(f.receiver[i], expected) << "cell " << x << ", " << y;
      (expected < 0 ? out : sink >= 0 ? to_sink : to_land) += 1;
    }
  EXPECT_GT(to_sink, 20);
  EXPECT_GT(to_land, 1000);
  EXPECT_GT(out, 0);
}

TEST(Flow, DrainRaisesOnlyTheRaisableCellsOfAPit) {
  std::vector<double> z(25, 10.0);
  z[12] = 0.0;  // a pit in the middle of a 5×5 plateau
  z[7] = 1.0;   // and beside it a lower cell that may not be raised
  std::vector<std::uint8_t> raisable(25, 0);
  raisable[12] = 1;
  morph::drain(z.data(), 5, 5, raisable.data());
  EXPECT_GE(z[12], 1.0);  // raised to the level of the water held by cell 7
  EXPECT_EQ(z[7], 1.0);
  EXPECT_EQ(z[0], 10.0);
}

// A routed fill that digs a basin into the void (a channel pinned far below
// the plain fill, ending where water cannot leave) holds far more water
// than the plain fill, and is refused; one whose channel drains is kept.
TEST(MorphAuto, AFillThatDigsABasinIsRefusedOneThatDrainsIsKept) {
  const int w = 41, h = 41;
  const std::size_t n = static_cast<std::size_t>(w) * h;
  std::vector<std::uint8_t> own(n, 0);
  std::vector<double> plain(n), basin(n), drains(n);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      own[i] = std::hypot(x - 20, y - 20) < 15;
      plain[i] = 1000.0 - 2.0 * y;  // a plane falling south
      basin[i] = plain[i] - 300.0 * std::exp(-std::pow(std::hypot(x - 20, y - 20) / 8.0, 2));  // a pit
      drains[i] = plain[i] - 30.0 * std::exp(-std::pow((x - 20) / 2.0, 2));  // a valley south, through
    }
  const std::vector<double> smooth = plain;
  const double plain_held = morph::drain_held(plain.data(), w, h, own.data());
  const double basin_held = morph::drain_held(basin.data(), w, h, own.data());
  const double drains_held = morph::drain_held(drains.data(), w, h, own.data());
  EXPECT_EQ(plain_held, 0.0);
  EXPECT_GT(basin_held, 1e4);  // raised to the spill: what the drain would fill flat
  EXPECT_LT(drains_held, 1.0);
  EXPECT_FALSE(morph::keeps_channels(basin_held, plain_held, smooth.data(), n, own.data()));
  EXPECT_TRUE(morph::keeps_channels(drains_held, plain_held, smooth.data(), n, own.data()));
}

TEST(MorphAuto, ValleyThroughAVoidStaysContinuousAndDescending) {
  MemoryRaster m = with_disc_void(121, 161, valley, valley_axis(80), 80, 18);
  FillParams p;
  p.morph.channels = true;
  fill_raster(m.access(), p, TilingParams{});
  EXPECT_EQ(new_pond_cells(m), 0);  // no pond in the void nor upstream of it
  // The floor (the lowest cell of each row crossing the void) falls downstream.
  double previous = 1e300;
  for (int y = 62; y <= 98; ++y) {
    const double floor = row_floor(m, y, 0, m.w);
    EXPECT_LE(floor, previous) << "row " << y;
    previous = floor;
  }
}

TEST(MorphAuto, TheDefaultFillDamsTheSameValley) {  // what the test above guards against
  MemoryRaster m = with_disc_void(121, 161, valley, valley_axis(80), 80, 18);
  fill_raster(m.access(), FillParams{}, TilingParams{});
  EXPECT_GT(new_pond_cells(m), 100);
}

// The gorge with a disc void across its floor and `small` 3×3 voids on a
// grid over the plateau and walls, and the cells the voids' fields hold
// together.
struct GorgeWithVoids {
  MemoryRaster raster;
  std::size_t field_cells = 0;
};
GorgeWithVoids gorge_with_voids(int small) {
  const double cx = valley_axis(80), cy = 80, r = 12;
  GorgeWithVoids g{with_disc_void(121, 161, valley, cx, cy, r), 0};
  MemoryRaster& m = g.raster;
  const detail::Box disc{static_cast<int>(std::ceil(cx - r)), static_cast<int>(cy - r),
                         static_cast<int>(std::floor(cx + r)), static_cast<int>(cy + r)};
  const detail::Box field = detail::void_field_rect(disc, m.w, m.h);
  g.field_cells += static_cast<std::size_t>(field.width()) * field.height();
  for (int k = 0; k < small; ++k) {  // rows clear of the disc's
    const int x0 = 6 + (k % 8) * 14, y0 = std::array<int, 5>{6, 30, 110, 130, 150}[k / 8];
    for (int y = y0; y < y0 + 3; ++y)
      for (int x = x0; x < x0 + 3; ++x) m.valid[static_cast<std::size_t>(y) * m.w + x] = 0;
    const detail::Box f = detail::void_field_rect(detail::Box{x0, y0, x0 + 2, y0 + 2}, m.w, m.h);
    g.field_cells += static_cast<std::size_t>(f.width()) * f.height();
  }
  return g;
}

// The drainage into the voids is computed in each field, or once for the
// whole raster when the fields overlap much (many small voids): either way
// the gorge drains through its void, and the fields solved on any number of
// threads give the same bits.
TEST(MorphAuto, EachFieldsOrTheRastersDrainageKeepsTheGorgeAndTheBits) {
  for (const int small : {4, 40}) {
    const GorgeWithVoids g = gorge_with_voids(small);
    const std::size_t cells = static_cast<std::size_t>(g.raster.w) * g.raster.h;
    // 4 voids: each field drained; 40: their fields overlap, the raster's.
    EXPECT_EQ(g.field_cells > 2 * cells, small == 40) << g.field_cells << " field cells";
    std::vector<double> first;
    for (const int threads : {1, 2, 4}) {
      MemoryRaster m = g.raster;
      FillParams p;
      p.morph.channels = true;
      TilingParams t;
      t.threads = threads;
      fill_raster(m.access(), p, t);
      if (first.empty()) {
        first = m.z;
        EXPECT_EQ(new_pond_cells(m), 0) << small << " small voids";
      } else {
        EXPECT_TRUE(m.z == first) << small << " small voids, " << threads << " threads";
      }
    }
  }
}

// Filled through tiles (a large raster, or TILING=ALWAYS), a void small
// enough to be solved alone is solved in its void field, channels included:
// the gorge drains through it, the same bits for any thread count or job
// order, and no warning that channels were skipped.
TEST(MorphAuto, ATiledRasterRoutesTheGorgeThroughAVoidSolvedAlone) {
  const MemoryRaster source = with_disc_void(121, 161, valley, valley_axis(80), 80, 18);
  std::vector<double> first;
  for (const int threads : {1, 2}) {
    for (const bool reversed : {false, true}) {
      MemoryRaster m = source;
      FillParams p;
      p.morph.channels = true;
      TilingParams t;
      t.always_tile = true;
      t.tile_side = 129;
      t.threads = threads;
      RasterFillStats stats;
      RasterFillHooks hooks;
      hooks.stats = &stats;
      if (reversed) hooks.reorder = [](std::vector<std::size_t>& o) { std::reverse(o.begin(), o.end()); };
      fill_raster(m.access(), p, t, {}, hooks);
      EXPECT_GT(stats.tile_side, 0);
      EXPECT_EQ(stats.small_components, 1u);
      EXPECT_EQ(stats.windows_solved, 0u);
      EXPECT_FALSE(stats.channels_skipped);
      if (!first.empty()) {
        EXPECT_TRUE(m.z == first) << threads << " threads" << (reversed ? ", reversed" : "");
        continue;
      }
      first = m.z;
      EXPECT_EQ(new_pond_cells(m), 0);  // the default dams it: TheDefaultFillDamsTheSameValley
    }
  }
}

// A hanging valley: a floor falling gently south, then a 120 m step down
// over 10 rows; a void covers the gentle floor and the top of the step.
double hanging_floor(int y) { return 1000.0 - 0.2 * y - 12.0 * std::clamp(y - 100, 0, 10); }
double hanging_valley(int x, int y) { return hanging_floor(y) + 80.0 * std::tanh(std::abs(x - 60) / 5.0); }

// The channel keeps the floor's gentle fall into the void instead of
// cutting a straight line down to the step's foot.
TEST(MorphAuto, AChannelKeepsAHangingValleysFloorAboveTheStep) {
  MemoryRaster m = with_disc_void(121, 161, hanging_valley, 60, 84, 22);
  FillParams p;
  p.morph.channels = true;
  fill_raster(m.access(), p, TilingParams{});
  EXPECT_EQ(new_pond_cells(m, hanging_valley), 0);
  // The floor (the lowest cell across the valley) below the true floor,
  // on three rows: 12.7 m on average; a straight fall from the inflow to
  // the outlet in place of the start_slope curve left 15.4 m.
  double below = 0.0;
  for (int y = 70; y <= 90; y += 10) below += (hanging_floor(y) - row_floor(m, y, 40, 81)) / 3.0;
  EXPECT_LT(below, 14.0);
}

// A long narrow void across a plane that falls south and, gently, east:
// its rim's lowest cell is at the far east end, while water entering from
// the north crosses the void straight south. The channel must cross too.
// A w×h field for route_channels: the smooth fill z (known cells and void
// alike), the void's cells (own, unknown), and the known terrain's inflow.
struct RoutingField {
  int w, h;
  std::vector<double> z;
  std::vector<CellState> state;
  std::vector<std::uint8_t> own;
  std::vector<double> inflow;
  // z from surface(x, y); the cells where in_void(x, y) are the void.
  template <class Surface, class InVoid>
  RoutingField(int w_, int h_, Surface surface, InVoid in_void)
      : w(w_), h(h_), z(static_cast<std::size_t>(w_) * h_), state(z.size(), CellState::known), own(z.size(), 0),
        inflow(z.size(), 0.0) {
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        z[index(x, y)] = surface(x, y);
        if (in_void(x, y)) own[index(x, y)] = 1, state[index(x, y)] = CellState::unknown;
      }
  }
  std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * w + x; }
  std::vector<morph::RiverCell> route() const {
    return morph::route_channels(morph::ChannelField{w, h, z.data(), state.data(), own.data(), inflow.data()}, 100.0);
  }
};

TEST(MorphAuto, AChannelLeavesWhereTheFillDrainsNotAtTheLowestRimCell) {
  RoutingField f(
      120, 40, [](int x, int y) { return 500.0 - 2.0 * y - 0.2 * x; },  // the smooth fill, in the void: the plane
      [](int x, int y) { return y >= 18 && y <= 22 && x >= 5 && x <= 114; });
  const int in_x = 20, in_y = 17;
  f.inflow[f.index(in_x, in_y)] = 5000.0;
  const std::vector<morph::RiverCell> river = f.route();
  ASSERT_FALSE(river.empty());
  for (const morph::RiverCell& r : river) {
    EXPECT_LE(std::abs(r.cell % f.w - in_x), 1) << "river cell at x " << r.cell % f.w;  // not along the void eastwards
    EXPECT_LT(r.z, f.z[f.index(in_x, in_y)]);
  }
}

// Water entering a void where the user's river line starts joins the line:
// the routed channel neither runs beside the line to an outlet of its own
// nor rewrites the line's heights.
TEST(MorphAuto, AChannelJoinsARiverLineTheUserGave) {
  RoutingField f(
      60, 60, [](int, int y) { return 500.0 - 2.0 * y; },  // the smooth fill, in the void: the plane
      [](int x, int y) { return x >= 10 && x < 50 && y >= 10 && y < 50; });
  for (int y = 10; y < 50; ++y)  // the given line
    f.state[f.index(30, y)] = CellState::river, f.z[f.index(30, y)] = 480.0 - 2.5 * (y - 10);
  f.inflow[f.index(30, 9)] = 5000.0;
  f.inflow[f.index(20, 9)] = 4000.0;  // a second stream, beside the line
  const std::vector<morph::RiverCell> river = f.route();
  for (const morph::RiverCell& r : river) {
    EXPECT_NE(f.state[r.cell], CellState::river) << "a line cell rerouted at y " << r.cell / f.w;
    EXPECT_NE(r.cell % f.w, 30);
  }
  // The stream at x 20 is routed down the void (the line does not swallow it).
  EXPECT_TRUE(std::any_of(river.begin(), river.end(), [&](const morph::RiverCell& r) { return r.cell / f.w == 40; }));
}

// A plane falling south, and a river drawn across it that the terrain's own
// slope would not follow.
double plane(int x, int y) { return 500.0 - 1.0 * y - 0.3 * x; }

TEST(Lines, ARiverLineIsFollowedThroughTheVoid) {
  MemoryRaster m = with_disc_void(101, 101, plane, 50, 50, 20);
  Line river;
  river.kind = CellState::river;
  for (int y = 0; y <= 100; y += 4) river.points.push_back({50.5 + 12.0 * std::sin(y / 12.0), y + 0.5});
  m.lines = {river};
  FillParams p;
  p.z_step = 1.0;
  fill_raster(m.access(), p, TilingParams{});
  const std::vector<std::pair<int, int>> line = morph::trace(river, m.w, m.h);
  // From the line's first cell inside the void, water runs along the line
  // (within a cell) until it leaves the void.
  auto start = std::find_if(line.begin(), line.end(), [&](auto c) { return std::hypot(c.first - 50, c.second - 50) <= 20; });
  ASSERT_NE(start, line.end());
  int inside = 0, near = 0;
  for (const auto& [x, y] : d8_path(m, start->first, start->second)) {
    if (std::hypot(x - 50, y - 50) > 20) break;
    ++inside;
    near += std::any_of(line.begin(), line.end(),
                        [&](auto c) { return std::abs(c.first - x) <= 1 && std::abs(c.second - y) <= 1; });
  }
  EXPECT_GT(inside, 20);
  EXPECT_EQ(near, inside);
  // Without the line, water takes the plane's own slope, away from it.
  MemoryRaster plain = with_disc_void(101, 101, plane, 50, 50, 20);
  fill_raster(plain.access(), p, TilingParams{});
  int plain_near = 0;
  for (const auto& [x, y] : d8_path(plain, start->first, start->second)) {
    if (std::hypot(x - 50, y - 50) > 20) break;
    plain_near += std::any_of(line.begin(), line.end(),
                              [&](auto c) { return std::abs(c.first - x) <= 1 && std::abs(c.second - y) <= 1; });
  }
  EXPECT_LT(plain_near, near / 2);
}

// A river line down the hanging valley's floor: its cells in the void keep
// the floor's gentle fall before the step, where the straight fall between
// the line's known ends cuts far below it.
TEST(Lines, ARiverLineKeepsAHangingValleysFloorAboveTheStep) {
  MemoryRaster m = with_disc_void(121, 161, hanging_valley, 60, 84, 22);
  Line river;
  river.kind = CellState::river;
  river.points = {{60.5, 0.5}, {60.5, 160.5}};
  m.lines = {river};
  fill_raster(m.access(), FillParams{}, TilingParams{});
  // The straight fall from the known cell above the void (y 61) to the one
  // below it (y 107), against the filled line, over the void's rows above
  // the step (y 62..100).
  double straight = 0.0, filled = 0.0, previous = 1e300;
  for (int y = 62; y <= 106; ++y) {
    const double fall = hanging_floor(61) + (y - 61) / 46.0 * (hanging_floor(107) - hanging_floor(61));
    if (y <= 100) straight += (hanging_floor(y) - fall) / 39.0, filled += (hanging_floor(y) - m.at(60, y)) / 39.0;
    EXPECT_LE(m.at(60, y), previous) << "the line rises at y " << y;
    previous = m.at(60, y);
  }
  EXPECT_GT(straight, 30.0);
  EXPECT_LT(filled, 0.5 * straight) << "straight fall " << straight << " m below the floor";
}

double ridge(int x, int y) { return 800.0 + 0.5 * y - 4.0 * std::abs(x - 50.0); }

// The crest line bends inside the void (x = 50 outside it, up to 58 in the
// middle): the user knows where the hidden crest runs.
double crest_x(double y) { return 50.0 + 8.0 * std::max(0.0, 1.0 - std::abs(y - 50.0) / 20.0); }

// Rows of the void where the line's cells (xa .. xb on the row) hold the
// maximum of the row's cross-profile: above their neighbours and above the
// cells 4 away.
int crest_maxima(const MemoryRaster& m, const std::vector<std::pair<int, int>>& line, int& profiles) {
  int maxima = 0;
  profiles = 0;
  for (int y = 34; y <= 66; ++y) {
    int xa = m.w, xb = -1;
    for (const auto& [x, ly] : line)
      if (ly == y && m.is_void(x, y)) xa = std::min(xa, x), xb = std::max(xb, x);
    if (xb < 0) continue;
    ++profiles;
    double crest = -1e300;
    for (int x = xa; x <= xb; ++x) crest = std::max(crest, m.at(x, y));
    maxima += crest >= m.at(xa - 1, y) && crest >= m.at(xb + 1, y) && crest > m.at(xa - 4, y) && crest > m.at(xb + 4, y);
  }
  return maxima;
}

TEST(Lines, ARidgeLineIsTheCrestAcrossTheVoid) {
  MemoryRaster m = with_disc_void(101, 101, ridge, 50, 50, 20);
  Line crest;
  crest.kind = CellState::ridge;
  for (int y = 0; y <= 100; y += 2) crest.points.push_back({crest_x(y) + 0.5, y + 0.5});
  MemoryRaster plain = m;
  fill_raster(plain.access(), FillParams{}, TilingParams{});
  m.lines = {crest};
  fill_raster(m.access(), FillParams{}, TilingParams{});
  int profiles = 0;
  const std::vector<std::pair<int, int>> cells = morph::trace(crest, m.w, m.h);
  const int maxima = crest_maxima(m, cells, profiles), plain_maxima = crest_maxima(plain, cells, profiles);
  EXPECT_GT(profiles, 25);
  EXPECT_GE(maxima, 0.9 * profiles);
  EXPECT_LT(plain_maxima, 0.5 * profiles);  // without the line the fill's crest is elsewhere
}

TEST(Lines, TracedCellsAreEightConnectedAndInsideTheRaster) {
  Line l;
  l.points = {{-5.0, 3.2}, {20.7, 9.9}, {20.2, 30.4}};
  const auto cells = morph::trace(l, 16, 25);
  ASSERT_FALSE(cells.empty());
  for (std::size_t k = 0; k < cells.size(); ++k) {
    EXPECT_GE(cells[k].first, 0);
    EXPECT_LT(cells[k].first, 16);
    EXPECT_LT(cells[k].second, 25);
    if (k > 0 && cells[k].first < 15 && cells[k - 1].first < 15) {  // a jump only where it leaves the raster
      EXPECT_LE(std::max(std::abs(cells[k].first - cells[k - 1].first), std::abs(cells[k].second - cells[k - 1].second)), 1);
    }
  }
}

}  // namespace
