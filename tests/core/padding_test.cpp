#include <gtest/gtest.h>
#include <vector>

#include "common/padding.hpp"

using namespace mcmd;

TEST(Padding, ReflectsWithoutRepeatingTheEdge) {
  EXPECT_EQ(reflect_index(-1, 5), 1);
  EXPECT_EQ(reflect_index(5, 5), 3);
  EXPECT_EQ(reflect_index(8, 5), 0);
  EXPECT_EQ(reflect_index(9, 5), 1);
  EXPECT_EQ(reflect_index(3, 1), 0);
}

TEST(Padding, LevelsCoverTheLongerSide) {
  EXPECT_EQ(levels_to_cover(1, 1), 0);
  EXPECT_EQ(levels_to_cover(3, 1000), 10);
  EXPECT_EQ(levels_to_cover(1025, 7), 10);
  EXPECT_EQ(levels_to_cover(1026, 7), 11);
}

TEST(Padding, MirroredGridKeepsValuesAndStates) {
  const std::vector<double> z{1, 2, 3, 4, 5, 6};  // 3 wide, 2 high
  const std::vector<std::uint8_t> valid{1, 1, 0, 1, 1, 1};
  Grid g = mirror_padded_grid(z.data(), valid.data(), 3, 2, 2);  // 5×5
  EXPECT_EQ(g.z(1, 1), 5);
  EXPECT_EQ(g.state(2, 0), CellState::unknown);
  EXPECT_EQ(g.z(3, 0), 2);  // x = 3 reflects to 1
  EXPECT_EQ(g.z(0, 2), 1);  // y = 2 reflects to 0
  EXPECT_EQ(g.state(4, 0), CellState::known);
}

TEST(Padding, MirroredWindowStartsAtItsOrigin) {
  const std::vector<double> z{1, 2, 3, 4, 5, 6};  // 3 wide, 2 high
  const std::vector<std::uint8_t> valid{1, 1, 0, 1, 1, 1};
  Grid g = mirror_padded_grid(z.data(), valid.data(), 3, 2, 1, 2, 1);  // 3×3 from cell (2, 1)
  EXPECT_EQ(g.z(0, 0), 6);  // (2, 1)
  EXPECT_EQ(g.z(1, 0), 5);  // x = 3 reflects to 1
  EXPECT_EQ(g.state(0, 1), CellState::unknown);  // (2, 2) reflects to (2, 0): void
  EXPECT_EQ(g.z(2, 2), 4);  // (4, 3) reflects to (0, 1)
}
