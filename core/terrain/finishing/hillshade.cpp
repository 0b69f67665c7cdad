#include <algorithm>
#include <cmath>
#include <numbers>

#include "mcmd/terrain_filters.hpp"

namespace mcmd {

std::vector<std::uint8_t> hillshade(const std::vector<double>& z, int w, int h, double dx, double dy) {
  constexpr double kAzimuth = 315.0 * std::numbers::pi / 180.0;
  constexpr double kAltitude = 45.0 * std::numbers::pi / 180.0;
  std::vector<std::uint8_t> out(static_cast<std::size_t>(w) * h);
  const auto at = [&](int x, int y) {
    return z[static_cast<std::size_t>(std::clamp(y, 0, h - 1)) * w + std::clamp(x, 0, w - 1)];
  };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      // Horn: 3×3 weighted differences; the border repeats its edge cells.
      const double gx = ((at(x + 1, y - 1) + 2 * at(x + 1, y) + at(x + 1, y + 1)) -
                         (at(x - 1, y - 1) + 2 * at(x - 1, y) + at(x - 1, y + 1))) / (8 * dx);
      const double gy = ((at(x - 1, y + 1) + 2 * at(x, y + 1) + at(x + 1, y + 1)) -
                         (at(x - 1, y - 1) + 2 * at(x, y - 1) + at(x + 1, y - 1))) / (8 * dy);
      // The unit normal (−gx, −gy, 1)/|·| against the unit vector to the
      // light: x east, y south, the azimuth clockwise from north.
      double shade = (-gx * std::cos(kAltitude) * std::sin(kAzimuth) + gy * std::cos(kAltitude) * std::cos(kAzimuth) +
                      std::sin(kAltitude)) / std::sqrt(1.0 + gx * gx + gy * gy);
      if (!std::isfinite(shade)) shade = 0;
      out[static_cast<std::size_t>(y) * w + x] = static_cast<std::uint8_t>(1 + std::lround(254 * std::clamp(shade, 0.0, 1.0)));
    }
  return out;
}

}  // namespace mcmd
