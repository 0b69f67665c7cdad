#include "terrain/erosion/texture.hpp"

#include <cmath>
#include <cstddef>

namespace mcmd::terrain {

namespace {

// The finest octave's RMS over the second finest's: 0.5 is the spectrum of
// a Hurst exponent of 1 carried down to the cell scale. At 1025² × 82 m,
// three seeds each, closed depressions per km² (real crops 0.12-0.53):
// 0.45: 0.16-0.40 from scratch, 0.09-0.14 on the skeleton (too few);
// 0.5: 0.23-0.50 and 0.13-0.18; 0.55: 0.47-0.63 (too many) and 0.17-0.23.
constexpr double kTextureRatio = 0.5;

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
  const auto free_fine = [&](std::size_t i) { return !g.fixed[i]; };
  // A coarse cell counts when the fine cell under it is free.
  const auto free_coarse = [&](std::size_t i) {
    const std::size_t X = i % cw, Y = i / cw;
    return !g.fixed[2 * Y * static_cast<std::size_t>(w) + 2 * X];
  };
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
