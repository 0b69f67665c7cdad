// Four-wide double vectors and the AVX2 clones of the noise's hot loops
// (internal to roughness/).
#pragma once

#include "common/simd_clones.hpp"  // MCMD_AVX2_CLONES

namespace mcmd::rough {

// Four doubles as one value (a GCC vector extension: one AVX2 register in
// add_octave's AVX2 clone, two SSE2 ones in its baseline x86-64 clone, lowered
// to scalars elsewhere). The noise's splines are evaluated at four cells at
// once by the very operations of the one-cell form (templates below, T =
// double or Quad; no fused multiply-add in either clone): the same bits
// either way, on any x86-64 machine.
using Quad = double __attribute__((vector_size(32)));
using QuadBits = long long __attribute__((vector_size(32)));
using QuadIndex = int __attribute__((vector_size(16)));  // node offsets: small


// std::floor for the node coordinates (|v| far below 2^51), without the call
// to libm that std::floor is on baseline x86-64: 2 per cell and octave.
[[gnu::always_inline]] inline double floor_of(double v) {
  const auto t = static_cast<double>(static_cast<long long>(v));  // towards zero
  return t > v ? t - 1.0 : t;
}
// The same floor in double arithmetic only (x86 converts four doubles to
// 64-bit integers one at a time before AVX-512): adding and taking away
// 2^52 rounds to the nearest integer, then 1 off where that is above v.
[[gnu::always_inline]] inline Quad floor_of(Quad v) {
  constexpr double k = 0x1p52;
  const Quad magic = v < 0.0 ? Quad{-k, -k, -k, -k} : Quad{k, k, k, k};
  const Quad t = (v + magic) - magic;
  const QuadBits one = (QuadBits)Quad{1.0, 1.0, 1.0, 1.0};
  return t - (Quad)((t > v) & one);
}

}  // namespace mcmd::rough
