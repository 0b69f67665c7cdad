// synthesize(): every method keeps the constraints bit for bit, is the same
// for any thread count, refuses what it cannot do; the default method keeps
// sketched ridges as crests and rivers as valleys that drain.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "mcmd/terrain.hpp"
#include "sketch_fixture.hpp"

namespace mcmd::test {
namespace {

Canvas sketch_canvas(int n) {
  Canvas c(n, n);
  for (const SketchLine& l : sketch_lines(n))
    for (std::size_t k = 0; k < l.cells.size(); ++k)
      c.set(l.cells[k].first, l.cells[k].second, l.z[k], l.river ? CellState::river : CellState::ridge);
  c.set(3, n - 4, 500.0);  // and a plain known cell
  return c;
}

TerrainParams method(TerrainMethod m, TerrainScheme s = TerrainScheme::diamond_square) {
  TerrainParams p;
  p.method = m;
  p.scheme = s;
  p.fill.rs = 0.3;
  p.fill.H = 0.7;
  p.fill.seed = 5;
  p.fill.known_shape = {1.0, 6.0};
  return p;
}

struct Case {
  const char* name;
  TerrainParams params;
  int w, h;
};

std::vector<Case> cases() {
  return {{"mcmd", method(TerrainMethod::mcmd), 129, 97},
          {"paper_ds", method(TerrainMethod::paper, TerrainScheme::diamond_square), 129, 97},
          {"paper_te", method(TerrainMethod::paper, TerrainScheme::triangle_edge), 100, 129},
          {"butterfly", method(TerrainMethod::paper, TerrainScheme::butterfly), 129, 129},
          {"mdi", method(TerrainMethod::mdi, TerrainScheme::triangle_edge), 70, 129}};
}

Canvas scattered(int w, int h) {
  Canvas c(w, h);
  for (int y = 3; y < h; y += 17)
    for (int x = 5; x < w; x += 13) c.set(x, y, 100.0 + 3.0 * x - 2.0 * y + ((x * y) % 7), CellState::known);
  c.set(w / 2, h / 2, 400.0, CellState::ridge);
  c.set(w / 2 + 1, h / 2, 60.0, CellState::river);
  return c;
}

TEST(TerrainSynthesis, EveryMethodKeepsConstraintsAndIsFinite) {
  for (const Case& k : cases()) {
    const Canvas before = scattered(k.w, k.h);
    Canvas c = before;
    synthesize(c, k.params);
    for (std::size_t i = 0; i < c.cells(); ++i) {
      ASSERT_TRUE(std::isfinite(c.z[i])) << k.name;
      ASSERT_EQ(c.state[i], before.state[i]) << k.name;
      if (is_constraint(before.state[i])) {
        ASSERT_EQ(c.z[i], before.z[i]) << k.name << " cell " << i;
      }
    }
  }
}

TEST(TerrainSynthesis, SameBitsForAnyThreadCount) {
  for (Case k : cases()) {
    Canvas one = scattered(k.w, k.h), four = one;
    k.params.threads = 1;
    synthesize(one, k.params);
    k.params.threads = 4;
    synthesize(four, k.params);
    EXPECT_EQ(one.z, four.z) << k.name;
  }
}

TEST(TerrainSynthesis, TheSeedChangesTheRelief) {
  TerrainParams p = method(TerrainMethod::mcmd);
  Canvas a = scattered(65, 65), b = a;
  synthesize(a, p);
  p.fill.seed = 6;
  synthesize(b, p);
  EXPECT_NE(a.z, b.z);
}

TEST(TerrainSynthesis, FromScratchNeedsAnAbsoluteRoughness) {
  for (TerrainMethod m : {TerrainMethod::mcmd, TerrainMethod::paper}) {
    Canvas empty(65, 40);
    TerrainParams p = method(m);
    EXPECT_THROW(synthesize(empty, p), std::invalid_argument);  // a fraction of no range
    p.fill.rs = 0;
    EXPECT_THROW(synthesize(empty, p), std::invalid_argument);  // flat
    p.fill.rs = 1;
    p.fill.noise_unit = 300;
    synthesize(empty, p);
    double lo = 1e300, hi = -1e300;
    for (double z : empty.z) lo = std::min(lo, z), hi = std::max(hi, z);
    EXPECT_GT(hi - lo, 30.0) << method_name(m);  // the relief has the asked scale, not 0
    EXPECT_LT(hi - lo, 6000.0) << method_name(m);
  }
}

TEST(TerrainSynthesis, OneSeedWithAbsoluteRoughnessIsNotFlat) {
  Canvas c(101, 101);
  c.set(50, 50, 1000.0);
  TerrainParams p = method(TerrainMethod::mcmd);
  p.fill.rs = 1;
  p.fill.noise_unit = 300;
  synthesize(c, p);
  EXPECT_EQ(c.z[c.index(50, 50)], 1000.0);
  double lo = 1e300, hi = -1e300;
  for (double z : c.z) lo = std::min(lo, z), hi = std::max(hi, z);
  EXPECT_GT(hi - lo, 100.0);
}

TEST(TerrainSynthesis, MethodNoneWritesNothing) {
  Canvas c = scattered(40, 30);
  const Canvas before = c;
  TerrainParams p;
  p.method = TerrainMethod::none;
  synthesize(c, p);
  EXPECT_EQ(c.z, before.z);
}

TEST(TerrainSynthesis, RefusesBadSizesAndParameters) {
  EXPECT_THROW(Canvas(0, 10), std::invalid_argument);
  EXPECT_THROW(Canvas(100000, 100000), std::invalid_argument);
  EXPECT_THROW(check_terrain_size(-5, 10), std::invalid_argument);
  Canvas c = scattered(30, 30);
  TerrainParams p = method(TerrainMethod::mcmd);
  p.fill.H = NAN;
  EXPECT_THROW(synthesize(c, p), std::invalid_argument);
  p = method(TerrainMethod::mcmd);
  p.fill.rs_auto = true;
  EXPECT_THROW(synthesize(c, p), std::invalid_argument);
  p = method(TerrainMethod::mcmd);
  p.sharpness = -1;
  EXPECT_THROW(synthesize(c, p), std::invalid_argument);
}

// Butterfly is exact on planes (an affine stencil with linear precision).
TEST(TerrainSynthesis, ButterflyReproducesAPlane) {
  Canvas c(65, 65);
  const auto plane = [](int x, int y) { return 10.0 + 2.0 * x - 3.0 * y; };
  for (int y : {0, 64})
    for (int x : {0, 64}) c.set(x, y, plane(x, y));
  TerrainParams p = method(TerrainMethod::paper, TerrainScheme::butterfly);
  p.fill.rs = 0;
  p.fill.known_shape = {};
  synthesize(c, p);
  for (int y = 0; y < 65; ++y)
    for (int x = 0; x < 65; ++x) ASSERT_NEAR(c.z[c.index(x, y)], plane(x, y), 1e-9) << x << "," << y;
}

// Butterfly differs from triangle-edge (its stencil reaches beyond the edge)
// and is smoother: smaller second differences on the same constraints.
TEST(TerrainSynthesis, ButterflyIsSmootherThanTriangleEdge) {
  const auto roughness = [](const Canvas& c) {
    double s = 0;
    for (int y = 1; y + 1 < c.h; ++y)
      for (int x = 1; x + 1 < c.w; ++x) {
        const double lap = c.z[c.index(x - 1, y)] + c.z[c.index(x + 1, y)] + c.z[c.index(x, y - 1)] +
                           c.z[c.index(x, y + 1)] - 4 * c.z[c.index(x, y)];
        s += lap * lap;
      }
    return s;
  };
  TerrainParams te = method(TerrainMethod::paper, TerrainScheme::triangle_edge), bf = te;
  bf.scheme = TerrainScheme::butterfly;
  te.fill.rs = bf.fill.rs = 0;
  Canvas a = scattered(129, 129), b = a;
  synthesize(a, te);
  synthesize(b, bf);
  EXPECT_NE(a.z, b.z);
  EXPECT_LT(roughness(b), roughness(a));
}

TEST(TerrainSynthesis, MdiMeansWithoutNoiseKeepAConstant) {
  Canvas c(65, 65);
  for (int k = 3; k < 60; k += 7) c.set(k, 60 - k, 250.0);
  TerrainParams p = method(TerrainMethod::mdi, TerrainScheme::diamond_square);
  p.fill.rs = 0;
  synthesize(c, p);
  for (double z : c.z) ASSERT_DOUBLE_EQ(z, 250.0);
}

// The default method on the sketch: ridge cells are crests across the line,
// and the D8 path from the river's upper end runs down the river to the
// border, smooth or rough.
TEST(TerrainSynthesis, SketchedRidgesAreCrestsAndTheRiverDrains) {
  const int n = 257;
  const std::vector<SketchLine> lines = sketch_lines(n);
  const std::set<Cell> on_lines = all_cells(lines);
  for (double rs : {0.0, 0.1}) {
    Canvas c = sketch_canvas(n);
    TerrainParams p = method(TerrainMethod::mcmd);
    p.fill.rs = rs;
    synthesize(c, p);
    const auto z = [&](int x, int y) { return c.z[c.index(x, y)]; };
    for (int r = 0; r < 2; ++r) {
      const auto [maxima, profiles] = ridge_maxima(z, n, n, lines[r].cells, on_lines);
      EXPECT_GT(profiles, 100);
      EXPECT_GE(maxima, 0.9 * profiles) << "ridge " << r << " rs " << rs;
    }
    const std::vector<Cell>& river = lines[2].cells;
    const std::set<Cell> river_cells(river.begin(), river.end());
    const std::vector<Cell> path = d8_path(z, n, n, river.front());
    EXPECT_TRUE(on_border(path.back(), n, n)) << "rs " << rs;
    for (const Cell& cell : path) EXPECT_TRUE(river_cells.count(cell)) << cell.first << "," << cell.second;
  }
}

}  // namespace
}  // namespace mcmd::test
