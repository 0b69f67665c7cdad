#include <cmath>
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
