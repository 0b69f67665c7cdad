// The hierarchy's building blocks (lattice.hpp, pull_push.hpp) against their
// definitions written out cell by cell: their fast paths (no bounds test per
// tap, memchr, selects) must give the same values to the last bit, on odd and
// even sizes (ghost cells), mostly pinned and mostly free lattices.
#include <gtest/gtest.h>
#include <limits>
#include <random>
#include <vector>

#include "thin_plate/lattice.hpp"
#include "thin_plate/pull_push.hpp"

namespace {

constexpr double kJunk = std::numeric_limits<double>::infinity();  // a free cell's z: never read

mcmd::Lattice random_lattice(int w, int h, double pinned_fraction, unsigned seed) {
  mcmd::Lattice lat;
  lat.w = w;
  lat.h = h;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < w * h; ++i) {
    lat.pinned.push_back(u(rng) < pinned_fraction ? 1 : 0);
    lat.z.push_back(lat.pinned.back() ? 1000.0 * u(rng) - 500.0 : kJunk);  // 0 · inf would show
  }
  lat.spans = mcmd::free_spans(lat.pinned, w, h);
  return lat;
}

struct Sizes {
  int w, h;
};
const Sizes kSizes[] = {{2, 3}, {3, 3}, {4, 7}, {5, 5}, {17, 9}, {33, 34}, {40, 61}};
const double kPinned[] = {0.05, 0.5, 0.97};

// The pull's definition: coarse cell (i, j) is the weighted mean of the fine
// cells (2i+dx, 2j+dy) inside the fine level, taps (1, 1/2, 1/4), skipping
// taps of weight 0; its weight is the taps' weight over the kernel's inside.
void expect_restriction(int fw, int fh, const std::vector<double>& weight, const std::vector<double>& mean,
                        const mcmd::PullLevel& c) {
  const double k[3] = {0.5, 1.0, 0.5};
  ASSERT_EQ(c.w, fw / 2 + 1);
  ASSERT_EQ(c.h, fh / 2 + 1);
  for (int j = 0; j < c.h; ++j)
    for (int i = 0; i < c.w; ++i) {
      double sw = 0, sm = 0, sk = 0;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int x = 2 * i + dx, y = 2 * j + dy;
          if (x < 0 || y < 0 || x >= fw || y >= fh) continue;
          sk += k[dx + 1] * k[dy + 1];
          const double w = k[dx + 1] * k[dy + 1] * weight[static_cast<std::size_t>(y) * fw + x];
          if (w == 0.0) continue;
          sw += w;
          sm += w * mean[static_cast<std::size_t>(y) * fw + x];
        }
      const std::size_t ci = static_cast<std::size_t>(j) * c.w + i;
      EXPECT_EQ(c.weight[ci], sk > 0 ? sw / sk : 0.0) << i << "," << j;
      EXPECT_EQ(c.mean[ci], sw > 0 ? sm / sw : 0.0) << i << "," << j;
    }
}

TEST(Pull, EveryLevelIsItsDefinitionToTheLastBit) {
  unsigned seed = 1;
  for (const Sizes s : kSizes)
    for (const double p : kPinned) {
      const mcmd::Lattice lat = random_lattice(s.w, s.h, p, seed++);
      const std::vector<mcmd::PullLevel> levels = mcmd::pull(lat);
      ASSERT_FALSE(levels.empty());
      std::vector<double> weight(lat.pinned.begin(), lat.pinned.end()), mean(lat.z);
      int fw = lat.w, fh = lat.h;
      for (auto level = levels.rbegin(); level != levels.rend(); ++level) {  // finest first
        expect_restriction(fw, fh, weight, mean, *level);
        weight = level->weight;
        mean = level->mean;
        fw = level->w;
        fh = level->h;
      }
      EXPECT_EQ(levels.front().w, 2);
      EXPECT_EQ(levels.front().h, 2);
    }
}

TEST(Lattice, FreeSpansAreTheRunsOfUnpinnedCells) {
  unsigned seed = 100;
  for (const Sizes s : kSizes)
    for (const double p : kPinned) {
      const mcmd::Lattice lat = random_lattice(s.w, s.h, p, seed++);
      std::vector<mcmd::Span> expected;
      for (int y = 0; y < lat.h; ++y)
        for (int x = 0; x < lat.w; ++x) {
          if (lat.pinned[lat.index(x, y)]) continue;
          if (x > 0 && !lat.pinned[lat.index(x - 1, y)]) {
            expected.back().x1 = x + 1;
          } else {
            expected.push_back({y, x, x + 1});
          }
        }
      ASSERT_EQ(lat.spans.size(), expected.size());
      for (std::size_t k = 0; k < expected.size(); ++k) {
        EXPECT_EQ(lat.spans[k].y, expected[k].y);
        EXPECT_EQ(lat.spans[k].x0, expected[k].x0);
        EXPECT_EQ(lat.spans[k].x1, expected[k].x1);
      }
    }
}

TEST(Lattice, CoarserLatticeByPositionKeepsThePinnedFineCells) {
  unsigned seed = 200;
  for (const Sizes s : kSizes)
    for (const double p : kPinned) {
      mcmd::Lattice fine = random_lattice(s.w, s.h, p, seed++);
      if (fine.w < 3 && fine.h < 3) continue;
      fine.tension = 0.25;
      const mcmd::Lattice c = mcmd::coarser_lattice(fine, mcmd::CoarsePin::position);
      ASSERT_EQ(c.w, fine.w / 2 + 1);
      ASSERT_EQ(c.h, fine.h / 2 + 1);
      EXPECT_EQ(c.tension, 1.0);
      for (int j = 0; j < c.h; ++j)
        for (int i = 0; i < c.w; ++i) {
          const bool inside = 2 * i < fine.w && 2 * j < fine.h;  // else a ghost cell: free
          const bool pinned = inside && fine.pinned[fine.index(2 * i, 2 * j)];
          EXPECT_EQ(c.pinned[c.index(i, j)], pinned ? 1 : 0) << i << "," << j;
          EXPECT_EQ(c.z[c.index(i, j)], pinned ? fine.z[fine.index(2 * i, 2 * j)] : 0.0) << i << "," << j;
        }
      EXPECT_EQ(c.spans.size(), mcmd::free_spans(c.pinned, c.w, c.h).size());
    }
}

}  // namespace
