// The ridges-and-rivers skeleton: every river drains to the border without
// climbing, ridges and rivers are there, the same seed gives the same bits.
#include <gtest/gtest.h>

#include <queue>
#include <stdexcept>

#include "mcmd/skeleton.hpp"

namespace mcmd::test {
namespace {

// River cells from which a path of river cells (8-connected), never going
// up, reaches a river cell on the border: a flood from the border upwards.
std::vector<std::uint8_t> draining(const Canvas& c) {
  std::vector<std::uint8_t> ok(c.cells(), 0);
  using Item = std::pair<double, std::size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
  for (int y = 0; y < c.h; ++y)
    for (int x = 0; x < c.w; ++x) {
      const std::size_t i = c.index(x, y);
      if (c.state[i] == CellState::river && (x == 0 || y == 0 || x == c.w - 1 || y == c.h - 1)) {
        ok[i] = 1;
        queue.push({c.z[i], i});
      }
    }
  while (!queue.empty()) {
    const std::size_t i = queue.top().second;
    queue.pop();
    const int x = static_cast<int>(i % c.w), y = static_cast<int>(i / c.w);
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        if (!c.contains(x + dx, y + dy)) continue;
        const std::size_t j = c.index(x + dx, y + dy);
        if (ok[j] || c.state[j] != CellState::river || c.z[j] < c.z[i]) continue;
        ok[j] = 1;
        queue.push({c.z[j], j});
      }
  }
  return ok;
}

struct Size {
  int w, h;
  std::uint64_t seed;
};

TEST(Skeleton, EveryRiverDrainsToTheBorderWithoutClimbing) {
  for (const Size s : {Size{257, 257, 0}, Size{513, 513, 1}, Size{300, 180, 2}, Size{129, 400, 3}, Size{513, 513, 4}}) {
    SkeletonParams p;
    p.seed = s.seed;
    const Skeleton k = make_skeleton(s.w, s.h, p);
    ASSERT_GT(k.rivers_kept, 0) << s.w << "x" << s.h;
    EXPECT_GT(k.canvas.count(CellState::ridge), 100u);
    EXPECT_GT(k.canvas.count(CellState::river), 50u);
    const std::vector<std::uint8_t> ok = draining(k.canvas);
    std::size_t rivers = 0;
    for (std::size_t i = 0; i < k.canvas.cells(); ++i) {
      const bool river = k.canvas.state[i] == CellState::river;
      ASSERT_EQ(river, k.downstream[i] != kNoRiver);
      if (!river) continue;
      ++rivers;
      EXPECT_TRUE(ok[i]) << "river cell " << i % s.w << "," << i / s.w << " does not drain";
      const std::int64_t d = k.downstream[i];
      if (d == kExits) {
        const int x = static_cast<int>(i % s.w), y = static_cast<int>(i / s.w);
        EXPECT_TRUE(x == 0 || y == 0 || x == s.w - 1 || y == s.h - 1);
        continue;
      }
      ASSERT_GE(d, 0);
      EXPECT_EQ(k.canvas.state[d], CellState::river);
      EXPECT_LE(k.canvas.z[d], k.canvas.z[i]) << "a river cell higher than the one upstream";
      const long long dx = static_cast<long long>(d % s.w) - static_cast<long long>(i % s.w);
      const long long dy = static_cast<long long>(d / s.w) - static_cast<long long>(i / s.w);
      EXPECT_TRUE(std::max(std::llabs(dx), std::llabs(dy)) == 1) << "the next river cell is not a neighbour";
    }
    EXPECT_GT(rivers, 0u);
  }
}

TEST(Skeleton, SameSeedSameBitsOtherSeedOtherSkeleton) {
  SkeletonParams p;
  p.seed = 9;
  const Skeleton a = make_skeleton(200, 150, p), b = make_skeleton(200, 150, p);
  EXPECT_EQ(a.canvas.z, b.canvas.z);
  EXPECT_EQ(a.canvas.state, b.canvas.state);
  p.seed = 10;
  const Skeleton c = make_skeleton(200, 150, p);
  EXPECT_NE(a.canvas.state, c.canvas.state);
}

TEST(Skeleton, ElevationsFollowTheRange) {
  SkeletonParams p;
  p.z_low = 200;
  p.z_high = 2200;
  const Skeleton k = make_skeleton(257, 257, p);
  double top = -1e300;
  for (std::size_t i = 0; i < k.canvas.cells(); ++i)
    if (k.canvas.state[i] == CellState::ridge) top = std::max(top, k.canvas.z[i]);
  EXPECT_GT(top, 200 + 0.7 * 2000);
  EXPECT_LT(top, 200 + 1.2 * 2000);
}

TEST(Skeleton, CountsAreHonoured) {
  SkeletonParams p;
  p.ridge_couples = 1;
  p.river_particles = 3;
  const Skeleton k = make_skeleton(257, 257, p);
  EXPECT_EQ(k.ridge_couples, 1);
  EXPECT_LE(k.rivers_kept + k.rivers_dropped, 3);
}

TEST(Skeleton, RefusesBadParameters) {
  SkeletonParams p;
  p.z_high = p.z_low;
  EXPECT_THROW(make_skeleton(100, 100, p), std::invalid_argument);
  p = SkeletonParams{};
  p.H = 2;
  EXPECT_THROW(make_skeleton(100, 100, p), std::invalid_argument);
  EXPECT_THROW(make_skeleton(0, 100, SkeletonParams{}), std::invalid_argument);
}

}  // namespace
}  // namespace mcmd::test
