#include "raster/tiles/tile_layout.hpp"

#include <algorithm>
#include <stdexcept>

namespace mcmd {

double blend_ramp(double u) {
  if (u <= 0.0) return 0.0;
  if (u >= 1.0) return 1.0;
  return u * u * u * (u * (6.0 * u - 15.0) + 10.0);
}

bool is_tile_side(int side) {
  if (side < 3) return false;
  const int p = side - 1;
  return (p & (p - 1)) == 0 && p <= (1 << 29);
}

TileAxis::TileAxis(int length, int step) : length_(length), step_(step) {
  if (length < 1) throw std::invalid_argument("raster size must be >= 1");
  if (step < 2 || (step & (step - 1)) != 0) throw std::invalid_argument("tile step must be a power of two >= 2");
  const long long cells = static_cast<long long>(length) - 1;
  count_ = cells <= 0 ? 1 : static_cast<int>((cells + step - 1) / step);
  band_ = std::clamp(step / 8, 1, kMaxBand);
}

namespace {
Range clip(long long b, long long e, int length) {
  return Range{static_cast<int>(std::clamp<long long>(b, 0, length)),
               static_cast<int>(std::clamp<long long>(e, 0, length))};
}
}  // namespace

Range TileAxis::region(int t) const {
  const long long b = t == 0 ? 0 : static_cast<long long>(t) * step_ - band_ + 1;
  const long long e = t == count_ - 1 ? length_ : static_cast<long long>(t + 1) * step_ + band_;
  return clip(b, e, length_);
}

Range TileAxis::solo(int t) const {
  const long long b = t == 0 ? 0 : static_cast<long long>(t) * step_ + band_;
  const long long e = t == count_ - 1 ? length_ : static_cast<long long>(t + 1) * step_ - band_ + 1;
  return clip(b, e, length_);
}

Range TileAxis::seam_band(int s) const {
  const long long c = static_cast<long long>(s) * step_;
  return clip(c - band_ + 1, c + band_, length_);
}

double TileAxis::weight(int t, int x) const {
  const double two_b = 2.0 * band_;
  const double left = t == 0 ? 1.0 : blend_ramp((x - (static_cast<double>(t) * step_ - band_)) / two_b);
  const double right =
      t == count_ - 1 ? 1.0 : 1.0 - blend_ramp((x - (static_cast<double>(t + 1) * step_ - band_)) / two_b);
  return left * right;
}

int TileAxis::owner(int x) const { return std::clamp(x / step_, 0, count_ - 1); }

TileLayout::TileLayout(int width, int height, int tile_side) {
  if (!is_tile_side(tile_side)) throw std::invalid_argument("tile side must be 2^k + 1 with k >= 1");
  x = TileAxis(width, tile_side - 1);
  y = TileAxis(height, tile_side - 1);
}

int TileLayout::window_levels() const {
  int n = 0;
  while ((1 << n) < 2 * x.step()) ++n;
  return n;
}

}  // namespace mcmd
