// Runs of zero bytes along a row of flags (free lattice cells, void cells):
// such rows are mostly non-zero, so memchr skips to each run a vector at a
// time instead of testing every byte.
#pragma once

#include <cstdint>
#include <cstring>

namespace mcmd::detail {

// Calls f(x0, x1) for each maximal run [x0, x1) of zero bytes in row[0, w),
// left to right.
template <class F>
void for_each_zero_run(const std::uint8_t* row, int w, F&& f) {
  const std::uint8_t* const end = row + w;
  for (const std::uint8_t* p = row;
       (p = static_cast<const std::uint8_t*>(std::memchr(p, 0, static_cast<std::size_t>(end - p))));) {
    const std::uint8_t* q = p;
    while (q < end && !*q) ++q;
    f(static_cast<int>(p - row), static_cast<int>(q - row));
    p = q;
  }
}

}  // namespace mcmd::detail
