// Runs of zero bytes along a row of flags (free lattice cells, void cells):
// such rows are mostly non-zero, so memchr skips to each run a vector at a
// time instead of testing every byte. And the other way round, the few
// non-zero bytes of a mostly zero row (constraint cells among scattered
// samples), eight bytes at a time.
#pragma once

#include <bit>
#include <cstdint>
#include <cstring>
#include <utility>

#include "mcmd/cell_state.hpp"

namespace mcmd::detail {

// Calls f(x0, x1) for each maximal run [x0, x1) of zero bytes in row[0, w),
// left to right.
template <class F>
void for_each_zero_run(const std::uint8_t* row, int w, F&& f) {
  if (w <= 0) return;  // an empty row may be null: no memchr on it
  const std::uint8_t* const end = row + w;
  for (const std::uint8_t* p = row;
       (p = static_cast<const std::uint8_t*>(std::memchr(p, 0, static_cast<std::size_t>(end - p))));) {
    const std::uint8_t* q = p;
    while (q < end && !*q) ++q;
    f(static_cast<int>(p - row), static_cast<int>(q - row));
    p = q;
  }
}

// Calls f(x) for each non-zero byte row[x] of row[0, w), left to right:
// a word of eight zero bytes costs one test.
template <class F>
void for_each_nonzero(const std::uint8_t* row, int w, F&& f) {
  static_assert(std::endian::native == std::endian::little, "byte k of a word is bits 8k .. 8k + 7");
  int x = 0;
  for (; x + 8 <= w; x += 8) {
    std::uint64_t word;
    std::memcpy(&word, row + x, sizeof word);
    while (word) {
      const int k = std::countr_zero(word) / 8;
      f(x + k);
      word &= ~(std::uint64_t{0xff} << (8 * k));
    }
  }
  for (; x < w; ++x)
    if (row[x]) f(x);
}

// Calls f(x) for each constraint cell of a row of states, left to right:
// a constraint is a non-zero byte (unknown is 0).
template <class F>
void for_each_constraint(const CellState* row, int w, F&& f) {
  static_assert(static_cast<int>(CellState::unknown) == 0 && sizeof(CellState) == 1);
  for_each_nonzero(reinterpret_cast<const std::uint8_t*>(row), w, std::forward<F>(f));
}

}  // namespace mcmd::detail
