#include <gtest/gtest.h>

#include "paper/subdivision.hpp"

using namespace mcmd;

TEST(Subdivision, LevelsFollowTheLowestSetBit) {
  const int n = 4;  // side 17
  EXPECT_EQ(level_of(0, 0, n), -1);
  EXPECT_EQ(level_of(16, 16, n), -1);
  EXPECT_EQ(level_of(8, 8, n), 0);
  EXPECT_EQ(level_of(8, 0, n), 0);
  EXPECT_EQ(level_of(4, 12, n), 1);
  EXPECT_EQ(level_of(3, 6, n), 3);
  EXPECT_EQ(half_spacing(3, n), 1);
}

TEST(Subdivision, DiamondSquareCentreHasItsFourCorners) {
  const Parents p = parents_of(Scheme::diamond_square, 4, 4, 3);
  ASSERT_EQ(p.count, 4);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(std::abs(p.cell[i].x - 4), 4);
    EXPECT_EQ(std::abs(p.cell[i].y - 4), 4);
  }
}

TEST(Subdivision, DiamondSquareEdgeHasThreeParentsAtTheBorder) {
  EXPECT_EQ(parents_of(Scheme::diamond_square, 4, 0, 3).count, 3);  // top border
  EXPECT_EQ(parents_of(Scheme::diamond_square, 4, 8, 4).count, 4);  // interior edge of a 17 grid
}

TEST(Subdivision, TriangleEdgeCentreUsesTheNorthWestSouthEastDiagonal) {
  const Parents p = parents_of(Scheme::triangle_edge, 2, 2, 2);
  ASSERT_EQ(p.count, 2);
  EXPECT_EQ(p.cell[0].x, 0);
  EXPECT_EQ(p.cell[0].y, 0);
  EXPECT_EQ(p.cell[1].x, 4);
  EXPECT_EQ(p.cell[1].y, 4);
  const Parents e = parents_of(Scheme::triangle_edge, 0, 2, 2);  // on the left edge
  ASSERT_EQ(e.count, 2);
  EXPECT_EQ(e.cell[0].y, 0);
  EXPECT_EQ(e.cell[1].y, 4);
}

TEST(Subdivision, ParentsAreCoarserOrSameLevelCentres) {
  const int n = 5, side = 33;
  for (Scheme s : {Scheme::diamond_square, Scheme::triangle_edge})
    for (int y = 0; y < side; ++y)
      for (int x = 0; x < side; ++x) {
        const int lv = level_of(x, y, n);
        const Parents p = parents_of(s, x, y, n);
        EXPECT_EQ(p.count == 0, lv == -1);
        for (int i = 0; i < p.count; ++i) {
          const int plv = level_of(p.cell[i].x, p.cell[i].y, n);
          const int h = half_spacing_of(p.cell[i].x, p.cell[i].y, n);
          const bool same_level_centre = plv == lv && is_square_centre(p.cell[i].x, p.cell[i].y, h);
          EXPECT_TRUE(plv < lv || same_level_centre) << x << "," << y;
        }
      }
}
