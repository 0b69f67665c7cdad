#include <gtest/gtest.h>

#include "common/grid.hpp"

namespace {

TEST(Grid, HasSideTwoToTheNPlusOneAndStartsUnknown) {
  mcmd::Grid g(3);
  EXPECT_EQ(g.side(), 9);
  EXPECT_EQ(g.cell_count(), 81u);
  EXPECT_EQ(g.count(mcmd::CellState::unknown), 81u);
}

TEST(Grid, RejectsAbsurdLevels) { EXPECT_THROW(mcmd::Grid(31), std::invalid_argument); }

}  // namespace
