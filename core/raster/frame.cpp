#include "raster/frame.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <vector>

namespace mcmd::detail {

void check_range(double lo, double hi) {
  if (!std::isfinite(lo) || !std::isfinite(hi)) throw std::invalid_argument("known values must be finite numbers");
  if (std::max(std::abs(lo), std::abs(hi)) > kFrameFrom) throw ExtremeRange{lo, hi};
}

Frame frame_for(double lo, double hi) {
  Frame f;
  f.shift = lo / 2 + hi / 2;  // hi - lo may overflow
  const double half = std::max(std::abs(hi - f.shift), std::abs(lo - f.shift));
  int e = 0;
  std::frexp(half, &e);  // half < 2^e
  f.scale = half > 0 ? std::ldexp(1.0, e) : 1.0;
  return f;
}

RasterAccess framed(const RasterAccess& raster, const Frame& frame) {
  RasterAccess a;
  a.width = raster.width;
  a.height = raster.height;
  a.read = [raster, frame](int x0, int y0, int w, int h, double* z, std::uint8_t* valid) {
    raster.read(x0, y0, w, h, z, valid);
    const std::size_t n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
    for (std::size_t i = 0; i < n; ++i)
      if (valid[i]) z[i] = (z[i] - frame.shift) / frame.scale;
  };
  auto buffer = std::make_shared<std::vector<double>>();
  a.write = [raster, frame, buffer](int x0, int y0, int w, int h, const double* z, const std::uint8_t* mask) {
    const std::size_t n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
    buffer->assign(z, z + n);
    for (std::size_t i = 0; i < n; ++i)
      if (mask[i]) (*buffer)[i] = (*buffer)[i] * frame.scale + frame.shift;
    raster.write(x0, y0, w, h, buffer->data(), mask);
  };
  return a;
}

FillParams framed(const FillParams& params, const Frame& frame) {
  FillParams p = params;
  if (p.noise_unit > 0) p.noise_unit /= frame.scale;
  return p;
}

}  // namespace mcmd::detail
