// make_skeleton(): ridge particles, their relief, river particles, then the
// skeleton DEM: ridge cells at their altitude, river cells carved by their
// mass and lowered so that each is lower than every cell upstream of it.
#include "mcmd/skeleton.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "terrain/skeleton/ridge_particles.hpp"
#include "terrain/skeleton/ridge_relief.hpp"
#include "terrain/skeleton/river_particles.hpp"

namespace mcmd {

namespace {

constexpr double kCarve = 0.02;  // of the relief's scale, times sqrt(mass): a river's depth

void check(int w, int h, const SkeletonParams& p) {
  check_terrain_size(w, h);
  if (!std::isfinite(p.z_low) || !std::isfinite(p.z_high) || p.z_high <= p.z_low)
    throw std::invalid_argument("the skeleton's elevation range must be finite, low below high");
  if (!(p.H >= 0 && p.H <= 1)) throw std::invalid_argument("the skeleton's H must be in [0, 1]");
  if (p.ridge_couples < 0 || p.ridge_couples > 10000 || p.river_particles < 0 || p.river_particles > 100000)
    throw std::invalid_argument("ridge couples must be in [0, 10000], river particles in [0, 100000]");
}

int automatic_couples(int w, int h) {
  return std::max(2, static_cast<int>(std::lround(std::sqrt(static_cast<double>(w) * h) / 80.0)));
}

// River elevations: the relief minus the carving, then, from the sources
// down (Kahn's order on the tree), below every cell upstream by at least
// kRiverDrop of the relief per cell: strictly descending, so that D8 water
// follows the river (a flat step would let it leave).
constexpr double kRiverDrop = 1e-5;

void river_elevations(Skeleton& s, const terrain::RiverNetwork& net, double top) {
  const std::size_t n = net.downstream.size();
  std::vector<int> upstream(n, 0);
  for (std::size_t c = 0; c < n; ++c)
    if (net.downstream[c] >= 0) ++upstream[net.downstream[c]];
  std::vector<double>& z = s.canvas.z;
  std::vector<std::size_t> ready;
  for (std::size_t c = 0; c < n; ++c) {
    if (net.downstream[c] == kNoRiver) continue;
    z[c] = s.canvas.z[c] - kCarve * top * std::sqrt(static_cast<double>(net.mass[c]));
    s.canvas.state[c] = CellState::river;
  }
  for (std::size_t c = 0; c < n; ++c)
    if (net.downstream[c] != kNoRiver && upstream[c] == 0) ready.push_back(c);
  while (!ready.empty()) {
    const std::size_t c = ready.back();
    ready.pop_back();
    const std::int64_t d = net.downstream[c];
    if (d < 0) continue;
    z[d] = std::min(z[d], z[c] - kRiverDrop * top);
    if (--upstream[d] == 0) ready.push_back(static_cast<std::size_t>(d));
  }
}

}  // namespace

Skeleton make_skeleton(int w, int h, const SkeletonParams& p, const ProgressFn& progress) {
  check(w, h, p);
  const double top = p.z_high - p.z_low;
  Skeleton s;
  s.canvas = Canvas(w, h);
  const int couples = p.ridge_couples > 0 ? p.ridge_couples : automatic_couples(w, h);
  const terrain::RidgeRoutes routes = terrain::run_ridge_particles(w, h, couples, p.H, top, p.seed);
  report(progress, 0.3);
  terrain::RidgeRelief relief(w, h, routes, top);
  report(progress, 0.5);
  const int particles = p.river_particles > 0 ? p.river_particles : 6 * couples;
  const terrain::RiverNetwork net = terrain::run_river_particles(w, h, routes, relief, top, particles, p.seed);
  s.relief = relief.cells();  // with the rivers' valleys
  for (double& v : s.relief) v += p.z_low;
  report(progress, 0.9);
  for (std::size_t c = 0; c < s.canvas.cells(); ++c) {
    // Both at the relief's elevation (the seed keeps the deformed map's
    // values): a river beside a crest is below it.
    if (routes.height[c] >= 0 || net.downstream[c] != kNoRiver)
      s.canvas.set(static_cast<int>(c % w), static_cast<int>(c / w), s.relief[c], CellState::ridge);
  }
  river_elevations(s, net, top);
  s.downstream = net.downstream;
  s.ridge_couples = routes.couples;
  s.rivers_kept = net.kept;
  s.rivers_dropped = net.dropped;
  report(progress, 1.0);
  return s;
}

}  // namespace mcmd
