#include "terrain/methods/fbm.hpp"

#include <cmath>

#include "roughness/blocks.hpp"
#include "roughness/octaves.hpp"

namespace mcmd::terrain {

int fbm_octaves(int w, int h) {
  const int half = (w > h ? w : h) / 2;
  int n = 1;
  while ((1 << n) <= half && n < 30) ++n;
  return n;
}

std::vector<double> fbm_relief(int w, int h, std::uint64_t seed, double H, double amplitude, int octaves,
                               int scale_octaves, int threads) {
  using namespace rough;
  const RoughField field{w, h, 0, 0, nullptr, nullptr, nullptr, -1.0};
  Blocks blocks = block_lattice(field);
  for (int j = 0; j < blocks.ny; ++j)
    for (int i = 0; i < blocks.nx; ++i)
      blocks.noise_box[blocks.index(i, j)] = Rect{blocks.x0(i), blocks.x1(i, w), blocks.y0(j), blocks.y1(j, h)};
  const Area area{0, 0, w, h};
  const std::vector<std::uint8_t> everywhere(area.cells(), 1);
  std::vector<double> relief(area.cells(), 0.0);
  const Amplitude scale{amplitude * std::exp2(-(scale_octaves - 1) * H), nullptr, {}};
  add_noise(field, area, blocks, everywhere, seed, H, octaves, scale, relief, threads);
  return relief;
}

}  // namespace mcmd::terrain
