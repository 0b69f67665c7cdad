// Counter-based noise: a value is a pure hash of (seed, global x, global y), so
// it never depends on traversal order, threads or tiling (internal and external
// consistency, seed 003).
#pragma once

#include <cstdint>

namespace mcmd {

namespace noise_detail {

// SplitMix64 finaliser: a strong 64-bit mixer, so neighbouring coordinates
// give unrelated values.
inline std::uint64_t mix(std::uint64_t v) {
  v += 0x9E3779B97F4A7C15ull;
  v = (v ^ (v >> 30)) * 0xBF58476D1CE4E5B9ull;
  v = (v ^ (v >> 27)) * 0x94D049BB133111EBull;
  return v ^ (v >> 31);
}

// The seed of one of a key's independent streams.
inline std::uint64_t stream_seed(std::uint64_t seed, std::uint64_t stream) {
  return mix(seed ^ (stream * 0xD6E8FEB86659FD93ull));
}

// Uniform in [0, 1) from the top 53 bits.
inline double unit(std::uint64_t h) { return static_cast<double>(h >> 11) * 0x1.0p-53; }

}  // namespace noise_detail

// hash_uniform of one seed, the seed's mixing done once: for loops over many
// cells (the noise octaves), inline. Other streams of the same seed give
// independent values (hash_normal's).
class UniformHash {
 public:
  explicit UniformHash(std::uint64_t seed, std::uint64_t stream = 1) : key_(noise_detail::stream_seed(seed, stream)) {}
  // 64 hashed bits of a cell.
  std::uint64_t bits(std::int64_t gx, std::int64_t gy) const {
    return noise_detail::mix(column(gx) ^ static_cast<std::uint64_t>(gy));
  }
  double operator()(std::int64_t gx, std::int64_t gy) const { return at(column(gx), gy); }
  // The same value in two steps, the first shared by a column of cells:
  // at(column(gx), gy) == (*this)(gx, gy) at half the mixing per cell.
  std::uint64_t column(std::int64_t gx) const { return noise_detail::mix(key_ ^ static_cast<std::uint64_t>(gx)); }
  static double at(std::uint64_t column, std::int64_t gy) {
    return 2.0 * noise_detail::unit(noise_detail::mix(column ^ static_cast<std::uint64_t>(gy))) - 1.0;
  }

 private:
  std::uint64_t key_;
};

// 32-bit hashes of cells, for loops over every cell of a box (the finest
// noise octave): a column key and a row key from the 64-bit mixer, xored,
// then mixed in 32 bits (the lowbias32 finaliser's constants, C. Wellons), so
// the per-cell step vectorises: AVX2 multiplies 32-bit lanes, not 64-bit ones.
class CellHash32 {
 public:
  explicit CellHash32(std::uint64_t seed)
      : columns_(noise_detail::stream_seed(seed, 4)), rows_(noise_detail::stream_seed(seed, 5)) {}
  std::uint32_t column(std::int64_t gx) const { return key(columns_, gx); }
  std::uint32_t row(std::int64_t gy) const { return key(rows_, gy); }
  static std::uint32_t at(std::uint32_t column, std::uint32_t row) {
    std::uint32_t v = column ^ row;
    v = (v ^ (v >> 16)) * 0x7FEB352Du;
    v = (v ^ (v >> 15)) * 0x846CA68Bu;
    return v ^ (v >> 16);
  }

 private:
  static std::uint32_t key(std::uint64_t stream, std::int64_t v) {
    return static_cast<std::uint32_t>(noise_detail::mix(stream ^ static_cast<std::uint64_t>(v)) >> 32);
  }
  std::uint64_t columns_, rows_;
};

// Uniform in [-1, 1], a pure function of its arguments.
double hash_uniform(std::uint64_t seed, std::int64_t gx, std::int64_t gy);

// Standard normal deviate, a pure function of its arguments.
double hash_normal(std::uint64_t seed, std::int64_t gx, std::int64_t gy);

// MCMD's displacement δ (paper eq. 1) for a cell at level r in dimension `dim`:
//   δ = (u + rt) · rs · 2^(−r · dim · H),  u = hash_uniform(seed, gx, gy).
double paper_delta(std::uint64_t seed, std::int64_t gx, std::int64_t gy, int level, int dim,
                   double H, double rt, double rs);

}  // namespace mcmd
