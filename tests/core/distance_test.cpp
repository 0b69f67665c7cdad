// distance_to_valid against brute force: exact Euclidean distances on random
// masks of odd shapes, and infinity where nothing is valid.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <gtest/gtest.h>
#include <limits>
#include <random>
#include <vector>

#include "common/distance.hpp"

namespace {

double brute_force(const std::vector<std::uint8_t>& valid, int w, int h, int x, int y) {
  double best = std::numeric_limits<double>::infinity();
  for (int v = 0; v < h; ++v)
    for (int u = 0; u < w; ++u)
      if (valid[static_cast<std::size_t>(v) * w + u]) best = std::min(best, std::hypot(u - x, v - y));
  return best;
}

TEST(Distance, MatchesBruteForceExactly) {
  std::mt19937 rng(7);
  const int sizes[][2] = {{1, 1}, {1, 40}, {40, 1}, {17, 23}, {64, 31}};
  for (const auto& s : sizes)
    for (double density : {0.0, 0.01, 0.05, 0.3}) {
      const int w = s[0], h = s[1];
      std::vector<std::uint8_t> valid(static_cast<std::size_t>(w) * h);
      std::bernoulli_distribution pick(density);
      for (auto& v : valid) v = pick(rng) ? 1 : 0;
      const std::vector<double> d = mcmd::distance_to_valid(valid.data(), w, h);
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
          ASSERT_EQ(d[static_cast<std::size_t>(y) * w + x], brute_force(valid, w, h, x, y))
              << w << "x" << h << " density " << density << " at " << x << "," << y;
    }
}

// Voids inside mostly valid rasters (a void's field), touching an edge or
// not, solid or with holes: exact, and 0 at the valid cells.
TEST(Distance, VoidsInsideValidRastersMatchBruteForce) {
  std::mt19937 rng(11);
  const int w = 57, h = 43;
  const int boxes[][4] = {{20, 15, 31, 24}, {0, 10, 8, 30}, {40, 0, 56, 5}, {25, 20, 25, 20}};
  for (const auto& b : boxes)
    for (double hole : {1.0, 0.7}) {
      std::vector<std::uint8_t> valid(static_cast<std::size_t>(w) * h, 1);
      std::bernoulli_distribution pick(hole);
      for (int y = b[1]; y <= b[3]; ++y)
        for (int x = b[0]; x <= b[2]; ++x)
          if (pick(rng)) valid[static_cast<std::size_t>(y) * w + x] = 0;
      const std::vector<double> d = mcmd::distance_to_valid(valid.data(), w, h);
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
          ASSERT_EQ(d[static_cast<std::size_t>(y) * w + x], brute_force(valid, w, h, x, y))
              << "void box " << b[0] << "," << b[1] << " at " << x << "," << y;
    }
}

// Over a rectangle's part: exact wherever the true distance is within reach,
// above reach elsewhere, for rectangles inside, at the edge of and spanning
// the raster (a part without the ring of reach + 1 cells fails: valid cells
// just outside the rectangle decide cells inside it).
TEST(Distance, PartIsExactWithinReach) {
  std::mt19937 rng(5);
  const int w = 61, h = 47;
  const int rects[][4] = {{20, 15, 31, 24}, {0, 0, 10, 8}, {50, 30, 61, 47}, {0, 0, 61, 47}, {30, 20, 31, 21}};
  for (double density : {0.002, 0.02, 0.2})
    for (double reach : {0.0, 1.5, 4.0, 7.3})
      for (const auto& r : rects) {
        std::vector<std::uint8_t> valid(static_cast<std::size_t>(w) * h);
        std::bernoulli_distribution pick(density);
        for (auto& v : valid) v = pick(rng) ? 1 : 0;
        const mcmd::PartDistance p = mcmd::distance_to_valid_near(valid.data(), w, h, r[0], r[1], r[2], r[3], reach);
        for (int y = r[1]; y < r[3]; ++y)
          for (int x = r[0]; x < r[2]; ++x) {
            const double truth = brute_force(valid, w, h, x, y);
            if (truth <= reach)
              ASSERT_EQ(p.at(x, y), truth) << "reach " << reach << " at " << x << "," << y;
            else
              ASSERT_GT(p.at(x, y), reach) << "reach " << reach << " at " << x << "," << y;
          }
      }
}

// The Chebyshev dilation and bound agree with brute force: a cell is within r
// when a valid cell lies within r along both axes; the bound is true exactly
// when every cell is.
TEST(Distance, ChebyshevBoundMatchesBruteForce) {
  std::mt19937 rng(11);
  const int sizes[][2] = {{1, 1}, {1, 30}, {30, 1}, {19, 13}, {40, 33}};
  for (const auto& s : sizes)
    for (double density : {0.0, 0.02, 0.1, 0.5})
      for (int r : {0, 1, 2, 3, 4, 7, 8}) {
        const int w = s[0], h = s[1];
        std::vector<std::uint8_t> valid(static_cast<std::size_t>(w) * h);
        std::bernoulli_distribution pick(density);
        for (auto& v : valid) v = pick(rng) ? 1 : 0;
        const std::vector<std::uint8_t> within = mcmd::within_chebyshev(valid.data(), w, h, r);
        ASSERT_EQ(within.size(), valid.size());
        bool all = true;
        for (int y = 0; y < h; ++y)
          for (int x = 0; x < w; ++x) {
            bool near = false;
            for (int v = std::max(0, y - r); v <= std::min(h - 1, y + r) && !near; ++v)
              for (int u = std::max(0, x - r); u <= std::min(w - 1, x + r); ++u)
                if (valid[static_cast<std::size_t>(v) * w + u]) {
                  near = true;
                  break;
                }
            all = all && near;
            ASSERT_EQ(within[static_cast<std::size_t>(y) * w + x] != 0, near)
                << w << "x" << h << " density " << density << " r " << r << " cell " << x << "," << y;
          }
        EXPECT_EQ(mcmd::all_within_chebyshev(valid.data(), w, h, r), all)
            << w << "x" << h << " density " << density << " r " << r;
      }
}

}  // namespace
