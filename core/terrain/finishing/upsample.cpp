#include <stdexcept>

#include "mcmd/terrain_filters.hpp"

namespace mcmd {

Canvas upsampled(const std::vector<double>& z, const std::vector<std::uint8_t>& valid, int w, int h, int k) {
  if (k < 1 || k > 1024) throw std::invalid_argument("the upsampling factor must be an integer in [1, 1024]");
  const long long fw = (static_cast<long long>(w) - 1) * k + 1, fh = (static_cast<long long>(h) - 1) * k + 1;
  check_terrain_size(fw, fh);
  Canvas c(static_cast<int>(fw), static_cast<int>(fh));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      if (valid[i]) c.set(x * k, y * k, z[i]);
    }
  return c;
}

}  // namespace mcmd
