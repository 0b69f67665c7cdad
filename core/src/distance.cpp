#include "mcmd/distance.hpp"

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

// Per cell, the distance to the nearest valid cell in its column, at most
// `cap` (cells with none get cap), by a downward and an upward scan over
// whole rows (cache-friendly; exact on a binary image).
template <class T>
std::vector<T> column_distance(const std::uint8_t* valid, int w, int h, T cap) {
  const std::size_t W = static_cast<std::size_t>(w);
  std::vector<T> d(W * static_cast<std::size_t>(h));
  for (int y = 0; y < h; ++y) {
    T* row = d.data() + y * W;
    const T* above = y > 0 ? row - W : nullptr;
    const std::uint8_t* ok = valid + y * W;
    for (std::size_t x = 0; x < W; ++x) row[x] = ok[x] ? T{0} : (above ? std::min(cap, above[x] + T{1}) : cap);
  }
  for (int y = h - 2; y >= 0; --y) {
    T* row = d.data() + y * W;
    for (std::size_t x = 0; x < W; ++x) row[x] = std::min(row[x], row[x + W] + T{1});
  }
  return d;
}

}  // namespace

std::vector<double> distance_to_valid(const std::uint8_t* valid, int w, int h) {
  const std::size_t W = static_cast<std::size_t>(w);
  // Columns first (the column pass's exact result), squared for the rows.
  std::vector<double> sq = column_distance(valid, w, h, kInf);
  for (double& s : sq) s *= s;
  const int longest = w > h ? w : h;
  std::vector<int> v(longest);
  std::vector<double> z(longest + 1), in(longest);
  for (int y = 0; y < h; ++y) {  // rows
    double* row = sq.data() + y * W;
    for (int x = 0; x < w; ++x) in[x] = row[x];
    transform_1d(in.data(), row, w, v, z);
  }
  for (double& s : sq) s = std::sqrt(s);
  return sq;
}

std::vector<std::uint8_t> within_chebyshev(const std::uint8_t* valid, int w, int h, int r) {
  const std::size_t W = static_cast<std::size_t>(w);
  const int cap = r + 1;  // "farther than r" is all that counts
  const std::vector<int> g = column_distance(valid, w, h, cap);  // vertical, capped
  // Along each row: the nearest column whose vertical distance is <= r.
  std::vector<std::uint8_t> out(W * static_cast<std::size_t>(h));
  std::vector<int> left(W);
  for (int y = 0; y < h; ++y) {
    const int* row = g.data() + y * W;
    std::uint8_t* o = out.data() + y * W;
    int last = -cap - 1;
    for (int x = 0; x < w; ++x) {
      if (row[x] <= r) last = x;
      left[x] = x - last;
    }
    int next = w + cap;
    for (int x = w - 1; x >= 0; --x) {
      if (row[x] <= r) next = x;
      o[x] = std::min(left[x], next - x) <= r;
    }
  }
  return out;
}

bool all_within_chebyshev(const std::uint8_t* valid, int w, int h, int r) {
  const std::vector<std::uint8_t> near = within_chebyshev(valid, w, h, r);
  return std::all_of(near.begin(), near.end(), [](std::uint8_t v) { return v != 0; });
}

}  // namespace mcmd
