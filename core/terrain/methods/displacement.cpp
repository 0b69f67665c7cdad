#include "terrain/methods/displacement.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "common/box_mean.hpp"
#include "common/distance.hpp"
#include "terrain/methods/fbm.hpp"

namespace mcmd::terrain {

namespace {

// Cells from a line within which its crease is not blurred (soften()).
constexpr double kCreaseKept = 8.0;

// Octave groups faded near lines: [first, next first) and the distance
// over which each fades, about its spacings (so no fade is steeper than the
// octaves' own slopes). The last group runs to the coarsest octave.
struct OctaveGroup {
  int first;
  double fade;
};
constexpr OctaveGroup kGroups[] = {{0, 4.0}, {3, 12.0}, {5, 48.0}, {7, 128.0}};

double saturation_width(const Canvas& c) { return std::max(c.w, c.h) / 8.0; }

// Distance from every cell to the nearest cell whose state passes `pick`
// (empty when there is none).
template <class Pick>
std::vector<double> distance_to(const Canvas& c, Pick pick) {
  std::vector<std::uint8_t> mask(c.cells());
  bool any = false;
  for (std::size_t i = 0; i < mask.size(); ++i) any |= (mask[i] = pick(c.state[i]) ? 1 : 0) != 0;
  if (!any) return {};
  return distance_to_valid(mask.data(), c.w, c.h);
}

// s · R · (1 − exp(−d / R)): slope s at the line, s · R far away.
double saturating(double s, double d, double R) { return s * R * -std::expm1(-d / R); }

// The relief, each octave group times 1 − exp(−(distance to a line / fade)²):
// 0 with a zero cross-slope at every line cell, so that no octave tilts a
// crest or a valley floor, whatever the roughness.
void add_relief(std::vector<double>& d, const Canvas& c, const TerrainParams& p, double amplitude,
                const std::vector<double>& line_distance) {
  const int octaves = fbm_octaves(c.w, c.h);
  const auto relief = [&](int count) {
    return fbm_relief(c.w, c.h, p.fill.seed, p.fill.H, amplitude, count, octaves, p.threads);
  };
  if (line_distance.empty()) {
    const std::vector<double> all = relief(octaves);
    for (std::size_t i = 0; i < d.size(); ++i) d[i] += all[i];
    return;
  }
  std::vector<double> below(d.size(), 0.0);  // the octaves of the groups before
  for (std::size_t g = 0; g < std::size(kGroups) && kGroups[g].first < octaves; ++g) {
    const int end = g + 1 < std::size(kGroups) ? std::min(kGroups[g + 1].first, octaves) : octaves;
    std::vector<double> upto = relief(end);
    for (std::size_t i = 0; i < d.size(); ++i) {
      const double t = line_distance[i] / kGroups[g].fade;
      d[i] += -std::expm1(-t * t) * (upto[i] - below[i]);
    }
    below.swap(upto);
  }
}

// The creases away from the lines, blurred: a crease is a function of the
// distance to the nearest line, which kinks where two lines are equally near
// (the medial axis: long straight and curved folds in a hillshade). Within a
// few cells of a line the crease is kept as it is (its kink at the line is
// the crest or the valley floor), beyond it gives way to its blur.
void soften(std::vector<double>& crease, const Canvas& c, const std::vector<double>& to_line) {
  std::vector<double> blur = crease;
  const int r = std::max(1, static_cast<int>(std::max(c.w, c.h) / 40));
  for (int pass = 0; pass < 3; ++pass) {  // three box passes: close to a Gaussian of σ ≈ r
    box_mean(blur, c.w, c.h, r);
  }
  for (std::size_t i = 0; i < crease.size(); ++i) {
    const double t = -std::expm1(-to_line[i] / kCreaseKept);
    crease[i] = (1.0 - t) * crease[i] + t * blur[i];
  }
}

}  // namespace

double crease_slope(const Canvas& canvas, double relief_amplitude) {
  const double range = std::max(constraint_range(canvas), relief_amplitude);
  return range / (std::max(canvas.w, canvas.h) / 4.0);
}

std::vector<double> terrain_displacement(const Canvas& c, const TerrainParams& p, double unit) {
  std::vector<double> d(c.cells(), 0.0);
  const double amplitude = p.fill.rs * unit;
  const std::vector<double> to_ridge = distance_to(c, [](CellState s) { return s == CellState::ridge; });
  const std::vector<double> to_river = distance_to(c, [](CellState s) { return s == CellState::river; });
  std::vector<double> to_line;
  if (!to_ridge.empty() || !to_river.empty()) {
    to_line.assign(c.cells(), std::numeric_limits<double>::infinity());
    for (std::size_t i = 0; i < d.size(); ++i)
      to_line[i] = std::min(to_ridge.empty() ? to_line[i] : to_ridge[i], to_river.empty() ? to_line[i] : to_river[i]);
  }
  if (amplitude > 0) add_relief(d, c, p, amplitude, to_line);
  const double R = saturation_width(c);
  const double slope = p.sharpness * crease_slope(c, amplitude);
  if (slope > 0 && !to_line.empty()) {
    std::vector<double> crease(d.size(), 0.0);
    for (std::size_t i = 0; i < d.size(); ++i) {
      if (!to_ridge.empty()) crease[i] -= saturating(slope, to_ridge[i], R);
      if (!to_river.empty()) crease[i] += saturating(slope, to_river[i], R);
    }
    soften(crease, c, to_line);
    for (std::size_t i = 0; i < d.size(); ++i) d[i] += crease[i];
  }
  if (p.fill.rt != 0 && amplitude > 0 && c.constraints() > 0) {
    const std::vector<double> to_any = distance_to(c, [](CellState s) { return is_constraint(s); });
    const double lift = p.fill.rt * amplitude / R;  // rt · amplitude once saturated
    for (std::size_t i = 0; i < d.size(); ++i) d[i] += saturating(lift, to_any[i], R);
  }
  return d;
}

}  // namespace mcmd::terrain
