#include <cmath>
#include <cstdint>
#include <vector>
#include <gtest/gtest.h>

#include "roughness/noise.hpp"

using namespace mcmd;

TEST(Noise, UniformIsAPureFunctionInRange) {
  double sum = 0;
  for (int y = 0; y < 100; ++y)
    for (int x = 0; x < 100; ++x) {
      const double u = hash_uniform(7, x, y);
      ASSERT_GE(u, -1.0);
      ASSERT_LE(u, 1.0);
      ASSERT_EQ(u, hash_uniform(7, x, y));
      sum += u;
    }
  EXPECT_NEAR(sum / 1e4, 0.0, 0.03);
  EXPECT_NE(hash_uniform(7, 3, 4), hash_uniform(8, 3, 4));
  EXPECT_NE(hash_uniform(7, 3, 4), hash_uniform(7, 4, 3));
}

TEST(Noise, NormalHasUnitVariance) {
  double s = 0, s2 = 0;
  const int count = 40000;
  for (int i = 0; i < count; ++i) {
    const double v = hash_normal(1, i, -i);
    s += v;
    s2 += v * v;
  }
  EXPECT_NEAR(s / count, 0.0, 0.03);
  EXPECT_NEAR(s2 / count, 1.0, 0.05);
}

TEST(Noise, PaperDeltaShrinksWithLevel) {
  EXPECT_DOUBLE_EQ(paper_delta(1, 2, 3, 0, 2, 0.5, 0.0, 1.0), hash_uniform(1, 2, 3));
  EXPECT_DOUBLE_EQ(paper_delta(1, 2, 3, 2, 2, 0.5, 0.0, 1.0), hash_uniform(1, 2, 3) / 4.0);
  EXPECT_DOUBLE_EQ(paper_delta(1, 2, 3, 0, 2, 0.5, 1.0, 0.5), (hash_uniform(1, 2, 3) + 1.0) * 0.5);
}

// The finest octave's 32-bit cell hash: uniform bits, and neither a cell's
// row neighbour nor its column neighbour tells anything about it (xored
// column and row keys must not leave stripes).
TEST(Noise, CellHash32IsUniformAndUncorrelatedWithNeighbours) {
  const CellHash32 hash(11);
  const int n = 200;
  std::vector<double> v(static_cast<std::size_t>(n) * n);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const std::uint32_t h = CellHash32::at(hash.column(x - 100), hash.row(y + 7));
      v[static_cast<std::size_t>(y) * n + x] = static_cast<std::int32_t>(h) * 0x1p-31;  // [-1, 1)
    }
  double s = 0, s2 = 0, right = 0, below = 0, diagonal = 0;
  for (int y = 0; y + 1 < n; ++y)
    for (int x = 0; x + 1 < n; ++x) {
      const double a = v[static_cast<std::size_t>(y) * n + x];
      s += a;
      s2 += a * a;
      right += a * v[static_cast<std::size_t>(y) * n + x + 1];
      below += a * v[static_cast<std::size_t>(y + 1) * n + x];
      diagonal += a * v[static_cast<std::size_t>(y + 1) * n + x + 1];
    }
  const double count = static_cast<double>(n - 1) * (n - 1), var = s2 / count;
  EXPECT_NEAR(s / count, 0.0, 0.01);
  EXPECT_NEAR(var, 1.0 / 3.0, 0.01);
  EXPECT_NEAR(right / count / var, 0.0, 0.02);
  EXPECT_NEAR(below / count / var, 0.0, 0.02);
  EXPECT_NEAR(diagonal / count / var, 0.0, 0.02);
  EXPECT_EQ(CellHash32::at(hash.column(3), hash.row(4)), CellHash32::at(CellHash32(11).column(3), hash.row(4)));
  EXPECT_NE(CellHash32::at(hash.column(3), hash.row(4)), CellHash32::at(CellHash32(12).column(3), CellHash32(12).row(4)));
}
