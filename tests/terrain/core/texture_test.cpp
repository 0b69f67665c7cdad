// The eroded terrain's texture (terrain/erosion/texture.hpp): the finest
// octave put back to 0.4 of the second's RMS, fixed cells untouched, nothing
// added where the surface is already that rough; and the erosion keeps it
// unless told not to.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "mcmd/erosion.hpp"
#include "terrain/erosion/pyramid.hpp"
#include "terrain/erosion/texture.hpp"

namespace mcmd::test {
namespace {

using terrain::ErosionGrid;

// RMS of the octave of v (w×h) that the next coarser grid cannot hold, over
// the cells that `fixed` leaves free (all cells when empty).
double octave_rms(const std::vector<double>& v, int w, int h, const std::vector<std::uint8_t>& fixed = {}) {
  const std::vector<double> smooth = terrain::prolong(terrain::restrict_field(v, w, h), w / 2 + 1, h / 2 + 1, w, h);
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < v.size(); ++i)
    if (fixed.empty() || !fixed[i]) sum += (v[i] - smooth[i]) * (v[i] - smooth[i]), ++n;
  return std::sqrt(sum / static_cast<double>(n));
}

// The finest octave over the second finest, both as RMS.
double octave_ratio(const std::vector<double>& v, int w, int h) {
  return octave_rms(v, w, h) / octave_rms(terrain::restrict_field(v, w, h), w / 2 + 1, h / 2 + 1);
}

// Deterministic detail at every scale: a sum of waves down to two cells.
double waves(int x, int y, double fine) {
  return 20.0 * std::sin(0.05 * x) * std::cos(0.04 * y) + 4.0 * std::sin(0.31 * x + 0.7 * y) +
         fine * std::sin(2.2 * x + 0.3 * y) * std::cos(1.9 * y - 0.5 * x);
}

ErosionGrid grid(int n) {
  ErosionGrid g;
  g.w = g.h = n;
  g.initial.resize(static_cast<std::size_t>(n) * n);
  g.fixed.assign(g.initial.size(), 0);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      g.initial[static_cast<std::size_t>(y) * n + x] = waves(x, y, 3.0);
      if (terrain::on_border(x, y, n, n) || (x == 40 && y > 10 && y < 90)) g.fixed[static_cast<std::size_t>(y) * n + x] = 1;
    }
  return g;
}

TEST(Texture, PutsTheFinestOctaveBackTo40PercentOfTheSecond) {
  const int n = 129;
  const ErosionGrid g = grid(n);
  std::vector<double> z(g.initial.size());
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) z[static_cast<std::size_t>(y) * n + x] = waves(x, y, 0.0);  // creep took the grain
  const std::vector<double> before = z;
  ASSERT_LT(octave_ratio(z, n, n), 0.3);
  terrain::restore_texture(z, g);
  EXPECT_NEAR(octave_ratio(z, n, n), 0.4, 0.04);
  for (std::size_t i = 0; i < z.size(); ++i) {
    if (g.fixed[i]) {
      EXPECT_EQ(z[i], before[i]) << i;
    }
  }
}

TEST(Texture, LeavesARoughSurfaceAsItIs) {
  const int n = 65;
  const ErosionGrid g = grid(n);
  std::vector<double> z(g.initial.size());
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) z[static_cast<std::size_t>(y) * n + x] = waves(x, y, 30.0);
  const std::vector<double> before = z;
  terrain::restore_texture(z, g);
  EXPECT_EQ(z, before);
}

TEST(Texture, TheErodedTerrainKeepsItsGrain) {
  // Creep alone leaves the finest octave at a fraction of the second's.
  const int n = 257;
  Canvas c(n, n);
  TerrainParams tp;
  tp.fill.rs = 300.0;
  tp.fill.noise_unit = 1.0;
  tp.fill.seed = 3;
  synthesize(c, tp);
  ErosionParams e;
  e.steps = kErodeAuto;
  e.cell_size = 90.0;
  Canvas smooth = c;
  erode(c, e);
  EXPECT_NEAR(octave_ratio(c.z, n, n), 0.4, 0.04);
  e.texture = false;  // the paper methods' way: their finest octave is a lattice
  erode(smooth, e);
  EXPECT_LT(octave_ratio(smooth.z, n, n), 0.3);
}

}  // namespace
}  // namespace mcmd::test
