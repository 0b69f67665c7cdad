#include "terrain/methods/mdi.hpp"

#include <cmath>
#include <unordered_map>

#include "roughness/noise.hpp"

namespace mcmd::terrain {

namespace {

// Sums of an ascendant's known children: elevations, distances, count.
struct ChildSums {
  double e = 0.0, d = 0.0;
  int n = 0;
};

// The noise stream of MDI, apart from MD's (which keys paper_delta on the seed).
constexpr std::uint64_t kMdiStream = 0x4D4449;

}  // namespace

std::size_t mdi(Grid& grid, std::vector<std::uint8_t>& fixed, Scheme scheme, const FillParams& params,
                double unit, const ProgressFn& progress) {
  const int n = grid.levels(), side = grid.side();
  const double top = n > 0 ? static_cast<double>(half_spacing(0, n)) : 1.0;
  const UniformHash urand(params.seed ^ kMdiStream);
  std::vector<std::uint32_t> wave, next;
  for (std::uint32_t i = 0; i < fixed.size(); ++i)
    if (fixed[i]) wave.push_back(i);
  std::unordered_map<std::uint32_t, ChildSums> sums;
  std::size_t set = 0;
  for (int w = 1; !wave.empty(); ++w) {
    for (std::uint32_t child : wave) {
      const int cx = static_cast<int>(child % side), cy = static_cast<int>(child / side);
      const Parents p = parents_of(scheme, cx, cy, n);
      for (int k = 0; k < p.count; ++k) {
        const std::uint32_t parent = static_cast<std::uint32_t>(p.cell[k].y) * side + p.cell[k].x;
        if (fixed[parent]) continue;
        auto [it, fresh] = sums.try_emplace(parent);
        if (fresh) next.push_back(parent);  // insertion order: reproducible
        it->second.e += grid.elevations()[child];
        it->second.d += std::hypot(p.cell[k].x - cx, p.cell[k].y - cy);
        ++it->second.n;
      }
    }
    for (std::uint32_t parent : next) {
      const ChildSums& s = sums[parent];
      double value = s.e / s.n;
      if (params.rs > 0) value += s.d / s.n / top * urand(parent % side, parent / side) * params.rs * unit;
      grid.elevations()[parent] = value;
      fixed[parent] = 1;
    }
    set += next.size();
    wave.swap(next);
    next.clear();
    sums.clear();
    report(progress, static_cast<double>(w) / (2 * n + 1 > w ? 2 * n + 1 : w + 1));
  }
  return set;
}

}  // namespace mcmd::terrain
