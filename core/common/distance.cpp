#include "common/distance.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace mcmd {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// 1D squared-distance transform of f (length n) into d: the lower envelope of
// the parabolas (q - p)^2 + f[p]. v/z are scratch buffers of n and n+1 entries.
void transform_1d(const double* f, double* d, int n, std::vector<int>& v, std::vector<double>& z) {
  int k = -1;
  for (int q = 0; q < n; ++q) {
    if (f[q] == kInf) continue;
    double s = 0.0;
    while (k >= 0) {
      const int p = v[k];
      s = ((f[q] + double(q) * q) - (f[p] + double(p) * p)) / (2.0 * (q - p));
      if (s > z[k]) break;
      --k;
    }
    ++k;
    v[k] = q;
    z[k] = k == 0 ? -kInf : s;
    z[k + 1] = kInf;
  }
  if (k < 0) {
    for (int q = 0; q < n; ++q) d[q] = kInf;
    return;
  }
  int j = 0;
  for (int q = 0; q < n; ++q) {
    while (z[j + 1] < q) ++j;
    const double dq = q - v[j];
    d[q] = dq * dq + f[v[j]];
  }
}

// Per cell, the distance to the nearest valid cell in its column (+infinity
// where none), by a downward and an upward scan over whole rows
// (cache-friendly; exact on a binary image).
std::vector<double> column_distance(const std::uint8_t* valid, int w, int h) {
  const std::size_t W = static_cast<std::size_t>(w);
  std::vector<double> d(W * static_cast<std::size_t>(h));
  for (int y = 0; y < h; ++y) {
    double* row = d.data() + y * W;
    const double* above = y > 0 ? row - W : nullptr;
    const std::uint8_t* ok = valid + y * W;
    for (std::size_t x = 0; x < W; ++x) row[x] = ok[x] ? 0.0 : (above ? above[x] + 1.0 : kInf);
  }
  for (int y = h - 2; y >= 0; --y) {
    double* row = d.data() + y * W;
    for (std::size_t x = 0; x < W; ++x) row[x] = std::min(row[x], row[x + W] + 1.0);
  }
  return d;
}

}  // namespace

std::vector<double> distance_to_valid(const std::uint8_t* valid, int w, int h) {
  const std::size_t W = static_cast<std::size_t>(w);
  // Columns first (the column pass's exact result), squared for the rows.
  std::vector<double> sq = column_distance(valid, w, h);
  for (double& s : sq) s *= s;
  const int longest = w > h ? w : h;
  std::vector<int> v(longest);
  std::vector<double> z(longest + 1), in(longest);
  for (int y = 0; y < h; ++y) {  // rows
    double* row = sq.data() + y * W;
    // A cell valid in its column (0) stays 0, and across a run of the others
    // the nearest cell lies within the run and the 0 on each side of it (any
    // farther one is farther than that 0): transform those stretches only, a
    // small part of a void's field.
    for (int x = 0; x < w;) {
      if (row[x] == 0.0) {
        ++x;
        continue;
      }
      int end = x;
      while (end < w && row[end] != 0.0) ++end;
      const int from = x > 0 ? x - 1 : 0, to = end < w ? end + 1 : w;
      for (int k = from; k < to; ++k) in[k - from] = row[k];
      transform_1d(in.data(), row + from, to - from, v, z);
      x = end;
    }
  }
  for (double& s : sq) s = std::sqrt(s);
  return sq;
}

namespace {

// In place over n items of `step` bytes each: item i becomes the OR of items
// i .. i + width - 1 (those past the end count as zero). The window doubles
// per pass, then one pass tops it up to `width`: byte ORs over contiguous
// memory, which vectorise.
void or_windows(std::uint8_t* items, std::size_t n, std::size_t step, std::size_t width) {
  const auto pass = [&](std::size_t k) {
    const std::size_t end = (n - std::min(n, k)) * step, ahead = k * step;
    // Each byte reads one k items ahead, not yet updated: safe in vectors.
#pragma omp simd
    for (std::size_t t = 0; t < end; ++t) items[t] |= items[t + ahead];
  };
  std::size_t k = 1;
  for (; 2 * k <= width; k *= 2) pass(k);
  if (width > k) pass(width - k);
}

}  // namespace

std::vector<std::uint8_t> within_chebyshev(const std::uint8_t* valid, int w, int h, int r) {
  // A (2r+1)² square is a column of 2r+1 then a row of 2r+1: each a sliding OR
  // over a copy padded with r zeros on both sides.
  const std::size_t W = static_cast<std::size_t>(w), H = static_cast<std::size_t>(h), R = static_cast<std::size_t>(r);
  const std::size_t width = 2 * R + 1;
  std::vector<std::uint8_t> rows((H + 2 * R) * W, 0);  // rows -r .. h+r-1
  for (std::size_t i = 0; i < W * H; ++i) rows[R * W + i] = valid[i] != 0;
  or_windows(rows.data(), H + 2 * R, W, width);  // padded row y: rows y-r .. y+r
  std::vector<std::uint8_t> out(W * H);
  std::vector<std::uint8_t> line(W + 2 * R, 0);
  for (std::size_t y = 0; y < H; ++y) {
    std::copy_n(rows.data() + y * W, W, line.data() + R);
    std::fill(line.begin() + static_cast<std::ptrdiff_t>(R + W), line.end(), std::uint8_t{0});
    std::fill_n(line.begin(), R, std::uint8_t{0});
    or_windows(line.data(), W + 2 * R, 1, width);
    std::copy_n(line.data(), W, out.data() + y * W);
  }
  return out;
}

bool all_within_chebyshev(const std::uint8_t* valid, int w, int h, int r) {
  const std::vector<std::uint8_t> near = within_chebyshev(valid, w, h, r);
  return std::all_of(near.begin(), near.end(), [](std::uint8_t v) { return v != 0; });
}

int near_margin(double reach) { return static_cast<int>(std::ceil(reach)) + 1; }

PartDistance distance_to_valid_near(const std::uint8_t* valid, int w, int h, int x0, int y0, int x1, int y1,
                                    double reach) {
  const int g = near_margin(reach);
  PartDistance p;
  p.x0 = std::max(0, x0 - g);
  p.y0 = std::max(0, y0 - g);
  p.w = std::min(w, x1 + g) - p.x0;
  p.h = std::min(h, y1 + g) - p.y0;
  std::vector<std::uint8_t> part(static_cast<std::size_t>(p.w) * p.h);
  for (int y = 0; y < p.h; ++y)
    std::copy_n(valid + static_cast<std::size_t>(p.y0 + y) * w + p.x0, p.w,
                part.begin() + static_cast<std::ptrdiff_t>(y) * p.w);
  p.d = distance_to_valid(part.data(), p.w, p.h);
  return p;
}

}  // namespace mcmd
