// common/zero_runs.hpp against a byte-by-byte walk: rows of every length
// around the 8-byte word, sparse and dense, with bytes other than 0 and 1.
#include <cstdint>
#include <gtest/gtest.h>
#include <random>
#include <utility>
#include <vector>

#include "common/zero_runs.hpp"

namespace {

std::vector<std::uint8_t> random_row(std::mt19937& rng, int w, double density) {
  std::bernoulli_distribution set(density);
  std::uniform_int_distribution<int> value(1, 255);
  std::vector<std::uint8_t> row(static_cast<std::size_t>(w));
  for (auto& b : row) b = set(rng) ? static_cast<std::uint8_t>(value(rng)) : 0;
  return row;
}

TEST(ZeroRuns, ForEachNonzeroVisitsEveryNonzeroByteInOrder) {
  std::mt19937 rng(11);
  for (int w = 0; w <= 41; ++w)
    for (double density : {0.0, 0.03, 0.3, 1.0}) {
      const std::vector<std::uint8_t> row = random_row(rng, w, density);
      std::vector<int> expected, got;
      for (int x = 0; x < w; ++x)
        if (row[x]) expected.push_back(x);
      mcmd::detail::for_each_nonzero(row.data(), w, [&](int x) { got.push_back(x); });
      EXPECT_EQ(got, expected) << "w " << w << ", density " << density;
    }
}

TEST(ZeroRuns, ForEachZeroRunGivesTheMaximalRunsInOrder) {
  std::mt19937 rng(12);
  for (int w = 0; w <= 41; ++w)
    for (double density : {0.0, 0.5, 0.97, 1.0}) {
      const std::vector<std::uint8_t> row = random_row(rng, w, density);
      std::vector<std::pair<int, int>> expected, got;
      for (int x = 0; x < w;) {
        if (row[x]) { ++x; continue; }
        int end = x;
        while (end < w && !row[end]) ++end;
        expected.emplace_back(x, end);
        x = end;
      }
      mcmd::detail::for_each_zero_run(row.data(), w, [&](int a, int b) { got.emplace_back(a, b); });
      EXPECT_EQ(got, expected) << "w " << w << ", density " << density;
    }
}

}  // namespace
