// Erosion (mcmd/erosion.hpp): the same bits for any thread count, constraint
// cells exact, rivers still draining along their course to the border,
// ridges still crests, a drainage network grown, bad parameters refused
// with one line.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "mcmd/erosion.hpp"
#include "mcmd/skeleton.hpp"
#include "terrain_checks.hpp"

namespace mcmd::test {
namespace {

// A synthesised terrain to erode: the skeleton's ridges and rivers with the
// default method's relief around them, or that relief alone.
Canvas synthesised(int n, bool skeleton, std::uint64_t seed) {
  SkeletonParams sp;
  sp.seed = seed;
  sp.z_high = 1500;
  Canvas c = skeleton ? make_skeleton(n, n, sp).canvas : Canvas(n, n);
  TerrainParams tp;
  tp.fill.rs = skeleton ? 0.1 : 300.0;
  tp.fill.noise_unit = skeleton ? 0.0 : 1.0;
  tp.fill.H = 0.7;
  tp.fill.seed = seed;
  synthesize(c, tp);
  return c;
}

ErosionParams auto_erosion(double cell = 90.0, int threads = 1) {
  ErosionParams e;
  e.steps = kErodeAuto;
  e.cell_size = cell;
  e.threads = threads;
  return e;
}

// Cells draining through each cell by D8 on z filled by a Priority-Flood
// (plain sort: small rasters), the border draining out.
std::vector<double> d8_area(const Canvas& c) {
  std::vector<std::size_t> order(c.cells());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return c.z[a] > c.z[b]; });
  std::vector<double> area(c.cells(), 1.0);
  for (const std::size_t i : order) {
    const int x = static_cast<int>(i % c.w), y = static_cast<int>(i / c.w);
    double best = 0.0;
    std::size_t to = i;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        if ((!dx && !dy) || !c.contains(x + dx, y + dy)) continue;
        const double s = (c.z[i] - c.z[c.index(x + dx, y + dy)]) / std::hypot(dx, dy);
        if (s > best) best = s, to = c.index(x + dx, y + dy);
      }
    if (to != i) area[to] += area[i];
  }
  return area;
}

TEST(Erosion, SameBitsForAnyThreadCount) {
  const Canvas start = synthesised(257, true, 3);
  Canvas one = start, two = start;
  erode(one, auto_erosion(90.0, 1));
  erode(two, auto_erosion(90.0, 2));
  EXPECT_EQ(one.z, two.z);
  EXPECT_NE(one.z, start.z);
}

TEST(Erosion, ConstraintCellsAndBorderStayExact) {
  const Canvas start = synthesised(300, true, 5);
  Canvas c = start;
  const ErosionReport r = erode(c, auto_erosion());
  EXPECT_GT(r.steps, 0);
  std::size_t changed = 0;
  for (std::size_t i = 0; i < c.cells(); ++i) {
    ASSERT_TRUE(std::isfinite(c.z[i]));
    ASSERT_EQ(c.state[i], start.state[i]);
    if (is_constraint(c.state[i])) ASSERT_EQ(c.z[i], start.z[i]) << i;
    else changed += c.z[i] != start.z[i];
  }
  EXPECT_GT(changed, c.cells() / 2);
}

TEST(Erosion, RiversDrainAlongTheirCourseToTheBorderAndRidgesStayCrests) {
  for (const std::uint64_t seed : {1u, 4u}) {
    SkeletonParams sp;
    sp.seed = seed;
    const Skeleton k = make_skeleton(257, 257, sp);
    Canvas c = k.canvas;
    TerrainParams tp;
    tp.fill.rs = 0.1;
    tp.fill.seed = seed;
    synthesize(c, tp);
    erode(c, auto_erosion());
    const auto z = [&](int x, int y) { return c.z[c.index(x, y)]; };
    // From every river source (a river cell no river cell drains into), D8
    // runs on river cells only, to the border.
    std::vector<std::uint8_t> fed(c.cells(), 0);
    for (std::size_t i = 0; i < c.cells(); ++i)
      if (k.downstream[i] >= 0) fed[static_cast<std::size_t>(k.downstream[i])] = 1;
    int sources = 0;
    for (std::size_t i = 0; i < c.cells(); ++i) {
      if (c.state[i] != CellState::river || fed[i]) continue;
      ++sources;
      const Cell start{static_cast<int>(i % c.w), static_cast<int>(i / c.w)};
      const std::vector<Cell> path = d8_path(z, c.w, c.h, start);
      EXPECT_TRUE(on_border(path.back(), c.w, c.h)) << "seed " << seed << " source " << start.first << "," << start.second;
      for (const Cell& p : path) ASSERT_EQ(c.state[c.index(p.first, p.second)], CellState::river) << "seed " << seed;
    }
    EXPECT_GT(sources, 0);
    // Every ridge cell stands above the free land within two cells (but
    // beside a river, which may come down higher than the ridge there: the
    // river's draining wins).
    const auto near_river = [&](int x, int y) {
      for (int dy = -4; dy <= 4; ++dy)
        for (int dx = -4; dx <= 4; ++dx)
          if (c.contains(x + dx, y + dy) && c.state[c.index(x + dx, y + dy)] == CellState::river) return true;
      return false;
    };
    for (int y = 2; y < c.h - 2; ++y)
      for (int x = 2; x < c.w - 2; ++x) {
        if (c.state[c.index(x, y)] != CellState::ridge || near_river(x, y)) continue;
        for (int dy = -2; dy <= 2; ++dy)
          for (int dx = -2; dx <= 2; ++dx)
            if (c.state[c.index(x + dx, y + dy)] == CellState::unknown) {
              ASSERT_LT(z(x + dx, y + dy), z(x, y)) << x << "," << y;
            }
      }
  }
}

TEST(Erosion, GrowsADrainageNetworkAndKeepsTheMountainsHeight) {
  const Canvas start = synthesised(257, false, 7);
  Canvas c = start;
  const ErosionReport r = erode(c, auto_erosion());
  EXPECT_TRUE(r.converged);
  EXPECT_GE(r.grids, 1);
  // The largest basin draining through one cell (a trunk valley) grows.
  const std::vector<double> before = d8_area(start), after = d8_area(c);
  EXPECT_GT(*std::max_element(after.begin(), after.end()), 2.0 * *std::max_element(before.begin(), before.end()));
  // The mountains keep their height (the 99th percentile).
  const auto quantile = [](std::vector<double> v, double q) {
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(q * (v.size() - 1)), v.end());
    return v[static_cast<std::size_t>(q * (v.size() - 1))];
  };
  const double lo = *std::min_element(start.z.begin(), start.z.end());
  const double top0 = quantile(start.z, 0.99) - lo, top1 = quantile(c.z, 0.99) - lo;
  EXPECT_NEAR(top1, top0, 0.1 * top0);
}

TEST(Erosion, ZeroStepsChangeNothing) {
  const Canvas start = synthesised(65, false, 1);
  Canvas c = start;
  ErosionParams e = auto_erosion();
  e.steps = 0;
  erode(c, e);
  EXPECT_EQ(c.z, start.z);
}

TEST(Erosion, BadParametersGiveOneLine) {
  const auto refused = [](ErosionParams p, const std::string& word) {
    try {
      check_erosion(p, 10, 10);
    } catch (const std::invalid_argument& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
      EXPECT_NE(what.find(word), std::string::npos) << what;
      return;
    }
    ADD_FAILURE() << "accepted: " << word;
  };
  ErosionParams p;
  p.steps = -5;
  refused(p, "steps");
  p = {};
  p.K = -1;
  refused(p, "erodibility");
  p = {};
  p.m = 3;
  refused(p, "exponent m");
  p = {};
  p.n = 0.1;
  refused(p, "exponent n");
  p = {};
  p.diffusion = -1;
  refused(p, "diffusion");
  p = {};
  p.talus = 0;
  refused(p, "talus");
  p = {};
  p.talus = 95;
  refused(p, "talus");
  p = {};
  p.cell_size = 0;
  refused(p, "cell size");
  p = {};
  p.uplift = UpliftPattern::map;
  p.uplift_map.assign(99, 1.0);
  refused(p, "one rate per cell");
  p.uplift_map.assign(100, 1.0);
  p.uplift_map[3] = -1;
  refused(p, ">= 0");
  Canvas c(8, 8);
  c.z[5] = std::nan("");
  EXPECT_THROW(erode(c, auto_erosion()), std::invalid_argument);
}

}  // namespace
}  // namespace mcmd::test
