#include "terrain/erosion/texture.hpp"

#include <cmath>
#include <cstddef>

namespace mcmd::terrain {

namespace {

// The finest octave's RMS over the second finest's, measured on the
// raster's own cells. Real DEMs hold 0.12-0.53 closed depressions (deeper
// than 1 m) per km²; at 1025² × 82 m, three seeds each, from scratch and
// around a skeleton: 0.35-0.55 and 0.11-0.15 at 0.4; 0.38-0.62 and
// 0.12-0.17 at 0.42; 0.42-0.72 and 0.14-0.19 at 0.45 (0.5 is the spectrum
// of a Hurst exponent of 1: 0.51-0.92 from scratch, too many).
constexpr double kTextureRatio = 0.4;

struct Octave {
  std::vector<double> coarse;  // the field on the next coarser grid
  double rms = 0.0;            // the RMS of the detail it cannot hold, over the free cells
};

// The octave of v (w×h) that its next coarser grid cannot hold; `detail`
// receives it when given. `free_cell(i)`: whether cell i counts in the RMS.
template <class Free>
Octave finest_octave(const std::vector<double>& v, int w, int h, Free free_cell, std::vector<double>* detail) {
  Octave o;
  o.coarse = restrict_field(v, w, h);
  std::vector<double> smooth = prolong(o.coarse, w / 2 + 1, h / 2 + 1, w, h);
  double sum = 0.0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    smooth[i] = v[i] - smooth[i];
    if (free_cell(i)) sum += smooth[i] * smooth[i], ++count;
  }
  o.rms = count ? std::sqrt(sum / static_cast<double>(count)) : 0.0;
  if (detail) *detail = std::move(smooth);
  return o;
}

}  // namespace

void restore_texture(std::vector<double>& z, const ErosionGrid& g) {
  const int w = g.w, h = g.h, cw = w / 2 + 1;
  if (w < 5 || h < 5) return;
  // The raster's own free cells count (not the margin, whose outlets
  // hold a lip); a coarse cell when the fine cell under it counts.
  const auto counts = [&](int x, int y) {
    const bool own = x >= g.margin && y >= g.margin && x < w - g.margin && y < h - g.margin;
    return own && !g.fixed[static_cast<std::size_t>(y) * w + x];
  };
  const auto free_fine = [&](std::size_t i) { return counts(static_cast<int>(i % w), static_cast<int>(i / w)); };
  const auto free_coarse = [&](std::size_t i) { return counts(2 * static_cast<int>(i % cw), 2 * static_cast<int>(i / cw)); };
  const Octave eroded = finest_octave(z, w, h, free_fine, nullptr);
  const Octave second = finest_octave(eroded.coarse, cw, h / 2 + 1, free_coarse, nullptr);
  std::vector<double> texture;
  const Octave initial = finest_octave(g.initial, w, h, free_fine, &texture);
  const double want = kTextureRatio * second.rms;
  if (!(want > eroded.rms) || !(initial.rms > 0.0)) return;
  // The texture is independent of the eroded detail: their powers add.
  const double scale = std::sqrt(want * want - eroded.rms * eroded.rms) / initial.rms;
  for (std::size_t i = 0; i < z.size(); ++i)
    if (!g.fixed[i]) z[i] += scale * texture[i];
}

}  // namespace mcmd::terrain
